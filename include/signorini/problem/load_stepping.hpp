#pragma once
// A loading history (problem-format.md, [loading]): the model's loads and prescribed
// displacements scaled by each load factor in turn, solved by one ContactSolver (set up once),
// each step warm-started from the last. With friction the answer depends on the path, so each
// step measures its slip from the previous step's displacement (ContactSolver::set_slip_origin)
// and the slip accumulates over the steps.

#include <functional>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

/// Called after each step with its number (from 1) and its result (load_factor set; with
/// friction `slip` accumulated over the steps so far; summary.load_steps the history so far).
using LoadStepSink = std::function<void(int step, const ContactResult& result)>;

/// Solves `model`'s problem at each of `factors` (non-empty, each finite and >= 0): loads and
/// prescribed displacements times the factor, the gaps as they are. Stops at the first step
/// that does not converge. Returns the last step's result. `options`: as for solve_contact
/// (model.solver, with its observer).
[[nodiscard]] ContactResult solve_load_steps(const Model& model,
                                             const ContactSolverOptions& options,
                                             const std::vector<double>& factors,
                                             const LoadStepSink& each_step = {});

/// What `signorini solve` solves: the model's loading history where it has one (`factors` not
/// empty, each step given to `each_step`), otherwise one solve of model.problem; the result's
/// summary says why the path was chosen (Model::solver_reason).
[[nodiscard]] ContactResult solve_model(const Model& model, const ContactSolverOptions& options,
                                        const std::vector<double>& factors,
                                        const LoadStepSink& each_step = {});

}  // namespace signorini

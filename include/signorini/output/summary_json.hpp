#pragma once
// summary.json: what a run found, for scripts and plots (the paper's Table 1 columns, the KKT
// residuals, timings and the settings that matter to reproduce it).

#include <nlohmann/json.hpp>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/problem_spec.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini {

/// Keys: converged, termination, message, method, M (the modified Lagrangian at the result),
/// energy (J), uzawa_iterations, per-outer-step arrays gnm_iterations, armijo_reductions,
/// active_set_sizes, dual_changes, linear_iterations, factorizations; n_dofs, n_free_dofs,
/// n_contact_nodes, n_active, contact_force, contact_force_vector, kkt {equilibrium,
/// penetration, sign, complementarity}, timings {phase: seconds, ..., total}, problem {...},
/// signorini_version. Non-finite numbers come out as null (JSON has no NaN).
/// Also: r (the augmentation parameter used), r_automatic, kkt_tolerance, resultants {reference,
/// applied, applied_moment, reactions [{boundary, force, moment}], contact, contact_moment,
/// balance, moment_balance, relative_balance, relative_moment_balance}, point_loads [{requested,
/// node, at, distance, force}] (docs/output.md).
nlohmann::json summary_to_json(const ContactResult& result, const Model& model,
                               const ProblemSpec& spec, const Resultants& resultants);
/// As above, with the resultants computed here (compute_resultants).
nlohmann::json summary_to_json(const ContactResult& result, const Model& model,
                               const ProblemSpec& spec);

/// The phases of a run: the model's (mesh, assembly, ...) then the solver's. The solver's
/// "linear ..." phases are part of its "contact solve".
TimingTable run_timings(const Model& model, const SolveSummary& summary);

/// Wall-clock seconds of a run: the model's phases plus "contact solve" (not the sum of every
/// phase, which would count the nested linear-solver phases twice).
double run_total_seconds(const Model& model, const SolveSummary& summary);

}  // namespace signorini

#pragma once
// The contact methods themselves (private to the library): solve_contact() picks one and
// completes its summary with KKT residuals, energies and timings.

#include <functional>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/distributed_engine.hpp"

namespace signorini {

/// ||l_new - l_old||_2 / ||l_new||_2, the paper's Uzawa stopping quantity; 0 if both are zero and
/// +infinity if only l_new is.
double relative_change(const Vector& l_new, const Vector& l_old);

/// Where a method starts: multipliers l^0 and displacement x^0 (free dofs of the problem it is
/// given). Empty vectors mean zero, the paper's start (method.md "Conventions"); ContactSolver
/// fills them for a warm start from an earlier solution.
struct MethodStart {
  Vector l;
  Vector x;
  [[nodiscard]] Vector multipliers(Index n) const { return l.size() == n ? l : Vector::Zero(n); }
  [[nodiscard]] Vector displacement(Index n) const { return x.size() == n ? x : Vector::Zero(n); }
  /// The rows of x (all n unknowns, or a rank's part of a solution) that this process holds
  /// (ContactProblem::held_rows), zero without x: on the distributed path no vector of all n
  /// unknowns is made for the start.
  [[nodiscard]] Vector held_displacement(const ContactProblem& problem) const {
    return x.size() == problem.A.rows() || x.size() == solution_size(problem)
               ? problem.held_rows(x)
               : Vector::Zero(problem.end_row() - problem.first_row());
  }
};

// The methods themselves; ContactSolver calls one through its table (method_table.hpp) and
// completes its summary. Each takes the multigrid levels of the backend path's preconditioner,
// which only the backend's methods use, so that all have the table's one shape.
ContactResult solve_uzawa_gnm(const ContactProblem& problem, const ContactSolverOptions& options,
                              const MethodStart& start = {},
                              const MultigridHierarchy* multigrid = nullptr);
ContactResult solve_classical_uzawa(const ContactProblem& problem,
                                    const ContactSolverOptions& options,
                                    const MethodStart& start = {},
                                    const MultigridHierarchy* multigrid = nullptr);
/// A method's loop on the registered distributed engine's Newton space (made from start's rows):
/// `method` runs it and fills out's summary; then u is the rank's solution and the summary says
/// where the solve ran.
ContactResult run_on_distributed_space(
    const ContactProblem& problem, const ContactSolverOptions& options, const MethodStart& start,
    const std::function<void(DistributedNewtonSpace&, ContactResult&)>& method);
/// Classical Uzawa on the registered distributed engine: step (i) by the engine's Newton space
/// with no node active (its matrix A, its KSP), step (ii) on every rank alike; u as Uzawa-GNM's.
ContactResult solve_classical_uzawa_distributed(const ContactProblem& problem,
                                                const ContactSolverOptions& options,
                                                const MethodStart& start,
                                                const MultigridHierarchy* multigrid = nullptr);
/// Uzawa-GNM on the registered distributed engine (contact/distributed_engine.hpp): the same
/// loop, its vectors and Newton systems PETSc's, spread over the MPI ranks; u gathered on every
/// rank, or on the ranks' parts of the mesh each rank's part (ContactProblem::solution_unknowns).
ContactResult solve_uzawa_gnm_distributed(const ContactProblem& problem,
                                          const ContactSolverOptions& options,
                                          const MethodStart& start,
                                          const MultigridHierarchy* multigrid = nullptr);
/// uzawa_gnm with conjugate gradients on a backend (CPU or GPU, docs/gpu.md), used when
/// uses_backend_path(options). `multigrid`: the levels when the preconditioner is multigrid
/// (null otherwise).
ContactResult solve_uzawa_gnm_on_backend(const ContactProblem& problem,
                                         const ContactSolverOptions& options,
                                         const MethodStart& start = {},
                                         const MultigridHierarchy* multigrid = nullptr);
/// Semismooth Newton on a frictional problem (contact.components > 1): friction_ssn.hpp on the
/// whole KKT system, from start (u, l with d values per node) or the frictionless solution.
ContactResult solve_friction_semismooth_newton(const ContactProblem& problem,
                                               const ContactSolverOptions& options,
                                               const MethodStart& start = {});
/// Starts from the active set {l_j > 0} of start.l (empty: no node active).
ContactResult solve_semismooth_newton(const ContactProblem& problem,
                                      const ContactSolverOptions& options,
                                      const MethodStart& start = {},
                                      const MultigridHierarchy* multigrid = nullptr);
/// Semismooth Newton on the registered distributed engine: the same loop, its Newton steps
/// solved by PETSc with the active normal displacements eliminated; u as Uzawa-GNM's.
ContactResult solve_semismooth_newton_distributed(const ContactProblem& problem,
                                                  const ContactSolverOptions& options,
                                                  const MethodStart& start,
                                                  const MultigridHierarchy* multigrid = nullptr);
/// semismooth_newton on a backend (projected CG, projected_active_set_solver.hpp), used when
/// uses_backend_path(options).
ContactResult solve_semismooth_newton_on_backend(const ContactProblem& problem,
                                                 const ContactSolverOptions& options,
                                                 const MethodStart& start = {},
                                                 const MultigridHierarchy* multigrid = nullptr);

}  // namespace signorini

#pragma once
// Entry point of the contact solvers. ContactSolver is set up once for a problem (options
// validated, r resolved, the path chosen, the condensation factorised) and then solves, again
// for new loads or gaps, from a warm start if asked; solve_contact() is the one-shot form. Every
// solve completes the summary with KKT residuals, energies, contact force and timings.

#include <memory>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/solve_summary.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

struct ContactResult {
  /// Displacement, free dofs: all n, or on a rank's part of a distributed run's mesh the
  /// values of ContactProblem::solution_unknowns (Model::full_displacement expands either).
  Vector u;
  Vector l;  ///< contact pressure l_j >= 0 per contact node (l* = -sigma_nu)
  /// Friction only (empty otherwise): (d - 1) x contact nodes, the tangential traction per node
  /// in its tangent basis (interface/contact_tangents.hpp), the force per area that the obstacle
  /// exerts on the body, opposed to its slip where it slides.
  Matrix tangential;
  /// Friction only: per node the length of the slip, |(T u)_j - slip origin|, the path length
  /// over the steps of a loading history (problem/load_stepping.hpp).
  Vector slip;
  /// The load factor of the loads and prescribed displacements this solution is for (a step of
  /// a loading history; 1 otherwise): the writers expand u with the prescribed values times it.
  double load_factor = 1.0;
  /// The step of a loading history it is (from 1; 0: none), which picks the factors of the
  /// loads that have their own (problem/model.hpp, Model::load_groups).
  int load_step = 0;
  SolveSummary summary;
};

/// A contact solver set up once for one problem (A, N and the contact boundary fixed) and solved
/// as often as needed, as in quasi-static load stepping or a fixed point on the contact data:
///
///   ContactSolver solver(model.problem, options);   // validation, r, condensation (the costly
///   ContactResult first = solver.solve();           //  sparse factorisation) done once
///   solver.set_loads(b2);                           // same A: one forward substitution
///   solver.warm_start(first);                       // start from (u, l) of `first`
///   ContactResult second = solver.solve();
///
/// The problem must outlive the solver; it is not changed (new loads and gaps are kept in the
/// solver, in a copy of the problem made at the first change). Never fails silently: a run that
/// stops short of convergence returns with summary.termination saying why and summary.message
/// giving the residuals.
class ContactSolver {
 public:
  /// `multigrid`: the levels of the multigrid preconditioner (solver.linear.preconditioner =
  /// "multigrid"; build_model makes them from the mesh, Model::multigrid), which must outlive the
  /// solver too; without them the "multigrid" is Chebyshev smoothing on the finest level alone.
  /// Throws InputError for invalid options, NumericalError if a factorisation fails.
  ContactSolver(const ContactProblem& problem, const ContactSolverOptions& options,
                const MultigridHierarchy* multigrid = nullptr);
  ~ContactSolver();
  ContactSolver(ContactSolver&&) noexcept;
  ContactSolver& operator=(ContactSolver&&) noexcept;

  /// Solves for the current loads and gaps, from the warm start if one was set (and kept for
  /// later solves), otherwise from the paper's start u = 0, l = 0.
  ContactResult solve();
  /// New loads b (free dofs, the size of the problem's b).
  void set_loads(const Vector& b);
  /// New gaps g_j of the contact nodes (the size of the problem's gaps).
  void set_gaps(const Vector& gaps);
  /// Start the next solves from (u, l) of an earlier result for this problem.
  void warm_start(const ContactResult& previous);
  /// Back to the paper's start u = 0, l = 0.
  void cold_start();
  /// Friction: slip is measured from the displacement u from now on (the previous load step's
  /// solution, so that each step's slip is its increment); no effect without friction.
  void set_slip_origin(const Vector& u);

  /// How this solver solves (from the options; recorded in every summary).
  [[nodiscard]] SolvePath path() const;
  /// Time of the set-up (condensation phases), also merged into the first solve's timings.
  [[nodiscard]] const TimingTable& setup_timings() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// One solve: ContactSolver(problem, options, multigrid).solve().
ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& options,
                            const MultigridHierarchy* multigrid = nullptr);

}  // namespace signorini

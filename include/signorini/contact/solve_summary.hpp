#pragma once
// What a contact solve reports (as Ceres' Solver::Summary): why it stopped, per-step records,
// the KKT residuals of the result, energies, and where the time went.

#include <string>
#include <vector>

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

enum class Termination {
  Converged,
  IterationLimit,
  ActiveSetCycling,
  LineSearchFailure,
  LinearSolverFailure,
  /// The method's own rule was met, but the KKT residuals of the result are not below
  /// ContactSolverOptions::kkt_tolerance (method.md section 7): not an answer to trust.
  KktResidualsTooLarge,
  /// ContactSolverOptions::callback asked to stop.
  StoppedByCallback,
  /// ContactSolverOptions::time_limit was reached: the current iterate, not an answer.
  TimeLimit,
};

inline constexpr EnumNames<Termination, 8> kTerminationNames{{
    {Termination::Converged, "converged"},
    {Termination::IterationLimit, "iteration_limit"},
    {Termination::ActiveSetCycling, "active_set_cycling"},
    {Termination::LineSearchFailure, "line_search_failure"},
    {Termination::LinearSolverFailure, "linear_solver_failure"},
    {Termination::KktResidualsTooLarge, "kkt_residuals_too_large"},
    {Termination::StoppedByCallback, "stopped_by_callback"},
    {Termination::TimeLimit, "time_limit"},
}};

/// One outer step: a Uzawa step k (uzawa_gnm, classical_uzawa) or one Newton iteration
/// (semismooth_newton).
struct OuterStepRecord {
  int inner_iterations = 0;   ///< GNM iterations (uzawa_gnm); 1 otherwise
  Index active_set_size = 0;  ///< at the end of the step
  int armijo_reductions = 0;  ///< Armijo halvings in this step
  int linear_iterations = 0;  ///< CG iterations in this step (0 with a direct solver)
  int factorizations = 0;     ///< numeric factorisations in this step
  int factor_updates =
      0;  ///< rank-one factor updates/downdates in this step (dense and CHOLMOD systems)
  double inner_residual = 0.0;  ///< last GNM residual max(||G||/f, ||dx||/||x||)
  double dual_change = 0.0;     ///< ||l^k - l^{k-1}||_2 / ||l^k||_2 (0 where l^k = l^{k-1} = 0)
};

/// KKT residuals of (u, l) for the discrete problem (14), each relative (see docs/solvers.md):
///   equilibrium     ||A u - b + N^T H l||_2 / max(||b||_2, ||N^T H l||_2)   (H = diag(h))
///   penetration     max_j (N u - g)_j^+ / max(||u||_inf, max|g|)
///   sign            max_j (-l_j)^+ / ||l||_inf
///   complementarity max_j |l_j (N u - g)_j| / (||l||_inf max(||u||_inf, max|g|))
/// and with friction (l_j = (normal, tangential), slip v_j = (T u)_j - slip origin, bound s_j
/// Tresca's or mu_j times the normal pressure; docs/method.md, "Friction"):
///   friction_bound  max_j (|l_t,j| - s_j)^+ / ||l||_inf
///   slip            max_j (s_j |v_j| - l_t,j . v_j) / (||l||_inf max(||u||_inf, max|g|)),
///                   0 where the node sticks (v_j = 0) or slides along its force at the bound
struct KktResiduals {
  double equilibrium = 0.0;
  double penetration = 0.0;
  double sign = 0.0;
  double complementarity = 0.0;
  double friction_bound = 0.0;  ///< 0 without friction
  double slip = 0.0;            ///< 0 without friction
  [[nodiscard]] double max() const;
};

/// How the discrete problem was solved (the choice follows from the options: solver.method,
/// schur_complement, linear.type, linear.preconditioner, device; docs/solvers.md).
enum class SolvePath {
  /// Condensed onto the contact nodes by one sparse Cholesky factorisation; the method iterates
  /// on the dense Schur complement (linear.type = "cholmod", schur_complement = true).
  CondensedDirect,
  /// The method iterates on the full sparse system, factorised by CHOLMOD or dense Cholesky.
  SparseDirect,
  /// The full sparse system with Eigen's Jacobi-preconditioned conjugate gradients (host).
  Iterative,
  /// Vectors and PCG on a backend (the CPU backend or a GPU, docs/gpu.md).
  Backend,
  /// Distributed over MPI ranks: PETSc matrices, vectors and Krylov solvers
  /// (docs/distributed.md).
  Distributed,
};

inline constexpr EnumNames<SolvePath, 5> kSolvePathNames{{
    {SolvePath::CondensedDirect, "condensed_direct"},
    {SolvePath::SparseDirect, "sparse_direct"},
    {SolvePath::Iterative, "iterative"},
    {SolvePath::Backend, "backend"},
    {SolvePath::Distributed, "distributed"},
}};

/// One step of a loading history (problem/load_stepping.hpp).
struct LoadStepRecord {
  double factor = 1.0;  ///< the load factor
  bool converged = false;
  int outer_iterations = 0;
  Index active = 0;            ///< contact nodes with a positive pressure
  double contact_force = 0.0;  ///< sum_j h_j l_j
  double seconds = 0.0;        ///< the step's solve
};

struct SolveSummary {
  ContactMethod method = ContactMethod::UzawaGnm;
  SolvePath path = SolvePath::CondensedDirect;  ///< how it was solved
  /// Why that path (SolverPlan::reason, set by the caller that planned it); empty: not said.
  std::string path_reason;
  /// Threads the host solve ran on: 2 when the condensation factorised two parts at once
  /// (ContactSolverOptions::threads), 1 otherwise (the backend path says its own in `device`).
  int threads = 1;
  /// MPI ranks that took part in the solve (1 unless the path is distributed).
  int ranks = 1;
  bool warm_started = false;  ///< started from an earlier solution (ContactSolver::warm_start)
  /// The steps of a loading history up to this one (its last), empty for one solve.
  std::vector<LoadStepRecord> load_steps;
  Termination termination = Termination::Converged;
  std::string message;       ///< one line: why it stopped, with the residuals
  int outer_iterations = 0;  ///< Uzawa iterations (or Newton iterations)
  /// Uzawa-GNM ended by its active-set finish (ContactSolverOptions::active_set_finish): the
  /// last step's projected CG iterations are in its record's linear_iterations.
  bool active_set_finish = false;
  std::vector<OuterStepRecord> steps;  ///< one per outer iteration
  KktResiduals kkt;
  double lagrangian = 0.0;     ///< M(u, l), the modified Lagrangian (10) at the result
  double energy = 0.0;         ///< J(u)
  double contact_force = 0.0;  ///< sum_j h_j l_j: total normal contact force
  /// -sum_j h_j l_j nu_j (z = 0 in 2D)
  Eigen::Vector3d contact_force_vector = Eigen::Vector3d::Zero();
  Index num_active = 0;         ///< contact nodes with l_j > 0
  double classical_step = 0.0;  ///< rho used by classical_uzawa
  /// The augmentation parameter used (uzawa_gnm), whether it was given or automatic, and the
  /// automatic value for comparison (method.md section 7).
  double r = 0.0;
  bool r_automatic = false;
  double automatic_r = 0.0;
  double kkt_tolerance = 0.0;  ///< the tolerance the KKT residuals were held to
  TimingTable timings;
  /// The backend path (docs/gpu.md): where it ran ("CPU, 2 threads", or the GPU's name), the most
  /// memory it held there, and the multigrid levels (unknowns, finest first; empty for Jacobi).
  /// Empty/0 on the host paths.
  std::string device;
  std::size_t device_peak_bytes = 0;
  std::vector<Index> multigrid_levels;
  HierarchyKind multigrid_hierarchy = HierarchyKind::None;  ///< how they were made

  [[nodiscard]] bool converged() const { return termination == Termination::Converged; }
  /// GNM iterations of each Uzawa step (the paper's "7/2" column).
  [[nodiscard]] std::vector<int> inner_iterations() const;
  /// A few lines for a terminal.
  [[nodiscard]] std::string brief_report() const;
};

}  // namespace signorini

#pragma once
// The generalised Newton method (17) with the Armijo rule for step (i) of the Uzawa method:
// minimises Phi for fixed multipliers l (method.md section 4). Written once, against
// NewtonSpace, for the host (sparse or dense Newton systems) and for a backend (PCG on a CPU or
// GPU backend).

#include <string>

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/contact/newton_space.hpp"
#include "signorini/contact/solve_summary.hpp"

namespace signorini {

struct GnmResult {
  Termination termination = Termination::Converged;
  std::string message;
  int iterations = 0;
  int armijo_reductions = 0;
  int linear_iterations = 0;
  int factorizations = 0;
  int factor_updates = 0;
  double residual = 0.0;  ///< max(||G(x_m)||, ||x_m - x_{m-1}|| / ||x_m||) at the last iteration
};

/// ||G|| / max(||b||, ||A x - b||) (||G|| itself where both are 0): the gradient part of the GNM
/// stopping rule, free of units (method.md section 7).
[[nodiscard]] double relative_gradient(double gradient_norm, double b_norm, double residual_norm);

/// With inner_tolerance = adaptive: the Newton systems are solved to this fraction of the GNM
/// tolerance of the Uzawa step, which is this fraction of the previous step's dual change.
inline constexpr double kLinearForcing = 0.1;
inline constexpr double kInnerForcing = 1e-3;
/// With inner_tolerance = adaptive: the relative residual of GNM's first Newton system where no
/// node is active (generalized_newton.cpp). On Hertz's ball it took 3 CG iterations instead of
/// 7-8, and the whole solve 43, 47 and 63 instead of 48, 51 and 68 at 107,586, 434,235 and
/// 1,041,093 unknowns (docs/performance.md, "The first Newton system, loosely").
inline constexpr double kFirstNewtonTolerance = 1e-2;
/// The relative residual of inexact active-set steps (semismooth Newton's on an iterative solver,
/// and Uzawa-GNM's active-set finish) while the active set still moves: measured at 405,600
/// unknowns in 3D, the same active sets as exact steps with half the CG iterations
/// (docs/solvers.md).
inline constexpr double kLooseNewtonTolerance = 1e-6;
/// Uzawa-GNM's active-set finish is tried from step 2 on, once the relative dual change is below
/// this, with at most kFinishSolves active-set solves each time (uzawa_iteration.cpp).
inline constexpr double kFinishDualChange = 0.2;
inline constexpr int kFinishSolves = 10;

class GeneralizedNewton {
 public:
  /// `b_norm` = ||b||, the load part of the force scale of relative_gradient();
  /// `contact_nodes` sizes the automatic iteration limit (gnm_iteration_limit).
  GeneralizedNewton(const ContactSolverOptions& options, double b_norm, Index contact_nodes = 0);

  /// Minimises Phi (set up in `phi`) starting from the point held by `space`, which holds the
  /// minimiser on return. `outer` is the Uzawa step number, passed to the observer.
  /// `tolerance`: the stopping rule's (0: options.gnm_tolerance); with
  /// inner_tolerance = adaptive the Newton systems are solved to a tenth of it (inexact
  /// Newton steps, iterative solvers only).
  GnmResult minimize(const ModifiedLagrangian& phi, NewtonSpace& space, int outer,
                     double tolerance = 0.0) const;

 private:
  const ContactSolverOptions& options_;
  double b_norm_;
  int max_iterations_;
};

}  // namespace signorini

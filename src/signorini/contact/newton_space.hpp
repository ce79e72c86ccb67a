#pragma once
// Where a generalised Newton minimisation (17) keeps its vectors and solves its linear systems:
// the one GNM loop (generalized_newton.cpp) is written against this interface and runs on the
// host (Eigen vectors, a sparse or dense Newton system: host_newton_space.hpp) or on a backend
// (vectors in the backend's memory, PCG there: backend_newton_space.hpp). Only vectors of the
// contact nodes (n_c values: N x, N d, the active set) and scalars cross the interface.

#include <optional>
#include <string>

#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

/// What one linear solve of a Newton system reports.
struct NewtonSolveStats {
  bool converged = true;
  int iterations = 0;      ///< iterations of an iterative solver, 0 for a direct one
  double residual = 0.0;   ///< relative residual reached by an iterative solver
  std::string solver;      ///< what solved it, for messages ("CHOLMOD", "conjugate gradients")
  double tolerance = 0.0;  ///< the iterative solver's tolerance (0 for a direct one)
};

/// Norms after a step, for the stopping rule of GNM (method.md sections 4 and 7).
struct NewtonStepNorms {
  double gradient = 0.0;  ///< ||G(x)|| = ||(A x - b) + N^T (h z_+)||
  double residual = 0.0;  ///< ||A x - b||
  double x = 0.0;         ///< ||x||
  double step = 0.0;      ///< ||t d||, the step just taken
};

/// What a solve with the active set known reports (NewtonSpace::solve_on_active_set).
struct ActiveSetSolve {
  NewtonSolveStats stats;
  Vector l;             ///< the multipliers: the reactions on S, 0 elsewhere
  Vector gap_residual;  ///< N x - g at the new x
};

class NewtonSpace {
 public:
  virtual ~NewtonSpace() = default;

  /// N x at the current point x (n_c values).
  [[nodiscard]] virtual const Vector& contact_values() const = 0;
  /// Makes H(P) = A + r N^T diag(h on P) N the Newton matrix (no work when P has not changed).
  virtual void set_active(const ActiveSet& active, double r) = 0;
  /// The same for any law: H = A + r N^T diag(h D_j) N from a linearisation. Frictionless ones
  /// are their active set; the host's spaces take friction's blocks too, the others refuse them
  /// (ContactSolver sends friction to the host, docs/solvers.md).
  virtual void set_linearization(const Linearization& lin, double r) {
    if (!lin.blocks.empty())
      throw InputError("friction runs on the host's sparse paths only (docs/solvers.md)");
    set_active(lin.active, r);
  }
  /// Solves H(P) x_new = b - N^T terms (17), starting from x_new = x; `terms` are
  /// ModifiedLagrangian::newton_contact_terms(P).
  virtual NewtonSolveStats solve(const Vector& terms) = 0;
  /// The relative tolerance of the following iterative solves (inexact Newton steps,
  /// ContactSolverOptions::inner_tolerance = adaptive); 0: the configured one. Direct solvers
  /// solve exactly and ignore it.
  virtual void set_linear_tolerance(double /*tolerance*/) {}
  /// d = x_new - x: fills dir's <A x - b, d>, <A d, d> and N d (not z, which the loop sets).
  virtual void direction(ModifiedLagrangian::Direction& dir) = 0;
  /// x += t d, A x - b += t A d, N x updated.
  virtual void step(double t) = 0;
  /// The norms at the current point; `contact_forces` are h z_+ at x (n_c values).
  virtual NewtonStepNorms norms(const Vector& contact_forces) = 0;

  /// Where the space can: x <- the minimiser of the energy under (N x)_j = g_j for j in S and
  /// nothing else (active_set_constraint.hpp), to `tolerance` relative to the forces, with the
  /// multipliers it implies. Empty where it cannot: a space without such a solve (the host's,
  /// whose direct paths run the exact method), friction, or contact rows that share a dof.
  virtual std::optional<ActiveSetSolve> solve_on_active_set(const ActiveSet& /*S*/, double /*r*/,
                                                            double /*tolerance*/) {
    return std::nullopt;
  }

  /// Numeric factorisations (direct solvers) or preconditioner refreshes (iterative) so far.
  [[nodiscard]] virtual int factorizations() const = 0;
  /// Rank-one factor updates and downdates so far (the dense Newton system).
  [[nodiscard]] virtual int factor_updates() const { return 0; }
};

}  // namespace signorini

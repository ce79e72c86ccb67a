#pragma once
// The GNM vectors on a backend (docs/gpu.md): every vector of the size of the mesh in the
// backend's memory (the GPU's with solver.device = "cuda"), the Newton systems solved there by
// preconditioned conjugate gradients (Jacobi or a multigrid V-cycle). The stiffness is uploaded
// once; per GNM iteration only scalars (dot products) and vectors of the contact nodes (N x, N d)
// cross between host and device.

#include <memory>
#include <vector>

#include "signorini/backend/backend.hpp"
#include "signorini/contact/active_set_constraint.hpp"
#include "signorini/contact/backend_newton_matrix.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/newton_space.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/iterative/linear_operator.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

class BackendNewtonSpace final : public NewtonSpace {
 public:
  /// Uploads A, N and b, sets up the preconditioner (timed in `timings`; `multigrid` gives the
  /// levels when it is multigrid), starts at x0.
  BackendNewtonSpace(const ContactProblem& problem, const ContactSolverOptions& options,
                     const MultigridHierarchy* multigrid, Backend& backend, TimingTable& timings,
                     const Vector& x0);

  [[nodiscard]] const Vector& contact_values() const override { return Nx_; }
  void set_active(const ActiveSet& active, double r) override;
  /// Friction: the active rows (2D) or the nodes' blocks (3D) as weights of H.
  void set_linearization(const Linearization& lin, double r) override;
  NewtonSolveStats solve(const Vector& terms) override;
  void set_linear_tolerance(double tolerance) override { linear_tolerance_ = tolerance; }
  void direction(ModifiedLagrangian::Direction& dir) override;
  void step(double t) override;
  NewtonStepNorms norms(const Vector& contact_forces) override;
  [[nodiscard]] int factorizations() const override { return refreshes_; }
  /// Projected CG with the Newton matrix of S as the preconditioner (active_set_constraint.hpp).
  std::optional<ActiveSetSolve> solve_on_active_set(const ActiveSet& S, double r,
                                                    double tolerance) override;

  /// x, downloaded.
  [[nodiscard]] Vector solution() const { return to_host(x_); }
  /// Unknowns per multigrid level (empty with Jacobi).
  [[nodiscard]] const std::vector<Index>& levels() const { return newton_.levels; }

 private:
  Vector contact_values_of(const DeviceVector& v);
  PenalizedOperator& H() { return *newton_.H; }

  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  Backend& be_;
  TimingTable& timings_;
  Index n_, nc_;
  BackendNewtonMatrix newton_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_, x_new_, residual_, d_, Ad_, work_, contact_;
  bool stiffness_of_new_ = false;  // Ad_ holds A x_new, from the last solve()
  ActiveSet weights_active_;
  Linearization linearization_;  // friction's, where one was set
  Vector Nx_;
  double last_t_ = 1.0;
  double linear_tolerance_ = 0.0;  // 0: o_.linear.cg_tolerance
  double b_norm_ = 0.0;            // ||b||
  int refreshes_ = 0;
  std::unique_ptr<ActiveSetConstraint> constraint_;  // made at the first solve_on_active_set
  bool constraint_possible_ = true;                  // no friction, the contact rows disjoint
};

}  // namespace signorini

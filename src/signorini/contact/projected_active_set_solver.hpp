#pragma once
// The semismooth Newton step (active_set_solver.hpp) on a backend, for meshes whose factor does
// not fit: conjugate gradients on the constrained subspace {x : (N x)_j = 0, j in S}, which is a
// product of one small subspace per node, since each contact row of N holds the free dofs of
// its own node. The projection onto it is local, P v = v - sum_{j in S} n_j (n_j . v) / |n_j|^2,
// and x = x_S + z with x_S = sum_{j in S} n_j g_j / |n_j|^2 (which meets the constraints) and z
// the solution of P A P z = P (b - A x_S) by CG, preconditioned by P M P, where M is the
// preconditioner of the Newton matrix A + N^T diag(c) N with c_j = r h_j on S (the GNM's, a
// multigrid V-cycle or Jacobi): the penalty stands in for the constraint, and P makes it exact.
// No penalty enters the answer: l_j = n_j . (b - A x) / (|n_j|^2 h_j) on S.

#include <memory>

#include "signorini/backend/backend.hpp"
#include "signorini/contact/active_set_solver.hpp"
#include "signorini/contact/backend_newton_matrix.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

class ProjectedActiveSetSolver final : public ActiveSetSolver {
 public:
  /// Uploads A, N, b and sets up the preconditioner (`multigrid`: the levels where it is
  /// multigrid); starts from x0. `r` scales the penalty of the preconditioner only. Throws
  /// InputError where two contact rows share a dof (the projection would not be local).
  ProjectedActiveSetSolver(const ContactProblem& problem, const ContactSolverOptions& options,
                           double r, const MultigridHierarchy* multigrid, Backend& backend,
                           const Vector& x0);
  ~ProjectedActiveSetSolver() override;

  LinearSolveStats solve(const ActiveSet& S, Vector& l, Vector& gap_residual) override;
  [[nodiscard]] Vector displacement() const override { return to_host(x_); }
  [[nodiscard]] int last_factorizations() const override { return last_refreshes_; }
  [[nodiscard]] bool iterative() const override { return true; }
  void set_tolerance(double tolerance) override { tolerance_ = tolerance; }
  /// Unknowns per multigrid level (empty with Jacobi).
  [[nodiscard]] const std::vector<Index>& levels() const { return newton_->levels; }

 private:
  class Projected;
  void project(DeviceVector& v);

  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  double r_;
  Backend& be_;
  Index n_, nc_;
  Vector inverse_norm2_;  // 1 / |n_j|^2 (0 where n_j = 0)
  std::unique_ptr<BackendNewtonMatrix> newton_;
  std::unique_ptr<Projected> projected_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_, z_, rhs_, work_, contact_, minus_w_;
  ActiveSet active_;
  bool first_ = true;
  int last_refreshes_ = 0;
  double b_norm_ = 0.0;
  double tolerance_ = 0.0;  // 0: cg_tolerance
};

}  // namespace signorini

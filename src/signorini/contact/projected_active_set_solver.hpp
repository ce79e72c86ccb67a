#pragma once
// The semismooth Newton step (active_set_solver.hpp) on a backend, for meshes whose factor does
// not fit: each step is the problem with its active set S known, solved by projected conjugate
// gradients on the constrained subspace (active_set_constraint.hpp), preconditioned by the
// Newton matrix A + N^T diag(c) N with c_j = r h_j on S (the GNM's, a multigrid V-cycle or
// Jacobi), which follows S.

#include <memory>

#include "signorini/backend/backend.hpp"
#include "signorini/contact/active_set_constraint.hpp"
#include "signorini/contact/active_set_solver.hpp"
#include "signorini/contact/backend_newton_matrix.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

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
  const ContactProblem& p_;
  const ContactSolverOptions& o_;
  double r_;
  Backend& be_;
  std::unique_ptr<BackendNewtonMatrix> newton_;
  std::unique_ptr<Pcg> pcg_;
  DeviceVector b_, x_, z_, rhs_, work_;
  std::unique_ptr<ActiveSetConstraint> constraint_;
  ActiveSet active_;
  bool first_ = true;
  int last_refreshes_ = 0;
  double b_norm_ = 0.0;
  double tolerance_ = 0.0;  // 0: cg_tolerance
};

}  // namespace signorini

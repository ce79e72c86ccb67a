#include "signorini/contact/projected_active_set_solver.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

ProjectedActiveSetSolver::ProjectedActiveSetSolver(const ContactProblem& problem,
                                                   const ContactSolverOptions& options, double r,
                                                   const MultigridHierarchy* multigrid,
                                                   Backend& backend, const Vector& x0)
    : p_(problem), o_(options), r_(r), be_(backend) {
  // Each dof in at most one contact row: then the rows are orthogonal and the projection local.
  std::pair<Index, Index> shared;
  if (!contact_rows_disjoint(problem.contact.N, &shared))
    throw InputError(fmt::format(
        "solver.method = \"semismooth_newton\" on the iterative path: contact nodes {} and {} "
        "share a degree of freedom (two contact boundaries on one node); use "
        "\"uzawa_gnm\", or a direct solver",
        shared.first, shared.second));
  newton_ = std::make_unique<BackendNewtonMatrix>(problem, options, multigrid, backend, timings_);
  {
    ScopedTimer t(timings_, "device upload");
    b_ = to_device(be_, problem.b);
    x_ = to_device(be_, x0);
    b_norm_ = norm(be_, b_);
    const Index n = problem.A.rows();
    z_ = DeviceVector(be_, n);
    rhs_ = DeviceVector(be_, n);
    work_ = DeviceVector(be_, n);
    pcg_ = std::make_unique<Pcg>(be_, n);
    constraint_ = std::make_unique<ActiveSetConstraint>(
        problem, options.linear, *newton_, be_,
        ActiveSetConstraint::Workspace{*pcg_, z_, rhs_, work_});
    be_.synchronize();
  }
}

ProjectedActiveSetSolver::~ProjectedActiveSetSolver() = default;

LinearSolveStats ProjectedActiveSetSolver::solve(const ActiveSet& S, Vector& l,
                                                 Vector& gap_residual) {
  last_refreshes_ = 0;
  if (first_ || S != active_) {
    // The preconditioner follows the Newton matrix of S: A + N^T diag(c) N, c_j = r h_j on S.
    active_ = S;
    first_ = false;
    newton_->set_active(S, r_, p_.contact.weights, timings_);
    last_refreshes_ = 1;
  }
  // To cg_tolerance, or the looser tolerance of the first steps (semismooth_newton_solver.cpp).
  return constraint_->solve(S, x_, b_, b_norm_,
                            tolerance_ > 0.0 ? tolerance_ : o_.linear.cg_tolerance, l, gap_residual,
                            timings_);
}

}  // namespace signorini

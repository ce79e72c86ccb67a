#include "signorini/contact/projected_active_set_solver.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/core/error.hpp"
#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

// P A and P M on the constrained subspace. CG's iterates stay in it (each direction is P M r),
// so P A P = P A there, and P M P = P M on residuals that P has made.
class ProjectedActiveSetSolver::Projected {
 public:
  class Stiffness final : public LinearOperator {
   public:
    explicit Stiffness(ProjectedActiveSetSolver& s) : s_(s) {}
    [[nodiscard]] Index size() const override { return s_.n_; }
    void apply(const DeviceVector& x, DeviceVector& y) override {
      s_.newton_->H->apply_stiffness(x, y);
      s_.project(y);
    }

   private:
    ProjectedActiveSetSolver& s_;
  };
  class Preconditioning final : public Preconditioner {
   public:
    explicit Preconditioning(ProjectedActiveSetSolver& s) : s_(s) {}
    void apply(const DeviceVector& r, DeviceVector& z) override {
      s_.newton_->preconditioner->apply(r, z);
      s_.project(z);
    }
    void refresh() override { s_.newton_->preconditioner->refresh(); }

   private:
    ProjectedActiveSetSolver& s_;
  };
  explicit Projected(ProjectedActiveSetSolver& s) : stiffness(s), preconditioning(s) {}
  Stiffness stiffness;
  Preconditioning preconditioning;
};

ProjectedActiveSetSolver::ProjectedActiveSetSolver(const ContactProblem& problem,
                                                   const ContactSolverOptions& options, double r,
                                                   const MultigridHierarchy* multigrid,
                                                   Backend& backend, const Vector& x0)
    : p_(problem),
      o_(options),
      r_(r),
      be_(backend),
      n_(problem.A.rows()),
      nc_(problem.contact.size()) {
  const SparseMatrix& N = problem.contact.N;
  // Each dof in at most one contact row: then the rows are orthogonal and P is local.
  inverse_norm2_ = Vector::Zero(nc_);
  for (Index k = 0; k < N.outerSize(); ++k) {
    Index row = -1;
    for (SparseMatrix::InnerIterator it(N, k); it; ++it) {
      if (it.value() == 0.0) continue;
      if (row >= 0)
        throw InputError(fmt::format(
            "solver.method = \"semismooth_newton\" on the iterative path: contact nodes {} and {} "
            "share a degree of freedom (two contact boundaries on one node); use "
            "\"uzawa_gnm\", or a direct solver",
            row, it.row()));
      row = it.row();
      inverse_norm2_(row) += it.value() * it.value();
    }
  }
  for (Index j = 0; j < nc_; ++j)
    if (inverse_norm2_(j) > 0.0) inverse_norm2_(j) = 1.0 / inverse_norm2_(j);
  newton_ = std::make_unique<BackendNewtonMatrix>(problem, options, multigrid, backend, timings_);
  {
    ScopedTimer t(timings_, "device upload");
    b_ = to_device(be_, problem.b);
    x_ = to_device(be_, x0);
    z_ = DeviceVector(be_, n_);
    rhs_ = DeviceVector(be_, n_);
    work_ = DeviceVector(be_, n_);
    contact_ = DeviceVector(be_, nc_);
    minus_w_ = DeviceVector(be_, nc_);
    b_norm_ = norm(be_, b_);
    be_.synchronize();
  }
  projected_ = std::make_unique<Projected>(*this);
  pcg_ = std::make_unique<Pcg>(be_, n_);
}

ProjectedActiveSetSolver::~ProjectedActiveSetSolver() = default;

void ProjectedActiveSetSolver::project(DeviceVector& v) {
  // v <- v - N^T (w .* (N v)), w_j = 1 / |n_j|^2 on S, 0 elsewhere
  if (nc_ == 0) return;
  newton_->H->apply_contact(v, contact_);
  be_.multiply(minus_w_, contact_, contact_);
  newton_->H->apply_contact_transpose(contact_, v, 1.0);
}

LinearSolveStats ProjectedActiveSetSolver::solve(const ActiveSet& S, Vector& l,
                                                 Vector& gap_residual) {
  const ContactSet& c = p_.contact;
  const auto in_S = [&](Index j) { return S[static_cast<std::size_t>(j)]; };
  last_refreshes_ = 0;
  if (first_ || S != active_) {
    // The preconditioner follows the Newton matrix of S: A + N^T diag(c) N, c_j = r h_j on S.
    active_ = S;
    first_ = false;
    Vector minus_w = Vector::Zero(nc_);
    for (Index j = 0; j < nc_; ++j)
      if (in_S(j)) minus_w(j) = -inverse_norm2_(j);
    upload_into(minus_w, minus_w_);
    newton_->set_active(S, r_, c.weights, timings_);
    last_refreshes_ = 1;
  }
  // The start: the last x moved onto the constraints, x = P x + x_S.
  project(x_);
  Vector target = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j)
    if (in_S(j)) target(j) = c.gaps(j) * inverse_norm2_(j);
  upload_into(target, contact_);
  newton_->H->apply_contact_transpose(contact_, x_, 1.0);
  // P A P z = P (b - A x) by CG, to ||P (b - A x)|| <= cg_tolerance max(||b||, ||b - A x||)
  // (or the looser tolerance of the first steps, semismooth_newton_solver.cpp):
  // the force scale of the loads, or where there are none (a body pressed by its obstacles
  // alone) of the forces that the start's constraints ask for.
  newton_->H->apply_stiffness(x_, rhs_);
  be_.axpby(1.0, b_, -1.0, rhs_);
  const double force_scale = std::max(b_norm_, norm(be_, rhs_));
  project(rhs_);
  const double rhs_norm = norm(be_, rhs_);
  LinearSolveStats stats;
  const double goal = (tolerance_ > 0.0 ? tolerance_ : o_.linear.cg_tolerance) * force_scale;
  if (rhs_norm > goal) {
    PcgOptions po = pcg_options(o_.linear, n_);
    po.tolerance = goal / rhs_norm;
    po.zero_initial_guess = true;
    PcgResult lin;
    {
      ScopedTimer t(timings_, "linear solve");
      lin = pcg_->solve(projected_->stiffness, projected_->preconditioning, rhs_, z_, po);
    }
    be_.axpby(1.0, z_, 1.0, x_);
    stats.iterations = lin.iterations;
    stats.residual = lin.residual;
    stats.converged = lin.converged;
  }
  // Multipliers from the reactions: h_j l_j = n_j . (b - A x) / |n_j|^2 on S.
  newton_->H->apply_stiffness(x_, work_);
  be_.axpby(1.0, b_, -1.0, work_);
  newton_->H->apply_contact(work_, contact_);
  const Vector reaction = to_host(contact_);
  newton_->H->apply_contact(x_, contact_);
  const Vector Nx = to_host(contact_);
  l = Vector::Zero(nc_);
  gap_residual = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    if (in_S(j)) l(j) = reaction(j) * inverse_norm2_(j) / c.weights(j);
    gap_residual(j) = Nx(j) - c.gaps(j);
  }
  return stats;
}

}  // namespace signorini

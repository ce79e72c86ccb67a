#include "signorini/contact/active_set_constraint.hpp"

#include <algorithm>

#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

bool contact_rows_disjoint(const SparseMatrix& N, std::pair<Index, Index>* first_shared) {
  for (Index k = 0; k < N.outerSize(); ++k) {
    Index row = -1;
    for (SparseMatrix::InnerIterator it(N, k); it; ++it) {
      if (it.value() == 0.0) continue;
      if (row >= 0) {
        if (first_shared != nullptr) *first_shared = {row, it.row()};
        return false;
      }
      row = it.row();
    }
  }
  return true;
}

// P A and P M on the constrained subspace. CG's iterates stay in it (each direction is P M r),
// so P A P = P A there, and P M P = P M on residuals that P has made.
class ActiveSetConstraint::Projected {
 public:
  class Stiffness final : public LinearOperator {
   public:
    explicit Stiffness(ActiveSetConstraint& s) : s_(s) {}
    [[nodiscard]] Index size() const override { return s_.n_; }
    void apply(const DeviceVector& x, DeviceVector& y) override {
      s_.newton_.H->apply_stiffness(x, y);
      s_.project(y);
    }

   private:
    ActiveSetConstraint& s_;
  };
  class Preconditioning final : public Preconditioner {
   public:
    explicit Preconditioning(ActiveSetConstraint& s) : s_(s) {}
    void apply(const DeviceVector& r, DeviceVector& z) override {
      s_.newton_.preconditioner->apply(r, z);
      s_.project(z);
    }
    void refresh() override { s_.newton_.preconditioner->refresh(); }

   private:
    ActiveSetConstraint& s_;
  };
  explicit Projected(ActiveSetConstraint& s) : stiffness(s), preconditioning(s) {}
  Stiffness stiffness;
  Preconditioning preconditioning;
};

ActiveSetConstraint::ActiveSetConstraint(const ContactProblem& problem,
                                         const LinearSolverOptions& linear,
                                         BackendNewtonMatrix& newton, Backend& backend,
                                         Workspace workspace)
    : p_(problem),
      linear_(linear),
      newton_(newton),
      be_(backend),
      n_(problem.A.rows()),
      nc_(problem.contact.size()),
      w_(workspace) {
  const SparseMatrix& N = problem.contact.N;
  inverse_norm2_ = Vector::Zero(nc_);
  for (Index k = 0; k < N.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(N, k); it; ++it)
      inverse_norm2_(it.row()) += it.value() * it.value();
  for (Index j = 0; j < nc_; ++j)
    if (inverse_norm2_(j) > 0.0) inverse_norm2_(j) = 1.0 / inverse_norm2_(j);
  contact_ = DeviceVector(be_, nc_);
  minus_w_ = DeviceVector(be_, nc_);
  projected_ = std::make_unique<Projected>(*this);
}

ActiveSetConstraint::~ActiveSetConstraint() = default;

void ActiveSetConstraint::project(DeviceVector& v) {
  // v <- v - N^T (w .* (N v)), w_j = 1 / |n_j|^2 on S, 0 elsewhere
  if (nc_ == 0) return;
  newton_.H->apply_contact(v, contact_);
  be_.multiply(minus_w_, contact_, contact_);
  newton_.H->apply_contact_transpose(contact_, v, 1.0);
}

LinearSolveStats ActiveSetConstraint::solve(const ActiveSet& S, DeviceVector& x,
                                            const DeviceVector& b, double b_norm, double tolerance,
                                            Vector& l, Vector& gap_residual, TimingTable& timings) {
  const ContactSet& c = p_.contact;
  const auto in_S = [&](Index j) { return S[static_cast<std::size_t>(j)]; };
  if (S != weights_for_) {
    Vector minus_w = Vector::Zero(nc_);
    for (Index j = 0; j < nc_; ++j)
      if (in_S(j)) minus_w(j) = -inverse_norm2_(j);
    upload_into(minus_w, minus_w_);
    weights_for_ = S;
  }
  // The start: x moved onto the constraints, x = P x + x_S.
  project(x);
  Vector target = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j)
    if (in_S(j)) target(j) = c.gaps(j) * inverse_norm2_(j);
  upload_into(target, contact_);
  newton_.H->apply_contact_transpose(contact_, x, 1.0);
  // P A P z = P (b - A x) by CG, to ||P (b - A x)|| <= tolerance max(||b||, ||b - A x||): the
  // force scale of the loads, or where there are none (a body pressed by its obstacles alone)
  // of the forces that the start's constraints ask for.
  newton_.H->apply_stiffness(x, w_.rhs);
  be_.axpby(1.0, b, -1.0, w_.rhs);
  const double force_scale = std::max(b_norm, norm(be_, w_.rhs));
  project(w_.rhs);
  const double rhs_norm = norm(be_, w_.rhs);
  LinearSolveStats stats;
  const double goal = tolerance * force_scale;
  if (rhs_norm > goal) {
    PcgOptions po = pcg_options(linear_, n_);
    po.tolerance = goal / rhs_norm;
    po.zero_initial_guess = true;
    PcgResult lin;
    {
      ScopedTimer t(timings, "linear solve");
      lin = w_.pcg.solve(projected_->stiffness, projected_->preconditioning, w_.rhs, w_.z, po);
    }
    be_.axpby(1.0, w_.z, 1.0, x);
    stats.iterations = lin.iterations;
    stats.residual = lin.residual;
    stats.converged = lin.converged;
  }
  // Multipliers from the reactions: h_j l_j = n_j . (b - A x) / |n_j|^2 on S.
  newton_.H->apply_stiffness(x, w_.work);
  be_.axpby(1.0, b, -1.0, w_.work);
  newton_.H->apply_contact(w_.work, contact_);
  const Vector reaction = to_host(contact_);
  newton_.H->apply_contact(x, contact_);
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

#include "signorini/contact/backend_newton_space.hpp"

#include <algorithm>
#include <limits>

#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

BackendNewtonSpace::BackendNewtonSpace(const ContactProblem& problem,
                                       const ContactSolverOptions& options,
                                       const MultigridHierarchy* multigrid, Backend& backend,
                                       TimingTable& timings, const Vector& x0)
    : p_(problem),
      o_(options),
      be_(backend),
      timings_(timings),
      n_(problem.A.rows()),
      nc_(problem.contact.N.rows()),  // the rows of N (d per node with friction)
      newton_(problem, options, multigrid, backend, timings) {
  {
    ScopedTimer t(timings_, "device upload");
    b_ = to_device(be_, problem.b);
    x_ = to_device(be_, x0);
    x_new_ = DeviceVector(be_, n_);
    residual_ = DeviceVector(be_, n_);
    d_ = DeviceVector(be_, n_);
    Ad_ = DeviceVector(be_, n_);
    work_ = DeviceVector(be_, n_);
    contact_ = DeviceVector(be_, nc_);
    H().apply_stiffness(x_, residual_);  // A x - b at x0
    be_.axpby(-1.0, b_, 1.0, residual_);
    b_norm_ = norm(be_, b_);
    be_.synchronize();
  }
  pcg_ = std::make_unique<Pcg>(be_, n_);
  weights_active_.assign(static_cast<std::size_t>(problem.contact.size()), false);
  Nx_ = contact_values_of(x_);
}

// c_j = r h_j on the active set: H = A + N^T diag(c) N (the Hessian of ModifiedLagrangian), and
// the preconditioner follows. The preconditioner was set up for c = 0 (no node active).
void BackendNewtonSpace::set_active(const ActiveSet& active, double r) {
  if (active == weights_active_) return;
  weights_active_ = active;
  newton_.set_active(active, r, p_.contact.weights, timings_);
  ++refreshes_;
}

void BackendNewtonSpace::set_linearization(const Linearization& lin, double r) {
  if (lin.blocks.empty()) {
    set_active(lin.active, r);
    return;
  }
  if (lin == linearization_ && refreshes_ > 0) return;
  linearization_ = lin;
  const ContactSet& c = p_.contact;
  const Index m = c.components;
  if (!lin.rows.empty()) {
    // 2D: c = r h on the rows whose entry of D is 1, as the frictionless law on its nodes.
    Vector weights = Vector::Zero(nc_);
    for (Index i = 0; i < nc_; ++i)
      if (lin.rows[static_cast<std::size_t>(i)]) weights(i) = r * c.weights(i / m);
    newton_.set_row_weights(weights, timings_);
  } else {
    // 3D: W = blockdiag(r h_j D_j), D_j the node's derivative of P (symmetric for step (i)).
    std::vector<Eigen::Triplet<double, Index>> entries;
    for (Index j = 0; j < c.size(); ++j)
      for (Index b = 0; b < m; ++b)
        for (Index a = 0; a < m; ++a) {
          const double v = lin.blocks[static_cast<std::size_t>(m * m * j + a + m * b)];
          if (v != 0.0) entries.emplace_back(m * j + a, m * j + b, r * c.weights(j) * v);
        }
    SparseMatrix W(nc_, nc_);
    W.setFromTriplets(entries.begin(), entries.end());
    newton_.set_block_weights(W, m, timings_);
  }
  ++refreshes_;
}

NewtonSolveStats BackendNewtonSpace::solve(const Vector& terms) {
  // Newton right-hand side b - N^T terms, then H x_new = rhs by PCG from x_new = x (17).
  upload_into(Vector(-terms), contact_);
  be_.copy(b_, work_);
  H().apply_contact_transpose(contact_, work_, 1.0);
  be_.copy(x_, x_new_);
  PcgOptions options = pcg_options(o_.linear, n_);
  if (linear_tolerance_ > 0.0) options.tolerance = linear_tolerance_;
  // The first residual rhs - H x = rhs - (A x - b) - b - N^T W N x from the A x - b kept: the
  // contact rows' products instead of a product with A (d is free until direction()).
  be_.axpbyz(1.0, work_, -1.0, residual_, d_);
  be_.axpby(-1.0, b_, 1.0, d_);
  H().add_contact_terms(x_, d_, -1.0);
  options.initial_residual = &d_;
  PcgResult lin;
  {
    ScopedTimer t(timings_, "linear solve");
    lin = pcg_->solve(H(), *newton_.preconditioner, work_, x_new_, options);
  }
  // A x_new for direction(), from what the solve left: H x_new = rhs - r (PCG's residual), so
  // A x_new = rhs - r - N^T W N x_new, the contact rows' products instead of a product with A
  // (one of the fine level's largest costs) in every GNM iteration.
  be_.axpbyz(1.0, work_, -1.0, pcg_->residual(), Ad_);
  H().add_contact_terms(x_new_, Ad_, -1.0);
  stiffness_of_new_ = true;
  NewtonSolveStats out;
  out.converged = lin.converged;
  out.iterations = lin.iterations;
  out.residual = lin.residual;
  out.solver = "conjugate gradients";
  out.tolerance = options.tolerance;
  return out;
}

void BackendNewtonSpace::direction(ModifiedLagrangian::Direction& dir) {
  be_.axpbyz(1.0, x_new_, -1.0, x_, d_);
  if (stiffness_of_new_) {
    // A d = A x_new - A x, where A x = residual + b.
    be_.axpby(-1.0, residual_, 1.0, Ad_);
    be_.axpby(-1.0, b_, 1.0, Ad_);
    stiffness_of_new_ = false;
  } else {
    H().apply_stiffness(d_, Ad_);
  }
  dir.residual_dot_d = be_.dot(residual_, d_);
  dir.d_A_d = be_.dot(Ad_, d_);
  dir.Nd = contact_values_of(d_);
}

void BackendNewtonSpace::step(double t) {
  be_.axpby(t, d_, 1.0, x_);
  be_.axpby(t, Ad_, 1.0, residual_);
  Nx_ = contact_values_of(x_);
  last_t_ = t;
}

NewtonStepNorms BackendNewtonSpace::norms(const Vector& contact_forces) {
  // G = (A x - b) + N^T (h z_+)
  upload_into(contact_forces, contact_);
  be_.copy(residual_, work_);
  H().apply_contact_transpose(contact_, work_, 1.0);
  NewtonStepNorms n;
  n.gradient = norm(be_, work_);
  n.residual = norm(be_, residual_);
  n.x = norm(be_, x_);
  n.step = last_t_ * norm(be_, d_);
  return n;
}

std::optional<ActiveSetSolve> BackendNewtonSpace::solve_on_active_set(const ActiveSet& S, double r,
                                                                      double tolerance) {
  if (!constraint_ && constraint_possible_) {
    constraint_possible_ = p_.contact.components == 1 && contact_rows_disjoint(p_.contact.N);
    if (constraint_possible_)
      // (The Newton systems' CG and vectors, free between GNM iterations: x_new, d and A d are
      // set again before the next one reads them.)
      constraint_ = std::make_unique<ActiveSetConstraint>(
          p_, o_.linear, newton_, be_, ActiveSetConstraint::Workspace{*pcg_, x_new_, d_, Ad_});
  }
  if (!constraint_) return std::nullopt;
  stiffness_of_new_ = false;  // (Ad_ is the constraint's work vector)
  set_active(S, r);           // (the preconditioner: the Newton matrix of S)
  ActiveSetSolve out;
  const LinearSolveStats s =
      constraint_->solve(S, x_, b_, b_norm_, tolerance, out.l, out.gap_residual, timings_);
  // A x - b and N x at the new x: the constraint's solve leaves b - A x in its work vector (Ad_),
  // so no product with A is spent on it again.
  be_.axpbyz(-1.0, Ad_, 0.0, Ad_, residual_);
  Nx_ = contact_values_of(x_);
  out.stats.converged = s.converged;
  out.stats.iterations = s.iterations;
  out.stats.residual = s.residual;
  out.stats.solver = "projected conjugate gradients";
  out.stats.tolerance = tolerance;
  return out;
}

Vector BackendNewtonSpace::contact_values_of(const DeviceVector& v) {
  H().apply_contact(v, contact_);
  return to_host(contact_);
}

}  // namespace signorini

#include "signorini/contact/backend_newton_space.hpp"

#include <algorithm>
#include <limits>

#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
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
      nc_(problem.contact.size()) {
  {
    ScopedTimer t(timings_, "device upload");
    // The problem outlives this space, so the stiffness (the largest matrix of the solve) may be
    // multiplied in place where a faster copy would not fit (stiffness_arrays).
    H_ = std::make_unique<PenalizedOperator>(be_, problem.A, problem.contact.N,
                                             stiffness_arrays(problem.A));
    b_ = to_device(be_, problem.b);
    x_ = to_device(be_, x0);
    x_new_ = DeviceVector(be_, n_);
    residual_ = DeviceVector(be_, n_);
    d_ = DeviceVector(be_, n_);
    Ad_ = DeviceVector(be_, n_);
    work_ = DeviceVector(be_, n_);
    contact_ = DeviceVector(be_, nc_);
    H_->apply_stiffness(x_, residual_);  // A x - b at x0
    be_.axpby(-1.0, b_, 1.0, residual_);
    be_.synchronize();
  }
  // The multigrid set-up (Galerkin coarse operators on the host, their upload) is timed apart
  // from the set-ups per active set ("preconditioner setup").
  ScopedTimer t(timings_, o_.linear.preconditioner == PreconditionerType::Multigrid
                              ? "multigrid setup"
                              : "preconditioner setup");
  preconditioner_ = make_preconditioner(*H_, problem.A, problem.contact.N, multigrid, o_.linear);
  if (const auto* mg = dynamic_cast<const MultigridPreconditioner*>(preconditioner_.get()))
    levels_ = mg->level_sizes();
  be_.synchronize();
  pcg_ = std::make_unique<Pcg>(be_, n_);
  weights_active_.assign(static_cast<std::size_t>(nc_), false);
  Nx_ = contact_values_of(x_);
}

// c_j = r h_j on the active set: H = A + N^T diag(c) N (the Hessian of ModifiedLagrangian), and
// the preconditioner follows. The preconditioner was set up for c = 0 (no node active).
void BackendNewtonSpace::set_active(const ActiveSet& active, double r) {
  if (active == weights_active_) return;
  weights_active_ = active;
  Vector c = Vector::Zero(nc_);
  for (Index j = 0; j < nc_; ++j)
    if (active[static_cast<std::size_t>(j)]) c(j) = r * p_.contact.weights(j);
  ScopedTimer timer(timings_, "preconditioner setup");
  H_->set_weights(c);
  preconditioner_->refresh();
  ++refreshes_;
}

NewtonSolveStats BackendNewtonSpace::solve(const Vector& terms) {
  // Newton right-hand side b - N^T terms, then H x_new = rhs by PCG from x_new = x (17).
  upload_into(Vector(-terms), contact_);
  be_.copy(b_, work_);
  H_->apply_contact_transpose(contact_, work_, 1.0);
  be_.copy(x_, x_new_);
  PcgOptions options = pcg_options(o_.linear, n_);
  if (linear_tolerance_ > 0.0) options.tolerance = linear_tolerance_;
  PcgResult lin;
  {
    ScopedTimer t(timings_, "linear solve");
    lin = pcg_->solve(*H_, *preconditioner_, work_, x_new_, options);
  }
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
  H_->apply_stiffness(d_, Ad_);
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
  H_->apply_contact_transpose(contact_, work_, 1.0);
  NewtonStepNorms n;
  n.gradient = norm(be_, work_);
  n.residual = norm(be_, residual_);
  n.x = norm(be_, x_);
  n.step = last_t_ * norm(be_, d_);
  return n;
}

Vector BackendNewtonSpace::contact_values_of(const DeviceVector& v) {
  H_->apply_contact(v, contact_);
  return to_host(contact_);
}

}  // namespace signorini

#include "signorini/contact/host_newton_space.hpp"

namespace signorini {

HostNewtonSpace::HostNewtonSpace(const ContactProblem& problem, NewtonSystem& system, Vector x0)
    : p_(problem), system_(system), x_(std::move(x0)) {
  Nx_ = p_.contact.N * x_;
  // A x - b, formed once and then updated by t A d with each step: one product with A per GNM
  // iteration.
  residual_ = p_.A * x_ - p_.b;
}

void HostNewtonSpace::set_active(const ActiveSet& active, double /*r: the system's phi has it*/) {
  system_.set_active(active);  // H(x_{m-1}) = A + r sum_{active} h_j nu_j nu_j^T
}

void HostNewtonSpace::set_linearization(const Linearization& lin, double /*r*/) {
  system_.set_linearization(lin);  // H = A + r N^T diag(h D_j) N (with friction)
}

NewtonSolveStats HostNewtonSpace::solve(const Vector& terms) {
  x_new_ = x_;
  const LinearSolveStats s = system_.solve(p_.b - p_.contact.N.transpose() * terms, x_new_);
  NewtonSolveStats out;
  out.converged = s.converged;
  out.iterations = s.iterations;
  out.residual = s.residual;
  out.solver = "the linear solver";
  return out;
}

void HostNewtonSpace::direction(ModifiedLagrangian::Direction& dir) {
  d_ = x_new_ - x_;
  Ad_ = p_.A * d_;
  dir.residual_dot_d = residual_.dot(d_);
  dir.d_A_d = Ad_.dot(d_);
  dir.Nd = p_.contact.N * d_;
}

void HostNewtonSpace::step(double t) {
  if (t != 1.0) d_ *= t;
  x_ += d_;
  residual_ += t * Ad_;
  Nx_ = p_.contact.N * x_;
  step_norm_ = d_.norm();
}

NewtonStepNorms HostNewtonSpace::norms(const Vector& contact_forces) {
  NewtonStepNorms n;
  n.gradient = (residual_ + p_.contact.N.transpose() * contact_forces).norm();
  n.residual = residual_.norm();
  n.x = x_.norm();
  n.step = step_norm_;
  return n;
}

}  // namespace signorini

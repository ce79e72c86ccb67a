#pragma once
// The GNM vectors on the host: x, A x - b, N x and the Newton point as Eigen vectors, the Newton
// systems solved by a NewtonSystem (CHOLMOD, Eigen CG or the dense updatable Cholesky).

#include "signorini/contact/newton_space.hpp"
#include "signorini/contact/newton_system.hpp"

namespace signorini {

class HostNewtonSpace final : public NewtonSpace {
 public:
  /// Starts at x0 (a warm start; zero for the paper's x^0 = 0).
  HostNewtonSpace(const ContactProblem& problem, NewtonSystem& system, Vector x0);

  [[nodiscard]] const Vector& contact_values() const override { return Nx_; }
  void set_active(const ActiveSet& active, double r) override;
  void set_linearization(const Linearization& lin, double r) override;
  NewtonSolveStats solve(const Vector& terms) override;
  void direction(ModifiedLagrangian::Direction& dir) override;
  void step(double t) override;
  NewtonStepNorms norms(const Vector& contact_forces) override;
  [[nodiscard]] int factorizations() const override { return system_.factorizations(); }
  [[nodiscard]] int factor_updates() const override { return system_.updates(); }

  [[nodiscard]] const Vector& x() const { return x_; }
  [[nodiscard]] Vector take_x() { return std::move(x_); }

 private:
  const ContactProblem& p_;
  NewtonSystem& system_;
  Vector x_, x_new_, d_, Ad_, residual_, Nx_;
  double step_norm_ = 0.0;
};

}  // namespace signorini

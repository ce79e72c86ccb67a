#include "signorini/contact/generalized_newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "signorini/contact/armijo_rule.hpp"

namespace signorini {

void set_gnm_iteration_limit(GnmResult& res, const ContactSolverOptions& options, int outer) {
  res.termination = Termination::IterationLimit;
  res.message = fmt::format(
      "GNM did not converge in {} iterations at Uzawa step {} (residual {:.3e}, tolerance {:.1e})",
      options.max_gnm_iterations, outer, res.residual, options.gnm_tolerance);
}

double relative_gradient(double gradient_norm, double b_norm, double residual_norm) {
  const double force = std::max(b_norm, residual_norm);
  return force > 0.0 ? gradient_norm / force : gradient_norm;
}

GeneralizedNewton::GeneralizedNewton(const ContactProblem& problem,
                                     const ContactSolverOptions& options, NewtonSystem& system)
    : problem_(problem), options_(options), system_(system), b_norm_(problem.b.norm()) {}

GnmResult GeneralizedNewton::minimize(const ModifiedLagrangian& phi, Vector& x, int outer) {
  const SparseMatrix& N = problem_.contact.N;
  GnmResult res;
  const int factorizations_before = system_.factorizations();
  const int updates_before = system_.updates();
  auto count_work = [&] {
    res.factorizations = system_.factorizations() - factorizations_before;
    res.factor_updates = system_.updates() - updates_before;
  };
  Vector Nx = N * x;
  // A x - b, formed once per call and then updated by t A d with each step: one product with A
  // per GNM iteration.
  Vector residual = problem_.A * x - problem_.b;
  ActiveSet previous;          // active set that defined the previous Newton step
  bool previous_full = false;  // previous step was a full Newton step (no Armijo cut)
  double gradient_norm = std::numeric_limits<double>::infinity();

  for (int m = 1; m <= options_.max_gnm_iterations; ++m) {
    const ActiveSet active = phi.active_set(Nx);
    IterationEvent ev{IterationEvent::Kind::Inner, outer, m, count_active(active), 0.0, 0, 0};

    // The active set repeats after a full Newton step: x minimises the quadratic piece that is
    // active at x, so it is the minimiser of Phi and this Newton step would return x itself
    // (method.md section 4: "the active set repeating at two successive steps"). It is counted as
    // an iteration, as the paper does, but costs no linear solve.
    if (m > 1 && previous_full && active == previous) {
      res.iterations = m;
      res.residual = gradient_norm;
      ev.residual = res.residual;
      if (options_.observer) options_.observer(ev);
      count_work();
      return res;
    }

    system_.set_active(active);  // H(x_{m-1}) = A + r sum_{active} h_j nu_j nu_j^T
    Vector x_new = x;
    const LinearSolveStats stats = system_.solve(phi.newton_rhs(active), x_new);
    res.linear_iterations += stats.iterations;
    ev.linear_iterations = stats.iterations;
    if (!stats.converged) {
      res.termination = Termination::LinearSolverFailure;
      res.message = fmt::format(
          "linear solver did not converge in GNM iteration {} of Uzawa step {} (relative "
          "residual {:.3e})",
          m, outer, stats.residual);
      res.iterations = m;
      count_work();
      return res;
    }

    // Armijo rule when the Newton point does not decrease Phi (method.md section 4).
    Vector d = x_new - x;
    const auto dir = phi.direction(residual, Nx, d);
    const ArmijoStep armijo = armijo_step(phi, dir, problem_.contact.weights, options_.armijo_sigma,
                                          options_.max_armijo_halvings);
    res.armijo_reductions += armijo.halvings;
    ev.armijo = armijo.halvings;
    if (armijo.failed) {
      res.termination = Termination::LineSearchFailure;
      res.message = armijo_failure_message(options_.max_armijo_halvings, m, outer, gradient_norm);
      res.iterations = m;
      count_work();
      return res;
    }
    const double t = armijo.t;
    const bool full = t == 1.0;
    if (!full) d *= t;
    x += d;
    residual += t * dir.Ad;
    Nx = N * x;
    // ||G|| relative to the forces at play, so that the rule means the same in any units
    // (method.md section 7); the paper's absolute ||G|| < 1e-10 suits metres and MPa only.
    gradient_norm = relative_gradient(phi.gradient(residual, Nx).norm(), b_norm_, residual.norm());
    const double x_norm = x.norm();
    const double step = x_norm > 0.0 ? d.norm() / x_norm : d.norm();
    res.residual = std::max(gradient_norm, step);
    res.iterations = m;
    ev.residual = res.residual;
    if (options_.observer) options_.observer(ev);
    if (res.residual < options_.gnm_tolerance) {  // the paper's stopping rule
      count_work();
      return res;
    }
    previous = active;
    previous_full = full;
  }
  set_gnm_iteration_limit(res, options_, outer);
  count_work();
  return res;
}

}  // namespace signorini

#include "signorini/contact/generalized_newton.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "signorini/contact/armijo_rule.hpp"

namespace signorini {

double relative_gradient(double gradient_norm, double b_norm, double residual_norm) {
  const double force = std::max(b_norm, residual_norm);
  return force > 0.0 ? gradient_norm / force : gradient_norm;
}

namespace {
void stopped_by_callback(GnmResult& res, int m, int outer) {
  res.termination = Termination::StoppedByCallback;
  res.message =
      fmt::format("stopped by the callback after GNM iteration {} of Uzawa step {}", m, outer);
}
}  // namespace

GeneralizedNewton::GeneralizedNewton(const ContactSolverOptions& options, double b_norm,
                                     Index contact_nodes)
    : options_(options),
      b_norm_(b_norm),
      max_iterations_(gnm_iteration_limit(options, contact_nodes)) {}

GnmResult GeneralizedNewton::minimize(const ModifiedLagrangian& phi, NewtonSpace& space, int outer,
                                      double tolerance) const {
  GnmResult res;
  if (!(tolerance > 0.0)) tolerance = options_.gnm_tolerance;
  // Inexact Newton steps: a linear residual of a tenth of the tolerance leaves a gradient below
  // it (both are relative to the loads), so the stopping rule can still be met; and the
  // repeated active set after a full step still marks a minimiser to within that accuracy.
  const double linear_tolerance =
      options_.adaptive_inner_tolerance()
          ? std::max(options_.linear.cg_tolerance, kLinearForcing * tolerance)
          : 0.0;
  space.set_linear_tolerance(linear_tolerance);
  const int factorizations_before = space.factorizations();
  const int updates_before = space.factor_updates();
  auto finish = [&] {
    res.factorizations = space.factorizations() - factorizations_before;
    res.factor_updates = space.factor_updates() - updates_before;
    return res;
  };
  Linearization previous;      // linearisation that defined the previous Newton step
  bool previous_full = false;  // previous step was a full Newton step (no Armijo cut)
  double gradient_norm = std::numeric_limits<double>::infinity();

  for (int m = 1; m <= max_iterations_; ++m) {
    // The active set (with friction also each node's derivative of P, method.md "Friction").
    Linearization active = phi.linearize(space.contact_values());
    IterationEvent ev{
        IterationEvent::Kind::Inner, outer, m, count_active(active.active), 0.0, 0, 0};

    // The active set repeats after a full Newton step: x minimises the quadratic piece that is
    // active at x, so it is the minimiser of Phi and this Newton step would return x itself
    // (method.md section 4: "the active set repeating at two successive steps"). It is counted as
    // an iteration, as the paper does, but costs no linear solve.
    if (m > 1 && previous_full && active == previous) {
      res.iterations = m;
      res.residual = gradient_norm;
      ev.residual = res.residual;
      if (notify(options_, ev)) stopped_by_callback(res, m, outer);
      return finish();
    }

    // H(x_{m-1}) = A + r sum_{active} h_j nu_j nu_j^T, then H x_m = b - N^T (h (l - r g))_active.
    // The first Newton system with no node active (Uzawa's first step, from l = 0) is the
    // problem without contact: its answer only tells which nodes it pushes through the
    // obstacle, the next active set, and is solved to kFirstNewtonTolerance (inexact steps only).
    // Not a minimiser, so a repeat of its set does not end GNM (previous_full below).
    space.set_linearization(active, phi.r());
    const bool loose = linear_tolerance > 0.0 && linear_tolerance < kFirstNewtonTolerance &&
                       m == 1 && ev.active == 0;
    if (loose) space.set_linear_tolerance(kFirstNewtonTolerance);
    const NewtonSolveStats stats = space.solve(phi.newton_contact_terms(active));
    if (loose) space.set_linear_tolerance(linear_tolerance);
    res.linear_iterations += stats.iterations;
    ev.linear_iterations = stats.iterations;
    if (!stats.converged) {
      res.termination = Termination::LinearSolverFailure;
      res.message = fmt::format(
          "{} did not converge in GNM iteration {} of Uzawa step {} ({} iterations, relative "
          "residual {:.3e}{})",
          stats.solver, m, outer, stats.iterations, stats.residual,
          stats.tolerance > 0.0 ? fmt::format(", tolerance {:.1e}", stats.tolerance) : "");
      res.iterations = m;
      return finish();
    }

    // Armijo rule when the Newton point does not decrease Phi (method.md section 4).
    ModifiedLagrangian::Direction dir;
    space.direction(dir);
    dir.z = phi.shifted_multipliers(space.contact_values());
    const ArmijoStep armijo =
        armijo_step(phi, dir, options_.armijo_sigma, options_.max_armijo_halvings);
    res.armijo_reductions += armijo.halvings;
    ev.armijo = armijo.halvings;
    if (armijo.failed) {
      res.termination = Termination::LineSearchFailure;
      res.message = armijo_failure_message(options_.max_armijo_halvings, m, outer, gradient_norm);
      res.iterations = m;
      return finish();
    }
    const bool full = armijo.t == 1.0;
    space.step(armijo.t);
    // ||G|| relative to the forces at play, so that the rule means the same in any units
    // (method.md section 7); the paper's absolute ||G|| < 1e-10 suits metres and MPa only.
    const NewtonStepNorms n = space.norms(phi.contact_forces(space.contact_values()));
    gradient_norm = relative_gradient(n.gradient, b_norm_, n.residual);
    const double step = n.x > 0.0 ? n.step / n.x : n.step;
    res.residual = std::max(gradient_norm, step);
    res.iterations = m;
    ev.residual = res.residual;
    if (notify(options_, ev)) {
      stopped_by_callback(res, m, outer);
      return finish();
    }
    if (res.residual < tolerance) return finish();  // the paper's stopping rule
    previous = std::move(active);
    previous_full = full && !loose;
  }
  res.termination = Termination::IterationLimit;
  res.message = fmt::format(
      "GNM did not converge in {} iterations at Uzawa step {} (residual {:.3e}, tolerance {:.1e})",
      max_iterations_, outer, res.residual, tolerance);
  return finish();
}

}  // namespace signorini

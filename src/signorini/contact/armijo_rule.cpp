#include "signorini/contact/armijo_rule.hpp"

#include <fmt/format.h>

namespace signorini {

std::string armijo_failure_message(int max_halvings, int m, int k, double gradient_norm) {
  return fmt::format(
      "Armijo rule found no decrease after {} halvings in GNM iteration {} of Uzawa step {} "
      "(relative ||G|| = {:.3e})",
      max_halvings, m, k, gradient_norm);
}

ArmijoStep armijo_step(const ModifiedLagrangian& phi, const ModifiedLagrangian::Direction& dir,
                       double sigma, int max_halvings) {
  ArmijoStep step;
  // The change of Phi is evaluated without cancellation (method.md section 4, numerical note).
  if (phi.phi_change(dir, 1.0) < 0.0) return step;
  const Vector hz = phi.forces_of(dir.z);                    // h P(z)
  const double slope = dir.residual_dot_d + hz.dot(dir.Nd);  // <G(x), d>
  if (slope >= 0.0) return step;  // d is round-off around a minimiser: take it as it is
  double alpha = 1.0;
  do {
    alpha *= 0.5;
    ++step.halvings;
    if (step.halvings > max_halvings) {  // the halvings tried were max_halvings
      step.halvings = max_halvings;
      step.failed = true;
      return step;
    }
  } while (phi.phi_change(dir, alpha) > sigma * alpha * slope);
  step.t = alpha;
  return step;
}

}  // namespace signorini

#pragma once
// The step length of a GNM iteration (method.md section 4): the full Newton step when it
// decreases Phi, otherwise the Armijo rule Phi(x + a d) <= Phi(x) + sigma a <G(x), d>,
// a = 1/2, 1/4, ... Shared by the GNM of the host paths and of the backend path.

#include <string>

#include "signorini/contact/modified_lagrangian.hpp"

namespace signorini {

struct ArmijoStep {
  double t = 1.0;       ///< step length along d
  int halvings = 0;     ///< halvings made
  bool failed = false;  ///< no decrease within max_halvings
};

/// `dir` describes d at x (ModifiedLagrangian::direction).
ArmijoStep armijo_step(const ModifiedLagrangian& phi, const ModifiedLagrangian::Direction& dir,
                       double sigma, int max_halvings);

/// The one-line message of a failed Armijo rule in GNM iteration m of Uzawa step k.
std::string armijo_failure_message(int max_halvings, int m, int k, double gradient_norm);

}  // namespace signorini

#include "signorini/contact/solve_summary.hpp"

#include <fmt/format.h>

#include <algorithm>

namespace signorini {

double KktResiduals::max() const {
  return std::max({equilibrium, penetration, sign, complementarity, friction_bound, slip});
}

std::vector<int> SolveSummary::inner_iterations() const {
  std::vector<int> out;
  out.reserve(steps.size());
  for (const auto& s : steps) out.push_back(s.inner_iterations);
  return out;
}

std::string SolveSummary::brief_report() const {
  std::string s = fmt::format("{}: {} after {} outer iteration(s)\n",
                              enum_to_string(kContactMethodNames, method),
                              enum_to_string(kTerminationNames, termination), outer_iterations);
  if (!message.empty()) s += "  " + message + "\n";
  s += fmt::format("  M(u,l) = {:.10e}   J(u) = {:.10e} (1/2 x.Ax - b.x, free unknowns x)\n",
                   lagrangian, energy);
  s += fmt::format("  active contact nodes {}, contact force {:.10e}\n", num_active, contact_force);
  s += fmt::format(
      "  KKT (relative): equilibrium {:.2e}, penetration {:.2e}, sign {:.2e}, "
      "complementarity {:.2e} (tolerance {:.0e})\n",
      kkt.equilibrium, kkt.penetration, kkt.sign, kkt.complementarity, kkt_tolerance);
  if (kkt.friction_bound > 0.0 || kkt.slip > 0.0)
    s += fmt::format("  friction (relative): bound {:.2e}, slip direction {:.2e}\n",
                     kkt.friction_bound, kkt.slip);
  if (method == ContactMethod::UzawaGnm)
    s += fmt::format("  r = {:.4g} ({})\n", r, r_automatic ? "automatic" : "given");
  s += fmt::format("  path: {}{}{}\n", enum_to_string(kSolvePathNames, path),
                   threads > 1 ? fmt::format(", {} threads", threads) : "",
                   path_reason.empty() ? "" : " (" + path_reason + ")");
  return s;
}

}  // namespace signorini

#include "signorini/contact/active_set_update.hpp"

#include <algorithm>

namespace signorini {

ActiveSet next_active_set(const ContactSet& contact, const ActiveSet& S, const Vector& l,
                          const Vector& gap_residual) {
  const Index nc = contact.size();
  const double l_tol = l.size() > 0 ? 1e-13 * l.cwiseAbs().maxCoeff() : 0.0;
  const double g_tol =
      1e-13 * std::max(gap_residual.size() > 0 ? gap_residual.cwiseAbs().maxCoeff() : 0.0,
                       contact.gaps.size() > 0 ? contact.gaps.cwiseAbs().maxCoeff() : 0.0);
  ActiveSet next(static_cast<std::size_t>(nc), false);
  for (Index j = 0; j < nc; ++j) {
    if (!contact.movable[static_cast<std::size_t>(j)]) continue;
    next[static_cast<std::size_t>(j)] =
        S[static_cast<std::size_t>(j)] ? l(j) > -l_tol : gap_residual(j) > g_tol;
  }
  return next;
}

}  // namespace signorini

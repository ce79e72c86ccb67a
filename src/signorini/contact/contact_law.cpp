#include "signorini/contact/contact_law.hpp"

#include <algorithm>
#include <cmath>

namespace signorini {

Vector UnilateralContactLaw::project(const Vector& z) const {
  Vector p(z.size());
  for (Index j = 0; j < z.size(); ++j) p(j) = std::isfinite(z(j)) ? std::max(z(j), 0.0) : 0.0;
  return p;
}

ActiveSet UnilateralContactLaw::active_set(const Vector& z) const {
  ActiveSet a(static_cast<std::size_t>(z.size()));
  for (Index j = 0; j < z.size(); ++j) a[static_cast<std::size_t>(j)] = z(j) > 0.0;
  return a;
}

double UnilateralContactLaw::penalty_change(double z0, double dz) const {
  const double z1 = z0 + dz;
  if (z0 > 0.0 && z1 > 0.0) return dz * (z0 + z1);  // difference of squares, no cancellation
  const double p0 = std::max(z0, 0.0), p1 = std::max(z1, 0.0);
  return p1 * p1 - p0 * p0;
}

const ContactLaw& unilateral_contact_law() {
  static const UnilateralContactLaw law;
  return law;
}

}  // namespace signorini

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

NodeProjection ContactLaw::project_node(Index /*j*/, const Eigen::VectorXd& zj) const {
  // A law of one component: P(z) = project(z), D = the active set's 0 or 1.
  NodeProjection p;
  p.force = project(zj);
  p.in_contact = active_set(zj)[0];
  p.derivative = Eigen::MatrixXd::Constant(1, 1, p.in_contact ? 1.0 : 0.0);
  return p;
}

LawViolations ContactLaw::violations(const Vector& l, const Vector& rows,
                                     const std::vector<bool>& movable) const {
  // One component per node: l_j >= 0, (N u - g)_j <= 0, l_j (N u - g)_j = 0.
  LawViolations v;
  for (Index j = 0; j < l.size(); ++j) {
    if (!movable[static_cast<std::size_t>(j)]) continue;
    v.penetration = std::max(v.penetration, rows(j));
    v.sign = std::max(v.sign, -l(j));
    v.complementarity = std::max(v.complementarity, std::abs(l(j) * rows(j)));
  }
  return v;
}

const ContactLaw& unilateral_contact_law() {
  static const UnilateralContactLaw law;
  return law;
}

}  // namespace signorini

#include "signorini/contact/contact_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/core/error.hpp"

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
  // The normal row of each node (the first of its components() rows): l_n >= 0,
  // (N u - g)_n <= 0, l_n (N u - g)_n = 0.
  const Index m = components();
  LawViolations v;
  for (Index j = 0; j < l.size() / m; ++j) {
    if (!movable[static_cast<std::size_t>(j)]) continue;
    const double ln = l(m * j), gap = rows(m * j);
    v.penetration = std::max(v.penetration, gap);
    v.sign = std::max(v.sign, -ln);
    v.complementarity = std::max(v.complementarity, std::abs(ln * gap));
  }
  return v;
}

void require_law_fits(const ContactProblem& problem) {
  const ContactLaw& law = contact_law(problem);
  const ContactSet& c = problem.contact;
  if (c.components != law.components())
    throw InputError(fmt::format(
        "the contact law \"{}\" has {} value(s) per contact node, the contact set {} row(s) of "
        "N per node",
        law.name(), law.components(), c.components));
  if (law.nodes() >= 0 && law.nodes() != c.size())
    throw InputError(
        fmt::format("the contact law \"{}\" has parameters for {} nodes, the contact set {} nodes",
                    law.name(), law.nodes(), c.size()));
}

const ContactLaw& unilateral_contact_law() {
  static const UnilateralContactLaw law;
  return law;
}

}  // namespace signorini

#include "signorini/contact/kkt_residuals.hpp"

#include <algorithm>
#include <cmath>

#include "signorini/parallel/distributed_engine.hpp"

namespace signorini {

KktResiduals kkt_residuals(const ContactProblem& p, const Vector& u, const Vector& l) {
  const ContactSet& c = p.contact;
  KktResiduals k;
  const Vector reaction = c.N.transpose() * c.weights.cwiseProduct(l);
  const double b_norm = std::max(p.b.norm(), reaction.norm());
  k.equilibrium = b_norm > 0.0 ? (stiffness_product(p, u) - p.b + reaction).norm() / b_norm : 0.0;

  const Vector gap_residual = c.N * u - c.gaps;  // <= 0 where feasible
  const double length = std::max(u.lpNorm<Eigen::Infinity>(),
                                 c.gaps.size() > 0 ? c.gaps.lpNorm<Eigen::Infinity>() : 0.0);
  const double l_max = l.size() > 0 ? l.lpNorm<Eigen::Infinity>() : 0.0;
  double pen = 0.0, sign = 0.0, comp = 0.0;
  for (Index j = 0; j < c.size(); ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    pen = std::max(pen, gap_residual(j));
    sign = std::max(sign, -l(j));
    comp = std::max(comp, std::abs(l(j) * gap_residual(j)));
  }
  k.penetration = length > 0.0 ? pen / length : 0.0;
  k.sign = l_max > 0.0 ? sign / l_max : 0.0;
  k.complementarity = (l_max > 0.0 && length > 0.0) ? comp / (l_max * length) : 0.0;
  return k;
}

}  // namespace signorini

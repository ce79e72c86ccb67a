#include "signorini/contact/kkt_residuals.hpp"

#include <algorithm>
#include <cmath>

#include "signorini/contact/friction_law.hpp"
#include "signorini/core/error.hpp"
#include "signorini/parallel/distributed_engine.hpp"

namespace signorini {

namespace {

// ||A u - b + N^T W l|| / max(||b||, ||N^T W l||) (`weighted` = W l, one value per row of N:
// the contact set is whole on every rank). A partitioned problem sums its rows' squares over the
// ranks.
double equilibrium_residual(const ContactProblem& p, const Vector& u, const Vector& weighted) {
  const Vector reaction = held_contact_transpose_rows(p, weighted);  // this process's rows
  double sums[2] = {reaction.squaredNorm(),
                    (held_stiffness_rows(p, u) - p.b + reaction).squaredNorm()};
  sum_over_ranks(p, sums, 2);
  const double b_norm = std::max(load_norm(p), std::sqrt(sums[0]));
  if (!(b_norm > 0.0)) return 0.0;
  return std::sqrt(sums[1]) / b_norm;
}

// With friction: the rows of N per node (normal, tangents), the multipliers likewise.
KktResiduals frictional_kkt_residuals(const ContactProblem& p, const Vector& u, const Vector& l,
                                      const FrictionLaw& law) {
  const ContactSet& c = p.contact;
  const Index m = c.components, nc = c.size();
  KktResiduals k;
  k.equilibrium = equilibrium_residual(p, u, row_weights(c).cwiseProduct(l));
  const Vector rows = contact_rows(p, u) - row_offsets(c);  // gap residual, then slip v_j
  const double length = std::max(largest_displacement(p, u),
                                 c.gaps.size() > 0 ? c.gaps.lpNorm<Eigen::Infinity>() : 0.0);
  const double l_max = l.size() > 0 ? l.lpNorm<Eigen::Infinity>() : 0.0;
  const Vector bounds = law.slip_bounds(l);
  double pen = 0.0, sign = 0.0, comp = 0.0, bound = 0.0, slip = 0.0;
  for (Index j = 0; j < nc; ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    const double ln = l(m * j), gap = rows(m * j);
    pen = std::max(pen, gap);
    sign = std::max(sign, -ln);
    comp = std::max(comp, std::abs(ln * gap));
    const Eigen::VectorXd lt = l.segment(m * j + 1, m - 1), v = rows.segment(m * j + 1, m - 1);
    bound = std::max(bound, lt.norm() - bounds(j));
    slip = std::max(slip, bounds(j) * v.norm() - lt.dot(v));
  }
  k.penetration = length > 0.0 ? pen / length : 0.0;
  k.sign = l_max > 0.0 ? sign / l_max : 0.0;
  k.complementarity = (l_max > 0.0 && length > 0.0) ? comp / (l_max * length) : 0.0;
  k.friction_bound = l_max > 0.0 ? std::max(bound, 0.0) / l_max : 0.0;
  k.slip = (l_max > 0.0 && length > 0.0) ? std::max(slip, 0.0) / (l_max * length) : 0.0;
  return k;
}

}  // namespace

KktResiduals kkt_residuals(const ContactProblem& p, const Vector& u, const Vector& l,
                           const ContactLaw& law) {
  const ContactSet& c = p.contact;
  if (c.components > 1) {
    const auto* friction = dynamic_cast<const FrictionLaw*>(&law);
    if (friction == nullptr) throw InputError("KKT residuals: a frictional set needs its law");
    return frictional_kkt_residuals(p, u, l, *friction);
  }
  KktResiduals k;
  k.equilibrium = equilibrium_residual(p, u, c.weights.cwiseProduct(l));

  const Vector gap_residual = contact_rows(p, u) - c.gaps;  // <= 0 where feasible
  const double length = std::max(largest_displacement(p, u),
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

#include "signorini/contact/kkt_residuals.hpp"

#include <algorithm>
#include <cmath>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/interface/contact_set.hpp"

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

}  // namespace

KktResiduals kkt_residuals(const ContactProblem& p, const Vector& u, const Vector& l) {
  // The rows of N per node (the normal, then with friction the tangents), the multipliers
  // likewise; the law says which of its conditions l and N u - g^ violate (contact_law.hpp).
  const ContactSet& c = p.contact;
  KktResiduals k;
  k.equilibrium = equilibrium_residual(p, u, row_weights(c).cwiseProduct(l));
  const Vector rows = contact_rows(p, u) - row_offsets(c);  // the gap residual, then the slip
  const double length = std::max(largest_displacement(p, u),
                                 c.gaps.size() > 0 ? c.gaps.lpNorm<Eigen::Infinity>() : 0.0);
  const double l_max = l.size() > 0 ? l.lpNorm<Eigen::Infinity>() : 0.0;
  const LawViolations v = contact_law(p).violations(l, rows, c.movable);
  k.penetration = length > 0.0 ? v.penetration / length : 0.0;
  k.sign = l_max > 0.0 ? v.sign / l_max : 0.0;
  k.complementarity = (l_max > 0.0 && length > 0.0) ? v.complementarity / (l_max * length) : 0.0;
  k.friction_bound = l_max > 0.0 ? std::max(v.friction_bound, 0.0) / l_max : 0.0;  // (0: none)
  k.slip = (l_max > 0.0 && length > 0.0) ? std::max(v.slip, 0.0) / (l_max * length) : 0.0;
  return k;
}

}  // namespace signorini

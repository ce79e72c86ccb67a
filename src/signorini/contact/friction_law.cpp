#include "signorini/contact/friction_law.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "signorini/contact/friction_projection.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

FrictionLaw::FrictionLaw(FrictionKind kind, int dim, Vector bound)
    : FrictionLaw(dim, kind == FrictionKind::Tresca ? bound : Vector::Zero(bound.size()),
                  kind == FrictionKind::Coulomb ? bound : Vector::Zero(bound.size()), {kind}) {}

FrictionLaw::FrictionLaw(int dim, Vector slip_bound, Vector mu, std::vector<FrictionKind> kinds)
    : dim_(dim), s_(std::move(slip_bound)), mu_(std::move(mu)) {
  for (const FrictionKind k : kinds) (k == FrictionKind::Tresca ? tresca_ : coulomb_) = true;
  if (kinds.empty()) {
    tresca_ = s_.size() > 0 && s_.maxCoeff() > 0.0;
    coulomb_ = mu_.size() > 0 && mu_.maxCoeff() > 0.0;
  }
  if (dim_ != 2 && dim_ != 3) throw std::invalid_argument("FrictionLaw: dim must be 2 or 3");
  if (s_.size() != mu_.size())
    throw std::invalid_argument("FrictionLaw: one slip bound and one mu per node");
  for (Index j = 0; j < s_.size(); ++j)
    if (!std::isfinite(s_(j)) || !std::isfinite(mu_(j)) || s_(j) < 0.0 || mu_(j) < 0.0 ||
        (s_(j) > 0.0 && mu_(j) > 0.0))
      throw std::invalid_argument(
          "FrictionLaw: per node a finite slip bound >= 0 or a finite mu >= 0, not both");
}

std::string_view FrictionLaw::name() const {
  if (tresca_ && coulomb_) return "tresca and coulomb";
  return tresca_ ? "tresca" : "coulomb";
}

Vector FrictionLaw::slip_bounds(const Vector& l) const {
  Vector s = s_;
  for (Index j = 0; j < s.size(); ++j)
    if (mu_(j) > 0.0) s(j) += mu_(j) * std::max(l(dim_ * j), 0.0);
  return s;
}

Vector FrictionLaw::project(const Vector& z) const {
  Vector p = Vector::Zero(z.size());
  for (Index j = 0; j < s_.size(); ++j) {
    const Eigen::VectorXd zj = z.segment(dim_ * j, dim_);
    if (zj.allFinite()) p.segment(dim_ * j, dim_) = project_node(j, zj).force;
  }
  return p;
}

ActiveSet FrictionLaw::active_set(const Vector& z) const {
  ActiveSet a(static_cast<std::size_t>(s_.size()));
  for (Index j = 0; j < s_.size(); ++j) a[static_cast<std::size_t>(j)] = z(dim_ * j) > 0.0;
  return a;
}

double FrictionLaw::penalty_change(double /*z0*/, double /*dz*/) const {
  throw std::logic_error("FrictionLaw::penalty_change: a frictional law has no scalar penalty");
}

bool FrictionLaw::has_friction() const {
  return s_.size() > 0 && (s_.maxCoeff() > 0.0 || mu_.maxCoeff() > 0.0);
}

Vector FrictionLaw::step_project(const Vector& z, const Vector& bounds) const {
  // With the bound of step (i) (Coulomb's from l^k), node by node; a node that cannot move
  // (z = -infinity) gets 0.
  Vector p = Vector::Zero(z.size());
  for (Index j = 0; j < s_.size(); ++j) {
    const Eigen::VectorXd zj = z.segment(dim_ * j, dim_);
    if (zj.allFinite()) p.segment(dim_ * j, dim_) = project_tresca(zj, bounds(j)).force;
  }
  return p;
}

Linearization FrictionLaw::step_linearize(const Vector& z, const Vector& bounds,
                                          const std::vector<bool>& movable) const {
  // Step (i) minimises a Tresca Phi: Coulomb's bound is mu (l_n)_+ of the Uzawa step.
  const Index m = dim_, nc = s_.size();
  Linearization lin;
  lin.active.assign(static_cast<std::size_t>(nc), false);
  lin.blocks.assign(static_cast<std::size_t>(m * m * nc), 0.0);
  lin.offsets.assign(static_cast<std::size_t>(m * nc), 0.0);
  for (Index j = 0; j < nc; ++j) {
    if (!movable[static_cast<std::size_t>(j)]) continue;
    const Eigen::VectorXd zj = z.segment(m * j, m);
    const FrictionProjection pj = project_tresca(zj, bounds(j));
    lin.active[static_cast<std::size_t>(j)] = pj.in_contact;
    Eigen::Map<Eigen::MatrixXd>(&lin.blocks[static_cast<std::size_t>(m * m * j)], m, m) =
        pj.derivative;
    Eigen::Map<Eigen::VectorXd>(&lin.offsets[static_cast<std::size_t>(m * j)], m) =
        pj.force - pj.derivative * zj;
  }
  // In 2D each block is diag(0 or 1, 0 or 1): (s / |z_t|)(1 - t t) with t = +-1 vanishes
  // exactly. Then the rows of N with a 1 describe H as an active set does.
  lin.rows.assign(static_cast<std::size_t>(m * nc), false);
  for (Index j = 0; j < nc; ++j)
    for (Index a = 0; a < m; ++a)
      for (Index b = 0; b < m; ++b) {
        const double v = lin.blocks[static_cast<std::size_t>(m * m * j + a + m * b)];
        if (a == b && v == 1.0)
          lin.rows[static_cast<std::size_t>(m * j + a)] = true;
        else if (v != 0.0) {
          lin.rows.clear();
          return lin;
        }
      }
  return lin;
}

double FrictionLaw::potential_change(Index j, const double* z0, const double* dz,
                                     const Vector& bounds) const {
  const double s = bounds(j);
  // Normal part: (max(z_n, 0)^2) / 2, as the unilateral law's penalty change.
  double change = 0.5 * unilateral_contact_law().penalty_change(z0[0], dz[0]);
  // Tangential part: |z_t|^2 / 2 inside the ball of radius s, s |z_t| - s^2 / 2 outside.
  double n0 = 0.0, n1 = 0.0, dot = 0.0;
  for (Index a = 1; a < dim_; ++a) {
    n0 += z0[a] * z0[a];
    n1 += (z0[a] + dz[a]) * (z0[a] + dz[a]);
    dot += dz[a] * (2.0 * z0[a] + dz[a]);
  }
  n0 = std::sqrt(n0);
  n1 = std::sqrt(n1);
  if (n0 < s && n1 < s)
    change += 0.5 * dot;  // |z1|^2 - |z0|^2 = dz . (z0 + z1)
  else if (n0 >= s && n1 >= s) {
    // s (|z1| - |z0|) without cancellation; nothing where s = 0 (no tangential force).
    if (s > 0.0) change += s * dot / (n0 + n1);
  } else {
    const auto psi = [s](double n) { return n < s ? 0.5 * n * n : s * (n - 0.5 * s); };
    change += psi(n1) - psi(n0);
  }
  return change;
}

NodeProjection FrictionLaw::project_node(Index j, const Eigen::VectorXd& zj) const {
  return mu_(j) > 0.0 ? project_coulomb(zj, mu_(j)) : project_tresca(zj, s_(j));
}

LawViolations FrictionLaw::violations(const Vector& l, const Vector& rows,
                                      const std::vector<bool>& movable) const {
  // The normal conditions as every law's; then, rows m j + 1 .. being the slip v_j, the bound
  // |l_t| <= s_j and the slip's direction against the tangential force.
  LawViolations v = ContactLaw::violations(l, rows, movable);
  const Index m = dim_;
  const Vector bounds = slip_bounds(l);
  for (Index j = 0; j < s_.size(); ++j) {
    if (!movable[static_cast<std::size_t>(j)]) continue;
    const Eigen::VectorXd lt = l.segment(m * j + 1, m - 1), vt = rows.segment(m * j + 1, m - 1);
    v.friction_bound = std::max(v.friction_bound, lt.norm() - bounds(j));
    v.slip = std::max(v.slip, bounds(j) * vt.norm() - lt.dot(vt));
  }
  return v;
}

std::vector<FrictionState> friction_states(const ContactLaw& law, const Vector& pressure,
                                           const Matrix& tangential) {
  const Index nc = pressure.size();
  const Vector bound = law.slip_bounds(node_multipliers(pressure, tangential));
  std::vector<FrictionState> states(static_cast<std::size_t>(nc), FrictionState::Separated);
  for (Index j = 0; j < nc; ++j) {
    const double t = tangential.col(j).norm();
    if (!(pressure(j) > 0.0)) continue;  // (Tresca's traction there is no contact's)
    states[static_cast<std::size_t>(j)] =
        t >= bound(j) * (1.0 - 1e-6) ? FrictionState::Sliding : FrictionState::Sticking;
  }
  return states;
}

Index count_in_contact(const Vector& l, Index components) {
  Index n = 0;
  for (Index j = 0; j < l.size(); j += components) n += l(j) > 0.0 ? 1 : 0;
  return n;
}

Vector node_multipliers(const Vector& pressure, const Matrix& tangential) {
  const Index m = 1 + tangential.rows(), nc = pressure.size();
  Vector l(m * nc);
  for (Index j = 0; j < nc; ++j) {
    l(m * j) = pressure(j);
    l.segment(m * j + 1, m - 1) = tangential.col(j);
  }
  return l;
}

}  // namespace signorini

#include "signorini/contact/friction_law.hpp"

#include <fmt/format.h>

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
    if (!zj.allFinite()) continue;
    p.segment(dim_ * j, dim_) =
        mu_(j) > 0.0 ? project_coulomb(zj, mu_(j)).force : project_tresca(zj, s_(j)).force;
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

std::vector<FrictionState> friction_states(const FrictionLaw& law, const Vector& pressure,
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

void add_tangential_rows(ContactSet& contact, const SparseMatrix& T) {
  const Index nc = contact.size();
  if (contact.components != 1) throw InputError("friction: the contact set has tangential rows");
  if (nc == 0 || T.rows() % nc != 0 || T.cols() != contact.N.cols() || T.rows() / nc < 1 ||
      T.rows() / nc > 2)
    throw InputError(
        fmt::format("friction: T must have 1 or 2 rows per contact node ({} nodes) over the {} "
                    "free dofs, not {} x {}",
                    nc, contact.N.cols(), T.rows(), T.cols()));
  const Index d = 1 + T.rows() / nc;
  std::vector<Eigen::Triplet<double, Index>> entries;
  entries.reserve(static_cast<std::size_t>(contact.N.nonZeros() + T.nonZeros()));
  for (Index col = 0; col < T.cols(); ++col) {
    for (SparseMatrix::InnerIterator it(contact.N, col); it; ++it)
      entries.emplace_back(d * it.row(), col, it.value());
    for (SparseMatrix::InnerIterator it(T, col); it; ++it)
      entries.emplace_back(d * (it.row() / (d - 1)) + 1 + it.row() % (d - 1), col, it.value());
  }
  SparseMatrix B(d * nc, T.cols());
  B.setFromTriplets(entries.begin(), entries.end());
  contact.N = std::move(B);
  contact.components = static_cast<int>(d);
}

Vector row_offsets(const ContactSet& contact) {
  const Index m = contact.components, nc = contact.size();
  if (m == 1) return contact.gaps;
  Vector g = Vector::Zero(m * nc);
  const bool origin = contact.slip_origin.size() == (m - 1) * nc;
  for (Index j = 0; j < nc; ++j) {
    g(m * j) = contact.gaps(j);
    if (origin) g.segment(m * j + 1, m - 1) = contact.slip_origin.segment((m - 1) * j, m - 1);
  }
  return g;
}

Vector row_weights(const ContactSet& contact) {
  const Index m = contact.components;
  if (m == 1) return contact.weights;
  Vector h(m * contact.size());
  for (Index j = 0; j < contact.size(); ++j) h.segment(m * j, m).setConstant(contact.weights(j));
  return h;
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

SparseMatrix normal_rows(const ContactSet& contact) {
  const Index m = contact.components;
  if (m == 1) return contact.N;
  std::vector<Eigen::Triplet<double, Index>> entries;
  for (Index col = 0; col < contact.N.cols(); ++col)
    for (SparseMatrix::InnerIterator it(contact.N, col); it; ++it)
      if (it.row() % m == 0) entries.emplace_back(it.row() / m, col, it.value());
  SparseMatrix N(contact.size(), contact.N.cols());
  N.setFromTriplets(entries.begin(), entries.end());
  return N;
}

}  // namespace signorini

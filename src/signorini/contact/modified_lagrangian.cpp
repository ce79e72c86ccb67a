#include "signorini/contact/modified_lagrangian.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "signorini/contact/friction_projection.hpp"
#include "signorini/core/error.hpp"
#include "signorini/parallel/distributed_engine.hpp"

namespace signorini {

Index count_active(const ActiveSet& active) {
  return static_cast<Index>(std::count(active.begin(), active.end(), true));
}

namespace {
// Position of entry (row, col) in a compressed column-major matrix, or -1.
Index find_entry(const SparseMatrix& A, Index row, Index col) {
  const int* begin = A.innerIndexPtr() + A.outerIndexPtr()[col];
  const int* end = A.innerIndexPtr() + A.outerIndexPtr()[col + 1];
  const int* it = std::lower_bound(begin, end, static_cast<int>(row));
  if (it == end || *it != row) return -1;
  return it - A.innerIndexPtr();
}
}  // namespace

ModifiedLagrangian::ModifiedLagrangian(const ContactProblem& problem, double r,
                                       const ContactLaw& law)
    : p_(problem), r_(r), law_(law), m_(law.components()) {
  if (p_.contact.components != m_)
    throw InputError(fmt::format(
        "the contact law \"{}\" has {} component(s) per node, the contact set {} row(s) of N",
        law.name(), m_, p_.contact.components));
  if (m_ > 1) {
    friction_ = dynamic_cast<const FrictionLaw*>(&law);
    if (friction_ == nullptr || friction_->size() != p_.contact.size())
      throw InputError("a frictional contact set needs a FrictionLaw with one bound per node");
  }
  g_hat_ = row_offsets(p_.contact);
  h_ = row_weights(p_.contact);
  set_multipliers(Vector::Zero(m_ * p_.contact.size()));
}

// Made at the first hessian(): only the host's sparse Newton systems need it, not the backend
// path or the condensed problems' dense systems. Rows a and b of node j list its free dofs with
// the components of its normal (and tangents); N^T D N adds D_ab (N_a)_p (N_b)_q to the (p, q)
// entries of node j's block, which A has since the dofs of one node always couple.
const std::vector<std::vector<ModifiedLagrangian::BlockEntry>>& ModifiedLagrangian::node_entries()
    const {
  if (node_entries_ready_) return node_entries_;
  const SparseMatrix Nt = p_.contact.N.transpose();  // column i = row i of N
  node_entries_.resize(static_cast<std::size_t>(p_.contact.size()));
  for (Index j = 0; j < p_.contact.size(); ++j)
    for (Index a = 0; a < m_; ++a)
      for (Index b = 0; b < m_; ++b)
        for (SparseMatrix::InnerIterator ia(Nt, m_ * j + a); ia; ++ia)
          for (SparseMatrix::InnerIterator ib(Nt, m_ * j + b); ib; ++ib) {
            const Index pos = find_entry(p_.A, ia.row(), ib.row());
            if (pos < 0)
              throw NumericalError("contact node block missing from the stiffness pattern");
            node_entries_[static_cast<std::size_t>(j)].push_back(
                {pos, static_cast<int>(a + m_ * b), ia.value() * ib.value()});
          }
  node_entries_ready_ = true;
  return node_entries_;
}

void ModifiedLagrangian::set_multipliers(const Vector& l) {
  l_ = l;
  for (Index j = 0; j < p_.contact.size(); ++j)
    if (!p_.contact.movable[static_cast<std::size_t>(j)]) l_.segment(m_ * j, m_).setZero();
  if (friction_ != nullptr) bounds_ = friction_->slip_bounds(l_);  // Coulomb: mu (l_n)_+
}

Vector ModifiedLagrangian::shifted_multipliers(const Vector& Nx) const {
  Vector z = l_ + r_ * (Nx - g_hat_);
  for (Index j = 0; j < p_.contact.size(); ++j)
    if (!p_.contact.movable[static_cast<std::size_t>(j)])
      z.segment(m_ * j, m_).setConstant(-std::numeric_limits<double>::infinity());
  return z;
}

ActiveSet ModifiedLagrangian::active_set(const Vector& Nx) const {
  return law_.active_set(shifted_multipliers(Nx));
}

Linearization ModifiedLagrangian::linearize(const Vector& Nx) const {
  Linearization lin;
  if (friction_ == nullptr) {
    lin.active = active_set(Nx);
    return lin;
  }
  // Step (i) minimises a Tresca Phi: Coulomb's bound is mu (l_n)_+ of the Uzawa step.
  const Vector z = shifted_multipliers(Nx);
  const Index nc = p_.contact.size();
  lin.active.assign(static_cast<std::size_t>(nc), false);
  lin.blocks.assign(static_cast<std::size_t>(m_ * m_ * nc), 0.0);
  lin.offsets.assign(static_cast<std::size_t>(m_ * nc), 0.0);
  for (Index j = 0; j < nc; ++j) {
    if (!p_.contact.movable[static_cast<std::size_t>(j)]) continue;
    const Eigen::VectorXd zj = z.segment(m_ * j, m_);
    const FrictionProjection pj = project_tresca(zj, bounds_(j));
    lin.active[static_cast<std::size_t>(j)] = pj.in_contact;
    Eigen::Map<Eigen::MatrixXd>(&lin.blocks[static_cast<std::size_t>(m_ * m_ * j)], m_, m_) =
        pj.derivative;
    Eigen::Map<Eigen::VectorXd>(&lin.offsets[static_cast<std::size_t>(m_ * j)], m_) =
        pj.force - pj.derivative * zj;
  }
  // In 2D each block is diag(0 or 1, 0 or 1): (s / |z_t|)(1 - t t) with t = +-1 vanishes
  // exactly. Then the rows of N with a 1 describe H as an active set does.
  lin.rows.assign(static_cast<std::size_t>(m_ * nc), false);
  for (Index j = 0; j < nc; ++j)
    for (Index a = 0; a < m_; ++a)
      for (Index b = 0; b < m_; ++b) {
        const double v = lin.blocks[static_cast<std::size_t>(m_ * m_ * j + a + m_ * b)];
        if (a == b && v == 1.0)
          lin.rows[static_cast<std::size_t>(m_ * j + a)] = true;
        else if (v != 0.0) {
          lin.rows.clear();
          return lin;
        }
      }
  return lin;
}

Vector ModifiedLagrangian::project(const Vector& z) const {
  if (friction_ == nullptr) return law_.project(z);
  // With friction the projection with the bound of step (i) (Coulomb's from l^k), node by node;
  // a node that cannot move (z = -infinity) gets 0.
  Vector p = Vector::Zero(z.size());
  for (Index j = 0; j < p_.contact.size(); ++j) {
    const Eigen::VectorXd zj = z.segment(m_ * j, m_);
    if (zj.allFinite()) p.segment(m_ * j, m_) = project_tresca(zj, bounds_(j)).force;
  }
  return p;
}

Vector ModifiedLagrangian::forces_of(const Vector& z) const {
  return h_.cwiseProduct(project(z));
}

Vector ModifiedLagrangian::updated_multipliers(const Vector& Nx) const {
  // Step (ii): l^{k+1} = P(z), with friction the bound of step (i).
  return project(shifted_multipliers(Nx));
}

Vector ModifiedLagrangian::contact_forces(const Vector& Nx) const {
  return forces_of(shifted_multipliers(Nx));
}

double ModifiedLagrangian::potential_change(Index j, const double* z0, const double* dz) const {
  const double s = bounds_(j);
  // Normal part: (max(z_n, 0)^2) / 2, as the unilateral law's penalty change.
  double change = 0.5 * unilateral_contact_law().penalty_change(z0[0], dz[0]);
  // Tangential part: |z_t|^2 / 2 inside the ball of radius s, s |z_t| - s^2 / 2 outside.
  double n0 = 0.0, n1 = 0.0, dot = 0.0;
  for (Index a = 1; a < m_; ++a) {
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

Vector ModifiedLagrangian::gradient(const Vector& residual, const Vector& Nx) const {
  return residual + p_.contact.N.transpose() * contact_forces(Nx);
}

void ModifiedLagrangian::hessian(const ActiveSet& active, SparseMatrix& H) const {
  if (H.nonZeros() != p_.A.nonZeros()) H = p_.A;
  std::copy(p_.A.valuePtr(), p_.A.valuePtr() + p_.A.nonZeros(), H.valuePtr());
  double* v = H.valuePtr();
  for (std::size_t i = 0; i < active.size(); ++i) {
    if (!active[i]) continue;
    // Row i of N is row a of node i / m (friction in 2D: lin.rows): the (a, a) terms.
    const auto node = static_cast<Index>(i) / m_, a = static_cast<Index>(i) % m_;
    const double scale = r_ * p_.contact.weights(node);
    for (const BlockEntry& e : node_entries()[static_cast<std::size_t>(node)])
      if (e.ab == a * (m_ + 1)) v[e.pos] += scale * e.value;
  }
}

void ModifiedLagrangian::hessian(const Linearization& lin, SparseMatrix& H) const {
  if (friction_ == nullptr) {
    hessian(lin.active, H);
    return;
  }
  if (H.nonZeros() != p_.A.nonZeros()) H = p_.A;
  std::copy(p_.A.valuePtr(), p_.A.valuePtr() + p_.A.nonZeros(), H.valuePtr());
  double* v = H.valuePtr();
  // H = A + r sum_j h_j N_j^T D_j N_j: node j's d x d block gains r h_j (N_j^T D_j N_j). D_j is
  // symmetric for Tresca's projection (friction_projection.hpp), so H stays symmetric.
  for (Index j = 0; j < p_.contact.size(); ++j) {
    const double* D = &lin.blocks[static_cast<std::size_t>(m_ * m_ * j)];
    const double scale = r_ * p_.contact.weights(j);
    for (const BlockEntry& e : node_entries()[static_cast<std::size_t>(j)])
      if (D[e.ab] != 0.0) v[e.pos] += scale * D[e.ab] * e.value;
  }
}

Vector ModifiedLagrangian::newton_contact_terms(const Linearization& lin) const {
  if (friction_ == nullptr) return newton_contact_terms(lin.active);
  Vector w = Vector::Zero(l_.size());
  for (Index j = 0; j < p_.contact.size(); ++j) {
    const Eigen::Map<const Eigen::MatrixXd> D(&lin.blocks[static_cast<std::size_t>(m_ * m_ * j)],
                                              m_, m_);
    const Eigen::Map<const Eigen::VectorXd> c(&lin.offsets[static_cast<std::size_t>(m_ * j)], m_);
    w.segment(m_ * j, m_) = p_.contact.weights(j) *
                            (c + D * (l_.segment(m_ * j, m_) - r_ * g_hat_.segment(m_ * j, m_)));
  }
  return w;
}

Vector ModifiedLagrangian::newton_contact_terms(const ActiveSet& active) const {
  Vector w = Vector::Zero(l_.size());
  for (Index j = 0; j < w.size(); ++j)
    if (active[static_cast<std::size_t>(j)])
      w(j) = p_.contact.weights(j) * (l_(j) - r_ * p_.contact.gaps(j));
  return w;
}

Vector ModifiedLagrangian::newton_rhs(const ActiveSet& active) const {
  return p_.b - p_.contact.N.transpose() * newton_contact_terms(active);
}

ModifiedLagrangian::Direction ModifiedLagrangian::direction(const Vector& residual,
                                                            const Vector& Nx,
                                                            const Vector& d) const {
  Direction dir;
  dir.Ad = p_.A * d;
  dir.residual_dot_d = residual.dot(d);
  dir.d_A_d = dir.Ad.dot(d);
  dir.z = shifted_multipliers(Nx);
  dir.Nd = p_.contact.N * d;
  return dir;
}

double ModifiedLagrangian::phi_change(const Direction& dir, double t) const {
  double change = t * dir.residual_dot_d + 0.5 * t * t * dir.d_A_d;
  double penalty = 0.0;
  if (friction_ != nullptr) {
    std::vector<double> dz(static_cast<std::size_t>(m_));
    for (Index j = 0; j < p_.contact.size(); ++j) {
      if (!p_.contact.movable[static_cast<std::size_t>(j)]) continue;
      for (Index a = 0; a < m_; ++a) dz[static_cast<std::size_t>(a)] = t * r_ * dir.Nd(m_ * j + a);
      // 2 (psi(z1) - psi(z0)), as P(z1)^2 - P(z0)^2 is for the unilateral law.
      penalty += 2.0 * p_.contact.weights(j) * potential_change(j, &dir.z(m_ * j), dz.data());
    }
    return change + penalty / (2.0 * r_);
  }
  for (Index j = 0; j < dir.z.size(); ++j) {
    const double z0 = dir.z(j);
    if (!std::isfinite(z0)) continue;                                 // non-movable node: no term
    const double diff = law_.penalty_change(z0, t * r_ * dir.Nd(j));  // P(z1)^2 - P(z0)^2
    penalty += p_.contact.weights(j) * diff;
  }
  return change + penalty / (2.0 * r_);
}

double ModifiedLagrangian::value(const ContactProblem& p, double r, const Vector& u,
                                 const Vector& l, const ContactLaw& law) {
  const Vector Nu = contact_rows(p, u);  // (a collective call for a rank's part of the solution)
  double penalty = 0.0;
  if (law.components() > 1) {
    // psi(l + r (N u - g^)) - |l|^2 / 2 = psi(z) - psi(l) for admissible l.
    ModifiedLagrangian phi(p, r, law);
    phi.set_multipliers(l);
    const Vector shift = r * (Nu - phi.g_hat_);
    for (Index j = 0; j < p.contact.size(); ++j)
      if (p.contact.movable[static_cast<std::size_t>(j)])
        penalty += 2.0 * p.contact.weights(j) *
                   phi.potential_change(j, &phi.l_(phi.m_ * j), &shift(phi.m_ * j));
    return quadratic_energy(p, u) + penalty / (2.0 * r);
  }
  for (Index j = 0; j < l.size(); ++j) {
    if (!p.contact.movable[static_cast<std::size_t>(j)]) continue;
    // P(l + shift)^2 - P(l)^2 with P(l) = l (l >= 0): (z_+)^2 - l^2, without cancellation near
    // the solution.
    const double diff = law.penalty_change(l(j), r * (Nu(j) - p.contact.gaps(j)));
    penalty += p.contact.weights(j) * diff;
  }
  return quadratic_energy(p, u) + penalty / (2.0 * r);
}

}  // namespace signorini

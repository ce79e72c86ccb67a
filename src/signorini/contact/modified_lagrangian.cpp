#include "signorini/contact/modified_lagrangian.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"

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
  if (law.nodes() >= 0 && law.nodes() != p_.contact.size())
    throw InputError(
        fmt::format("the contact law \"{}\" has parameters for {} nodes, the contact "
                    "set {} nodes",
                    law.name(), law.nodes(), p_.contact.size()));
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
  parameters_ = law_.step_parameters(l_);  // Coulomb: the slip bounds mu (l_n)_+
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
  return law_.step_linearize(shifted_multipliers(Nx), parameters_, p_.contact.movable);
}

Vector ModifiedLagrangian::project(const Vector& z) const {
  // P(z) with what step (i) holds fixed (friction: Tresca's projection with the bound of l^k).
  return law_.step_project(z, parameters_);
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
  if (lin.blocks.empty()) {  // a law of one component: the active set says it all
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
  if (lin.blocks.empty()) return newton_contact_terms(lin.active);
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
  const double change = t * dir.residual_dot_d + 0.5 * t * t * dir.d_A_d;
  return change + penalty_change(dir.z, t * r_ * dir.Nd) / (2.0 * r_);
}

double ModifiedLagrangian::penalty_change(const Vector& z0, const Vector& dz) const {
  // sum_j h_j (2 psi(z0_j + dz_j) - 2 psi(z0_j)): P(z1)^2 - P(z0)^2 for one component.
  double penalty = 0.0;
  for (Index j = 0; j < p_.contact.size(); ++j) {
    if (!p_.contact.movable[static_cast<std::size_t>(j)] || !std::isfinite(z0(m_ * j))) continue;
    penalty += 2.0 * p_.contact.weights(j) *
               law_.potential_change(j, &z0(m_ * j), &dz(m_ * j), parameters_);
  }
  return penalty;
}

double ModifiedLagrangian::value(const ContactProblem& p, double r, const Vector& u,
                                 const Vector& l, const ContactLaw& law) {
  // The penalty term psi(l + r (N u - g^)) - |l|^2 / 2 = psi(z) - psi(l) for admissible l.
  const Vector Nu = contact_rows(p, u);  // (a collective call for a rank's part of the solution)
  ModifiedLagrangian phi(p, r, law);
  phi.set_multipliers(l);
  const Vector shift = r * (Nu - phi.g_hat_);
  return quadratic_energy(p, u) + phi.penalty_change(phi.l_, shift) / (2.0 * r);
}

}  // namespace signorini

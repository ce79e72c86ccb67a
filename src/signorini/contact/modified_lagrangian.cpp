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

ModifiedLagrangian::ModifiedLagrangian(const ContactProblem& problem, double r)
    : p_(problem), r_(r), law_(contact_law(problem)), m_(law_.components()) {
  require_law_fits(p_);
  g_hat_ = row_offsets(p_.contact);
  h_ = row_weights(p_.contact);
  set_multipliers(Vector::Zero(m_ * p_.contact.size()));
}

namespace {
// The free dofs that the rows of each contact node touch (all m of them), increasing.
std::vector<std::vector<Index>> node_dofs(const ContactSet& c, Index m) {
  const SparseMatrix Nt = c.N.transpose();  // column i = row i of N
  std::vector<std::vector<Index>> dofs(static_cast<std::size_t>(c.size()));
  for (Index j = 0; j < c.size(); ++j) {
    auto& d = dofs[static_cast<std::size_t>(j)];
    for (Index a = 0; a < m; ++a)
      for (SparseMatrix::InnerIterator it(Nt, m * j + a); it; ++it) d.push_back(it.row());
    std::sort(d.begin(), d.end());
    d.erase(std::unique(d.begin(), d.end()), d.end());
  }
  return dofs;
}
}  // namespace

// N^T D N adds to H the pairs of dofs that one contact node's rows touch (method.md, the
// generalised Hessian of (17)). Against an obstacle these are the node's own dofs, which A
// couples: H has A's pattern. A row between two bodies also touches the partner's dofs, which A
// does not couple with the node's: those pairs are added, once, as explicit zeros.
const SparseMatrix& ModifiedLagrangian::hessian_pattern() const {
  if (pattern_ready_) return pattern_.nonZeros() == 0 ? p_.A : pattern_;
  const std::vector<std::vector<Index>> dofs = node_dofs(p_.contact, m_);
  std::vector<Eigen::Triplet<double, int>> missing;
  for (const auto& d : dofs)
    for (const Index p : d)
      for (const Index q : d)
        if (find_entry(p_.A, p, q) < 0)
          missing.emplace_back(static_cast<int>(p), static_cast<int>(q), 0.0);
  pattern_ready_ = true;
  if (missing.empty()) return p_.A;
  std::vector<Eigen::Triplet<double, int>> entries = std::move(missing);
  for (Index col = 0; col < p_.A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(p_.A, col); it; ++it)
      entries.emplace_back(static_cast<int>(it.row()), static_cast<int>(col), it.value());
  pattern_.resize(p_.A.rows(), p_.A.cols());
  pattern_.setFromTriplets(entries.begin(), entries.end());  // (explicit zeros are kept)
  pattern_.makeCompressed();
  a_positions_.reserve(static_cast<std::size_t>(p_.A.nonZeros()));
  for (Index col = 0; col < p_.A.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(p_.A, col); it; ++it)
      a_positions_.push_back(find_entry(pattern_, it.row(), col));
  return pattern_;
}

void ModifiedLagrangian::start_hessian(SparseMatrix& H) const {
  const SparseMatrix& pattern = hessian_pattern();
  if (H.nonZeros() != pattern.nonZeros()) H = pattern;
  if (a_positions_.empty()) {
    std::copy(p_.A.valuePtr(), p_.A.valuePtr() + p_.A.nonZeros(), H.valuePtr());
    return;
  }
  double* v = H.valuePtr();
  std::fill(v, v + H.nonZeros(), 0.0);
  for (std::size_t k = 0; k < a_positions_.size(); ++k) v[a_positions_[k]] = p_.A.valuePtr()[k];
}

// Made at the first hessian(): only the host's sparse Newton systems need it, not the backend
// path or the condensed problems' dense systems. Rows a and b of node j list the free dofs they
// touch with their coefficients (the components of its normal and tangents, and between bodies
// the partner's weights); N^T D N adds D_ab (N_a)_p (N_b)_q to the (p, q) entries of node j's
// block, which hessian_pattern() has.
const std::vector<std::vector<ModifiedLagrangian::BlockEntry>>& ModifiedLagrangian::node_entries()
    const {
  if (node_entries_ready_) return node_entries_;
  const SparseMatrix& H = hessian_pattern();
  const SparseMatrix Nt = p_.contact.N.transpose();  // column i = row i of N
  node_entries_.resize(static_cast<std::size_t>(p_.contact.size()));
  for (Index j = 0; j < p_.contact.size(); ++j)
    for (Index a = 0; a < m_; ++a)
      for (Index b = 0; b < m_; ++b)
        for (SparseMatrix::InnerIterator ia(Nt, m_ * j + a); ia; ++ia)
          for (SparseMatrix::InnerIterator ib(Nt, m_ * j + b); ib; ++ib) {
            const Index pos = find_entry(H, ia.row(), ib.row());
            if (pos < 0)
              throw NumericalError("contact node block missing from the Hessian's pattern");
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
  start_hessian(H);
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
  start_hessian(H);
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
                                 const Vector& l) {
  // The penalty term psi(l + r (N u - g^)) - |l|^2 / 2 = psi(z) - psi(l) for admissible l.
  const Vector Nu = contact_rows(p, u);  // (a collective call for a rank's part of the solution)
  ModifiedLagrangian phi(p, r);
  phi.set_multipliers(l);
  const Vector shift = r * (Nu - phi.g_hat_);
  return quadratic_energy(p, u) + phi.penalty_change(phi.l_, shift) / (2.0 * r);
}

}  // namespace signorini

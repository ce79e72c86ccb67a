#include "signorini/contact/modified_lagrangian.hpp"

#include <algorithm>
#include <limits>

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
    : p_(problem), r_(r), law_(law), l_(Vector::Zero(problem.contact.size())) {}

// Made at the first hessian(): only the host's sparse Newton systems need it, not the backend
// path or the condensed problems' dense systems.
const std::vector<std::vector<std::pair<Index, double>>>& ModifiedLagrangian::block_entries()
    const {
  if (block_entries_ready_) return block_entries_;
  const SparseMatrix& N = p_.contact.N;
  // Row j of N lists the free dofs of node j with the normal components; N^T diag N adds
  // nu_a nu_b to the (a, b) entries of node j's block, which A has since the dofs of one node
  // always couple.
  const SparseMatrix Nt = N.transpose();  // column j = row j of N
  block_entries_.resize(static_cast<std::size_t>(N.rows()));
  for (Index j = 0; j < N.rows(); ++j) {
    for (SparseMatrix::InnerIterator ia(Nt, j); ia; ++ia)
      for (SparseMatrix::InnerIterator ib(Nt, j); ib; ++ib) {
        const Index pos = find_entry(p_.A, ia.row(), ib.row());
        if (pos < 0) throw NumericalError("contact node block missing from the stiffness pattern");
        block_entries_[static_cast<std::size_t>(j)].emplace_back(pos, ia.value() * ib.value());
      }
  }
  block_entries_ready_ = true;
  return block_entries_;
}

void ModifiedLagrangian::set_multipliers(const Vector& l) {
  l_ = l;
  for (Index j = 0; j < l_.size(); ++j)
    if (!p_.contact.movable[static_cast<std::size_t>(j)]) l_(j) = 0.0;
}

Vector ModifiedLagrangian::shifted_multipliers(const Vector& Nx) const {
  Vector z = l_ + r_ * (Nx - p_.contact.gaps);
  for (Index j = 0; j < z.size(); ++j)
    if (!p_.contact.movable[static_cast<std::size_t>(j)])
      z(j) = -std::numeric_limits<double>::infinity();
  return z;
}

ActiveSet ModifiedLagrangian::active_set(const Vector& Nx) const {
  return law_.active_set(shifted_multipliers(Nx));
}

Vector ModifiedLagrangian::updated_multipliers(const Vector& Nx) const {
  return law_.project(shifted_multipliers(Nx));
}

Vector ModifiedLagrangian::contact_forces(const Vector& Nx) const {
  return p_.contact.weights.cwiseProduct(updated_multipliers(Nx));
}

Vector ModifiedLagrangian::gradient(const Vector& residual, const Vector& Nx) const {
  return residual + p_.contact.N.transpose() * contact_forces(Nx);
}

void ModifiedLagrangian::hessian(const ActiveSet& active, SparseMatrix& H) const {
  if (H.nonZeros() != p_.A.nonZeros()) H = p_.A;
  std::copy(p_.A.valuePtr(), p_.A.valuePtr() + p_.A.nonZeros(), H.valuePtr());
  double* v = H.valuePtr();
  for (std::size_t j = 0; j < active.size(); ++j) {
    if (!active[j]) continue;
    const double scale = r_ * p_.contact.weights(static_cast<Index>(j));
    for (const auto& [pos, c] : block_entries()[j]) v[pos] += scale * c;
  }
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
  const Vector Nu = p.contact.N * u;
  double penalty = 0.0;
  for (Index j = 0; j < l.size(); ++j) {
    if (!p.contact.movable[static_cast<std::size_t>(j)]) continue;
    // P(l + shift)^2 - P(l)^2 with P(l) = l (l >= 0): (z_+)^2 - l^2, without cancellation near
    // the solution.
    const double diff = law.penalty_change(l(j), r * (Nu(j) - p.contact.gaps(j)));
    penalty += p.contact.weights(j) * diff;
  }
  return 0.5 * u.dot(stiffness_product(p, u)) - p.b.dot(u) + penalty / (2.0 * r);
}

}  // namespace signorini

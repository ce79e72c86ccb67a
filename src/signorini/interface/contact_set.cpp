#include "signorini/interface/contact_set.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {

Index ContactSet::num_movable() const {
  return static_cast<Index>(std::count(movable.begin(), movable.end(), true));
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

#include "signorini/contact/normal_rotation.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/core/error.hpp"

namespace signorini {

Vector NormalRotation::to_rotated(const Vector& v) const {
  return identity() ? v : Vector(Q.transpose() * v);
}

Vector NormalRotation::from_rotated(const Vector& y) const {
  return identity() ? y : Vector(Q * y);
}

namespace {

// The node of the first movable row that touches a free dof of an earlier row of another node,
// or -1. (The rows of one node, with friction its normal and tangents, share its dofs by design.)
Index node_of_a_shared_dof(const ContactSet& c) {
  std::vector<Index> owner(static_cast<std::size_t>(c.N.cols()), -1);
  const SparseMatrix Nt = c.N.transpose();
  for (Index row = 0; row < Nt.outerSize(); ++row) {
    const Index j = row / c.components;
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    for (SparseMatrix::InnerIterator it(Nt, row); it; ++it) {
      if (it.value() == 0.0) continue;
      Index& o = owner[static_cast<std::size_t>(it.row())];
      if (o >= 0 && o != j) return c.nodes[static_cast<std::size_t>(j)];
      o = j;
    }
  }
  return -1;
}

}  // namespace

bool rows_share_dofs(const ContactSet& c) {
  return node_of_a_shared_dof(c) >= 0;
}

NormalRotation make_normal_rotation(const ContactSet& c, Index num_free) {
  if (const Index node = node_of_a_shared_dof(c);
      node >= 0 && c.kind == InterfaceKind::BetweenBodies)
    throw InputError(fmt::format(
        "the contact rows of node {} and of another node touch the same dofs (their partners' "
        "faces share a node): this method needs one normal displacement per node; use "
        "solver.method = \"uzawa_gnm\" (or \"classical_uzawa\"), which take any constraint rows",
        node));
  else if (node >= 0)
    throw InputError(fmt::format(
        "contact node {} is in two contact boundaries, each with its own normal: this method "
        "needs one normal displacement per node; use solver.method = \"uzawa_gnm\" (or "
        "\"classical_uzawa\"), which take any constraint rows",
        node));
  NormalRotation r;
  const Index nc = c.size();
  r.normal_dof.assign(static_cast<std::size_t>(nc), -1);
  r.scale = Vector::Zero(nc);
  std::vector<Eigen::Triplet<double, int>> qt;
  std::vector<bool> in_block(static_cast<std::size_t>(num_free), false);
  const SparseMatrix Nt = c.N.transpose();
  for (Index j = 0; j < nc; ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    std::vector<Index> dofs;
    std::vector<double> values;
    for (SparseMatrix::InnerIterator it(Nt, j); it; ++it)
      if (it.value() != 0.0) {
        dofs.push_back(it.row());
        values.push_back(it.value());
      }
    r.normal_dof[static_cast<std::size_t>(j)] = dofs.front();
    if (dofs.size() == 1) {
      r.scale(j) = values.front();
      continue;
    }
    const Eigen::Map<const Vector> coef(values.data(), static_cast<Index>(values.size()));
    r.scale(j) = coef.norm();
    Vector v = coef / r.scale(j);
    v(0) -= 1.0;  // Q_j = I - 2 v v^T / (v.v) maps e_1 to coef / |coef|
    const double vv = v.squaredNorm();
    for (std::size_t a = 0; a < dofs.size(); ++a) {
      in_block[static_cast<std::size_t>(dofs[a])] = true;
      for (std::size_t b = 0; b < dofs.size(); ++b) {
        const double q =
            (a == b ? 1.0 : 0.0) - 2.0 * v(static_cast<Index>(a)) * v(static_cast<Index>(b)) / vv;
        qt.emplace_back(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]), q);
      }
    }
    r.blocks.push_back(std::move(dofs));
  }
  if (!r.blocks.empty()) {
    for (Index i = 0; i < num_free; ++i)
      if (!in_block[static_cast<std::size_t>(i)])
        qt.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
    r.Q.resize(num_free, num_free);
    r.Q.setFromTriplets(qt.begin(), qt.end());
  }
  return r;
}

// Q^T A Q for the block-diagonal reflection Q (symmetric, so Q^T A Q = Q A Q), computed in place
// on a copy of A: the dofs of one node are consecutive and their columns share one row pattern in
// a nodal stiffness matrix, so each block mixes entries that already exist. Falls back to sparse
// products where that structure is missing.
SparseMatrix rotate_matrix(const SparseMatrix& A, const NormalRotation& rotation,
                           Index first_column) {
  if (rotation.identity()) return A;
  const SparseMatrix& Q = rotation.Q;
  const auto& blocks = rotation.blocks;
  // The columns held: [c0, c1) of the unknowns, column i of A at i - c0. Q is block diagonal by
  // nodes, so (Q^T A Q)'s columns there are Q^T A Q(held, held).
  const Index c0 = first_column, c1 = first_column + A.cols();
  const auto product = [&] {
    if (c0 == 0 && c1 == A.rows()) return SparseMatrix(Q * A * Q);
    return SparseMatrix(Q * A * SparseMatrix(Q.block(c0, c0, c1 - c0, c1 - c0)));
  };
  SparseMatrix R = A;
  R.makeCompressed();
  const int* outer = R.outerIndexPtr();
  const int* inner = R.innerIndexPtr();
  double* v = R.valuePtr();
  const Index n = R.rows();
  std::vector<Index> block_of(static_cast<std::size_t>(n), -1);
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const auto& d = blocks[b];
    for (std::size_t a = 0; a < d.size(); ++a) {
      if (d[a] != d.front() + static_cast<Index>(a)) return product();
      block_of[static_cast<std::size_t>(d[a])] = static_cast<Index>(b);
    }
    if (d.front() >= c1 || d.back() < c0) continue;  // another rank's node: its rows only
    if (d.front() < c0 || d.back() >= c1) return product();
    const Index f = d.front() - c0;
    const Index len = outer[f + 1] - outer[f];
    for (const Index col : d)
      if (outer[col - c0 + 1] - outer[col - c0] != len ||
          !std::equal(inner + outer[col - c0], inner + outer[col - c0 + 1], inner + outer[f]))
        return product();
  }
  auto q = [&](Index row, Index col) { return Q.coeff(row, col); };
  // Columns: R(:, d) <- R(:, d) Q_b.
  std::vector<double> tmp;
  for (const auto& d : blocks) {
    if (d.front() >= c1 || d.back() < c0) continue;  // (columns not held)
    const auto k = d.size();
    const Index len = outer[d.front() - c0 + 1] - outer[d.front() - c0];
    tmp.assign(k * static_cast<std::size_t>(len), 0.0);
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t c = 0; c < k; ++c) {
        const double qca = q(d[c], d[a]);
        if (qca == 0.0) continue;
        const double* src = v + outer[d[c] - c0];
        for (Index p = 0; p < len; ++p)
          tmp[a * static_cast<std::size_t>(len) + static_cast<std::size_t>(p)] += qca * src[p];
      }
    for (std::size_t a = 0; a < k; ++a)
      std::copy(tmp.begin() + static_cast<std::ptrdiff_t>(a * static_cast<std::size_t>(len)),
                tmp.begin() + static_cast<std::ptrdiff_t>((a + 1) * static_cast<std::size_t>(len)),
                v + outer[d[a] - c0]);
  }
  // Rows: R(d, :) <- Q_b R(d, :); in every column the rows of a block are consecutive entries.
  double buf[3];
  for (Index col = 0; col < R.cols(); ++col)
    for (int p = outer[col]; p < outer[col + 1];) {
      const Index b = block_of[static_cast<std::size_t>(inner[p])];
      if (b < 0) {
        ++p;
        continue;
      }
      const auto& d = blocks[static_cast<std::size_t>(b)];
      const auto k = static_cast<int>(d.size());
      if (inner[p] != d.front() || p + k > outer[col + 1] || inner[p + k - 1] != d.back())
        return product();
      for (int a = 0; a < k; ++a) {
        buf[a] = 0.0;
        for (int c = 0; c < k; ++c)
          buf[a] += q(d[static_cast<std::size_t>(a)], d[static_cast<std::size_t>(c)]) * v[p + c];
      }
      std::copy(buf, buf + k, v + p);
      p += k;
    }
  return R;
}

}  // namespace signorini

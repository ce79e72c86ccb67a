#include "signorini/contact/condensed_problem.hpp"

namespace signorini {

namespace {

// Q^T A Q for the block-diagonal reflection Q (symmetric, so Q^T A Q = Q A Q), computed in place
// on a copy of A: the dofs of one node are consecutive and their columns share one row pattern in
// a nodal stiffness matrix, so each block mixes entries that already exist. Falls back to sparse
// products where that structure is missing.
SparseMatrix rotate(const SparseMatrix& A, const SparseMatrix& Q,
                    const std::vector<std::vector<Index>>& blocks) {
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
      if (d[a] != d.front() + static_cast<Index>(a)) return SparseMatrix(Q * A * Q);
      block_of[static_cast<std::size_t>(d[a])] = static_cast<Index>(b);
    }
    const Index len = outer[d.front() + 1] - outer[d.front()];
    for (const Index col : d)
      if (outer[col + 1] - outer[col] != len ||
          !std::equal(inner + outer[col], inner + outer[col + 1], inner + outer[d.front()]))
        return SparseMatrix(Q * A * Q);
  }
  auto q = [&](Index row, Index col) { return Q.coeff(row, col); };
  // Columns: R(:, d) <- R(:, d) Q_b.
  std::vector<double> tmp;
  for (const auto& d : blocks) {
    const auto k = d.size();
    const Index len = outer[d.front() + 1] - outer[d.front()];
    tmp.assign(k * static_cast<std::size_t>(len), 0.0);
    for (std::size_t a = 0; a < k; ++a)
      for (std::size_t c = 0; c < k; ++c) {
        const double qca = q(d[c], d[a]);
        if (qca == 0.0) continue;
        const double* src = v + outer[d[c]];
        for (Index p = 0; p < len; ++p) tmp[a * static_cast<std::size_t>(len) + static_cast<std::size_t>(p)] += qca * src[p];
      }
    for (std::size_t a = 0; a < k; ++a)
      std::copy(tmp.begin() + static_cast<std::ptrdiff_t>(a * static_cast<std::size_t>(len)),
                tmp.begin() + static_cast<std::ptrdiff_t>((a + 1) * static_cast<std::size_t>(len)),
                v + outer[d[a]]);
  }
  // Rows: R(d, :) <- Q_b R(d, :); in every column the rows of a block are consecutive entries.
  double buf[3];
  for (Index col = 0; col < n; ++col)
    for (int p = outer[col]; p < outer[col + 1];) {
      const Index b = block_of[static_cast<std::size_t>(inner[p])];
      if (b < 0) {
        ++p;
        continue;
      }
      const auto& d = blocks[static_cast<std::size_t>(b)];
      const auto k = static_cast<int>(d.size());
      if (inner[p] != d.front() || p + k > outer[col + 1] || inner[p + k - 1] != d.back())
        return SparseMatrix(Q * A * Q);
      for (int a = 0; a < k; ++a) {
        buf[a] = 0.0;
        for (int c = 0; c < k; ++c) buf[a] += q(d[static_cast<std::size_t>(a)], d[static_cast<std::size_t>(c)]) * v[p + c];
      }
      std::copy(buf, buf + k, v + p);
      p += k;
    }
  return R;
}

}  // namespace

CondensedProblem::CondensedProblem(const ContactProblem& full) {
  const ContactSet& c = full.contact;
  const Index n = full.A.rows();
  const Index nc = c.size();
  Vector scale = Vector::Zero(nc);  // (N x)_j = scale_j * (normal unknown of j)
  Vector b_rotated;                 // Q^T b
  std::vector<std::vector<Index>> blocks;  // free dofs of each rotated contact node
  {
    ScopedTimer t(timings_, "condensation rotation");
    // Where nu_j has a single nonzero component over node j's free dofs (edges along the axes),
    // that dof is the normal unknown as it is, with the signed component as scale. Elsewhere a
    // Householder reflection on the node's free dofs, whose first column is nu_j restricted to
    // them and normalised (as in the semismooth Newton solver), makes y = Q^T x hold
    // (x . nu)_j / s_j in the first dof.
    std::vector<Eigen::Triplet<double, int>> qt;
    std::vector<bool> in_block(static_cast<std::size_t>(n), false);
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
      if (dofs.size() == 1) {
        scale(j) = values.front();
        normal_dofs_.push_back(dofs.front());
        continue;
      }
      const Eigen::Map<const Vector> coef(values.data(), static_cast<Index>(values.size()));
      scale(j) = coef.norm();
      Vector v = coef / scale(j);
      v(0) -= 1.0;
      const double vv = v.squaredNorm();
      for (std::size_t a = 0; a < dofs.size(); ++a) {
        in_block[static_cast<std::size_t>(dofs[a])] = true;
        for (std::size_t b = 0; b < dofs.size(); ++b) {
          const double q = (a == b ? 1.0 : 0.0) -
                           2.0 * v(static_cast<Index>(a)) * v(static_cast<Index>(b)) / vv;
          qt.emplace_back(static_cast<int>(dofs[a]), static_cast<int>(dofs[b]), q);
        }
      }
      normal_dofs_.push_back(dofs.front());
      blocks.push_back(std::move(dofs));
    }
    if (!blocks.empty()) {
      for (Index i = 0; i < n; ++i)
        if (!in_block[static_cast<std::size_t>(i)])
          qt.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
      Q_.resize(n, n);
      Q_.setFromTriplets(qt.begin(), qt.end());
      b_rotated = Q_.transpose() * full.b;
    } else {
      b_rotated = full.b;  // no rotation: Q = I, and A is used as it is (no copy)
    }
  }
  if (blocks.empty()) {
    schur_ = std::make_unique<SchurComplement>(full.A, normal_dofs_);
  } else {
    SparseMatrix A_rotated = [&] {
      ScopedTimer t(timings_, "condensation rotation");
      return rotate(full.A, Q_, blocks);
    }();
    schur_ = std::make_unique<SchurComplement>(std::move(A_rotated), normal_dofs_);
  }
  ScopedTimer t(timings_, "condensation setup");
  const auto nm = static_cast<Index>(normal_dofs_.size());
  // S as a sparse matrix with every entry stored, so that the generic solvers apply to it.
  const Eigen::MatrixXd& S = schur_->matrix();
  reduced_.A.resize(nm, nm);
  reduced_.A.reserve(Eigen::VectorXi::Constant(nm, static_cast<int>(nm)));
  for (Index col = 0; col < nm; ++col)
    for (Index row = 0; row < nm; ++row) reduced_.A.insert(row, col) = S(row, col);
  reduced_.A.makeCompressed();
  reduced_.b = schur_->condensed_load(b_rotated);

  ContactSet& rc = reduced_.contact;
  rc.nodes = c.nodes;
  rc.normals = c.normals;
  rc.weights = c.weights;
  rc.gaps = c.gaps;
  rc.movable = c.movable;
  std::vector<Eigen::Triplet<double, int>> nt;
  Index k = 0;
  for (Index j = 0; j < nc; ++j)
    if (c.movable[static_cast<std::size_t>(j)]) nt.emplace_back(static_cast<int>(j), static_cast<int>(k++), scale(j));
  rc.N.resize(nc, nm);
  rc.N.setFromTriplets(nt.begin(), nt.end());
}

Vector CondensedProblem::expand(const Vector& v) const {
  // A_r y = Q^T b + E (S v - g) has y_C = v and the interior solution y_I = A_II^-1 (b_I - A_IC v);
  // the forward substitution of Q^T b was done for g already.
  const Vector y = schur_->solve_with_condensed_forces(reduced_.A * v - reduced_.b);
  return Q_.rows() > 0 ? Vector(Q_ * y) : y;
}

TimingTable CondensedProblem::timings() const {
  TimingTable t = timings_;
  t.merge(schur_->timings());
  return t;
}

}  // namespace signorini

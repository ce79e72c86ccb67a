#include "signorini/contact/condensed_problem.hpp"

#include <algorithm>

#include "signorini/contact/normal_rotation.hpp"

namespace signorini {

CondensedProblem::CondensedProblem(const ContactProblem& full, int threads) {
  // Two parts when two threads may run and the problem is large enough.
  const Index parts = SchurComplement::automatic_parts(full.A.rows(), threads);
  const ContactSet& c = full.contact;
  const Index nc = c.size();
  // With friction, or where a node has rows in two contact parts (a corner against two
  // obstacles, whose normals need not be along distinct axes), N's rows are kept as they are on
  // the contact nodes' dofs; otherwise each node's normal displacement becomes one unknown
  // (normal_rotation.hpp).
  const bool friction = c.components > 1;
  const bool general_rows = friction || rows_share_dofs(c);
  Vector b_rotated;
  if (general_rows) {
    // Every dof that a row of N touches: the contact nodes' free dofs, in their order.
    std::vector<char> touched(static_cast<std::size_t>(full.A.rows()), 0);
    for (Index k = 0; k < c.N.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(c.N, k); it; ++it)
        if (it.value() != 0.0) touched[static_cast<std::size_t>(it.col())] = 1;
    for (std::size_t i = 0; i < touched.size(); ++i)
      if (touched[i] != 0) kept_.push_back(static_cast<Index>(i));
    b_rotated = full.b;
  } else {
    ScopedTimer t(timings_, "condensation rotation");
    rotation_ = make_normal_rotation(c, full.A.rows());
    for (Index j = 0; j < nc; ++j)
      if (c.movable[static_cast<std::size_t>(j)])
        kept_.push_back(rotation_.normal_dof[static_cast<std::size_t>(j)]);
    b_rotated = rotation_.to_rotated(full.b);
  }
  if (rotation_.identity()) {
    schur_ = std::make_unique<SchurComplement>(full.A, kept_, parts);  // no copy of A
  } else {
    SparseMatrix A_rotated = [&] {
      ScopedTimer t(timings_, "condensation rotation");
      return rotate_matrix(full.A, rotation_);
    }();
    schur_ = std::make_unique<SchurComplement>(std::move(A_rotated), kept_, parts);
  }
  ScopedTimer t(timings_, "condensation setup");
  const auto nm = static_cast<Index>(kept_.size());
  // S itself, a dense matrix with every entry stored (dense_storage.hpp), so that the generic
  // methods apply to it and the dense Newton systems read it without a copy.
  reduced_.law = full.law;  // (the law acts on the same rows, in the nodes' frames)
  reduced_.A = schur_->release_matrix();
  reduced_.b = schur_->condensed_load(b_rotated);

  ContactSet& rc = reduced_.contact;
  rc.nodes = c.nodes;
  rc.normals = c.normals;
  rc.weights = c.weights;
  rc.gaps = c.gaps;
  rc.movable = c.movable;
  std::vector<Eigen::Triplet<double, int>> nt;
  if (general_rows) {
    // N's rows as they are, on the kept columns.
    rc.components = c.components;
    rc.slip_origin = c.slip_origin;
    std::vector<Index> column(static_cast<std::size_t>(full.A.rows()), -1);
    for (std::size_t k = 0; k < kept_.size(); ++k)
      column[static_cast<std::size_t>(kept_[k])] = static_cast<Index>(k);
    for (Index k = 0; k < c.N.outerSize(); ++k)
      for (SparseMatrix::InnerIterator it(c.N, k); it; ++it)
        if (it.value() != 0.0)
          nt.emplace_back(static_cast<int>(it.row()),
                          static_cast<int>(column[static_cast<std::size_t>(it.col())]), it.value());
    rc.N.resize(c.N.rows(), nm);
  } else {
    Index k = 0;
    for (Index j = 0; j < nc; ++j)
      if (c.movable[static_cast<std::size_t>(j)])
        nt.emplace_back(static_cast<int>(j), static_cast<int>(k++), rotation_.scale(j));
    rc.N.resize(nc, nm);
  }
  rc.N.setFromTriplets(nt.begin(), nt.end());
}

Vector CondensedProblem::expand(const Vector& v) const {
  // A_r y = Q^T b + E (S v - g) has y_C = v and the interior solution y_I = A_II^-1 (b_I - A_IC v);
  // the forward substitution of Q^T b was done for g already.
  const Vector y = schur_->solve_with_condensed_forces(reduced_.A * v - reduced_.b);
  return rotation_.from_rotated(y);
}

void CondensedProblem::set_load(const Vector& b) {
  ScopedTimer t(timings_, "condensation solve");
  reduced_.b = schur_->condensed_load(rotation_.to_rotated(b));
}

Vector CondensedProblem::condense(const Vector& u) const {
  const Vector y = rotation_.to_rotated(u);  // Q^T u: node j's normal displacement at normal_dofs_
  Vector v(static_cast<Index>(kept_.size()));
  for (std::size_t k = 0; k < kept_.size(); ++k) v(static_cast<Index>(k)) = y(kept_[k]);
  return v;
}

TimingTable CondensedProblem::timings() const {
  TimingTable t = timings_;
  t.merge(schur_->timings());
  return t;
}

}  // namespace signorini

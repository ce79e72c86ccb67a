#include "signorini/iterative/contact_prolongation.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

using Rows = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
using Triplets = std::vector<Eigen::Triplet<double, int>>;

// The rows of the column-major M whose slot is not -1, in the order of their slots (count x
// M.cols()): one pass over M's nonzeros.
Rows rows_of(const SparseMatrix& M, const std::vector<Index>& slot, Index count) {
  Triplets t;
  for (Index k = 0; k < M.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M, k); it; ++it) {
      const Index s = slot[static_cast<std::size_t>(it.row())];
      if (s >= 0) t.emplace_back(static_cast<int>(s), static_cast<int>(k), it.value());
    }
  Rows R(count, M.cols());
  R.setFromTriplets(t.begin(), t.end());
  return R;
}

}  // namespace

void keep_contact_rows(MultigridHierarchy& hierarchy, const SparseMatrix& N,
                       const std::vector<Index>& node_of_unknown) {
  if (hierarchy.tentatives.empty()) return;
  SparseMatrix& T = hierarchy.tentatives.front();
  if (T.nonZeros() == 0) return;
  if (N.cols() != T.rows() || static_cast<Index>(node_of_unknown.size()) != T.rows())
    throw NumericalError(
        fmt::format("contact prolongation: N has {} columns, T {} rows, {} node numbers", N.cols(),
                    T.rows(), node_of_unknown.size()));
  const Index nodes = node_of_unknown.empty()
                          ? 0
                          : *std::max_element(node_of_unknown.begin(), node_of_unknown.end()) + 1;
  std::vector<char> touched(static_cast<std::size_t>(nodes), 0);
  for (Index k = 0; k < N.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(N, k); it; ++it)
      if (it.value() != 0.0)
        touched[static_cast<std::size_t>(node_of_unknown[static_cast<std::size_t>(k)])] = 1;
  T.prune([&](Index row, Index, double) {
    return touched[static_cast<std::size_t>(node_of_unknown[static_cast<std::size_t>(row)])] != 0;
  });
  T.data().squeeze();
}

ContactProlongation::ContactProlongation(const SparseMatrix& A, const SparseMatrix& N,
                                         const SparseMatrix& P, const SparseMatrix& T, double omega)
    : ContactProlongation(
          [&] {
            if (A.rows() != P.rows() || A.cols() != P.rows())
              throw NumericalError(fmt::format("contact prolongation: A {}x{}, P {}x{}", A.rows(),
                                               A.cols(), P.rows(), P.cols()));
            // (Only the diagonal at N's unknowns is read: the others stay 0.)
            Vector d = Vector::Zero(A.rows());
            for (Index k = 0; k < N.outerSize(); ++k)
              if (N.col(k).nonZeros() > 0) d(k) = A.coeff(k, k);
            return d;
          }(),
          N, P, T, omega) {}

ContactProlongation::ContactProlongation(const Vector& diagonal_of_A, const SparseMatrix& N,
                                         const SparseMatrix& P, const SparseMatrix& T, double omega)
    : n_(P.rows()), m_(P.cols()), omega_(omega), Nt_(N.transpose()) {
  if (diagonal_of_A.size() != n_ || N.cols() != n_ || T.rows() != n_ || T.cols() != m_ ||
      !(omega > 0.0))
    throw NumericalError(fmt::format(
        "contact prolongation: {} diagonal entries, N {}x{}, P {}x{}, T {}x{}, omega {}",
        diagonal_of_A.size(), N.rows(), N.cols(), P.rows(), P.cols(), T.rows(), T.cols(), omega));
  slot_.assign(static_cast<std::size_t>(n_), -1);
  for (Index k = 0; k < N.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(N, k); it; ++it)
      if (it.value() != 0.0 && slot_[static_cast<std::size_t>(k)] < 0) {
        slot_[static_cast<std::size_t>(k)] = static_cast<Index>(unknown_.size());
        unknown_.push_back(k);
      }
  const auto count = static_cast<Index>(unknown_.size());
  diag_a_.resize(count);
  for (Index s = 0; s < count; ++s) {
    const Index k = unknown_[static_cast<std::size_t>(s)];
    diag_a_(s) = diagonal_of_A(k);
  }
  P_rows_ = rows_of(P, slot_, count);
  T_rows_ = rows_of(T, slot_, count);
  for (Index s = 0; s < count; ++s)
    if (T_rows_.outerIndexPtr()[s + 1] == T_rows_.outerIndexPtr()[s])
      throw NumericalError(fmt::format(
          "contact prolongation: the tentative prolongation has no row for unknown {}, which a "
          "contact row touches",
          unknown_[static_cast<std::size_t>(s)]));
}

SparseMatrix ContactProlongation::change(const Vector& c, const SparseMatrix* current) const {
  const SparseMatrix& Nt = current != nullptr ? *current : Nt_;
  if (c.size() != Nt.cols() || Nt.rows() != n_)
    throw NumericalError(fmt::format("contact prolongation: {} weights for {}x{} contact rows^T",
                                     c.size(), Nt.rows(), Nt.cols()));
  const auto count = static_cast<Index>(unknown_.size());
  // diag(E) and E T at the kept rows, E = N^T diag(c) N (the active rows), as N_Z^T (diag(c)
  // (N_Z T_Z)) with N_Z the active rows' entries at the kept unknowns: per row j its entries
  // times those of (N T)_j, a few aggregates' columns. Formed entry pair by entry pair instead
  // (sum_j c_j n_j n_j^T T), a coarse level's rows of some twenty entries cost their square:
  // 0.2 s of a refresh at a million unknowns on Hertz's ball.
  Vector diag_e = Vector::Zero(count);
  Triplets nz;
  for (Index j = 0; j < Nt.outerSize(); ++j) {
    if (!(c(j) > 0.0)) continue;
    for (SparseMatrix::InnerIterator a(Nt, j); a; ++a) {
      const Index sa = slot_[static_cast<std::size_t>(a.row())];
      if (sa < 0) continue;  // (a zero entry of N; see the header for another Nt)
      diag_e(sa) += c(j) * a.value() * a.value();
      nz.emplace_back(static_cast<int>(j), static_cast<int>(sa), a.value());
    }
  }
  Rows NZ(Nt.cols(), count);
  NZ.setFromTriplets(nz.begin(), nz.end());
  const Rows W = c.asDiagonal() * Rows(NZ * T_rows_);  // diag(c) N_Z T_Z
  const Rows ET = Rows(NZ.transpose()) * W;            // (E T)_Z
  // P_H,Z - P_Z = (1 - D_A / D_H) (T_Z - P_Z) - omega D_H^-1 (E T)_Z on the rows where E is not
  // zero (the header's derivation).
  Triplets d;
  for (Index s = 0; s < count; ++s) {
    if (diag_e(s) == 0.0) continue;
    const int row = static_cast<int>(unknown_[static_cast<std::size_t>(s)]);
    const double diag_h = diag_a_(s) + diag_e(s);
    const double keep = 1.0 - diag_a_(s) / diag_h;
    for (Rows::InnerIterator p(P_rows_, s); p; ++p)
      d.emplace_back(row, static_cast<int>(p.col()), -keep * p.value());
    for (Rows::InnerIterator t(T_rows_, s); t; ++t)
      d.emplace_back(row, static_cast<int>(t.col()), keep * t.value());
    for (Rows::InnerIterator e(ET, s); e; ++e)
      d.emplace_back(row, static_cast<int>(e.col()), -omega_ / diag_h * e.value());
  }
  SparseMatrix change(n_, m_);
  change.setFromTriplets(d.begin(), d.end());
  return change;
}

SparseMatrix ContactProlongation::carry(const SparseMatrix& D) const {
  if (D.cols() != n_)
    throw NumericalError(
        fmt::format("contact prolongation: rows of {} columns for {} unknowns", D.cols(), n_));
  // D's columns at the kept unknowns, as slots, times the kept rows of P.
  Triplets t;
  t.reserve(static_cast<std::size_t>(D.nonZeros()));
  for (Index k = 0; k < D.outerSize(); ++k) {
    const Index s = slot_[static_cast<std::size_t>(k)];
    if (s < 0) continue;
    for (SparseMatrix::InnerIterator it(D, k); it; ++it)
      t.emplace_back(static_cast<int>(it.row()), static_cast<int>(s), it.value());
  }
  Rows DZ(D.rows(), static_cast<Index>(unknown_.size()));
  DZ.setFromTriplets(t.begin(), t.end());
  return SparseMatrix(Rows(DZ * P_rows_));
}

}  // namespace signorini

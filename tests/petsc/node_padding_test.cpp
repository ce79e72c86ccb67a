// The unknowns of the PETSc path in whole node blocks (src/signorini/petsc/node_padding.hpp).

#include "signorini/petsc/node_padding.hpp"

#include <gtest/gtest.h>

namespace signorini::petsc {
namespace {

// Three nodes: node 7 with three free unknowns, node 3 on a roller with one, node 5 with two.
const std::vector<Index> kNodes = {7, 7, 7, 3, 5, 5};

SparseMatrix spd(Index n) {
  Matrix M = Matrix::Zero(n, n);
  for (Index i = 0; i < n; ++i)
    for (Index j = 0; j < n; ++j)
      M(i, j) = (i == j) ? 10.0 + static_cast<double>(i) : 1.0 / (1.0 + static_cast<double>(i + j));
  return M.sparseView();
}

TEST(NodePadding, GivesEachNodeAWholeBlock) {
  const NodePadding p(kNodes, 6);
  ASSERT_TRUE(p.active());
  EXPECT_EQ(p.block(), 3);
  EXPECT_EQ(p.size(), 9);
  const std::vector<Index> slots = {0, 1, 2, 3, 6, 7};
  for (Index i = 0; i < 6; ++i) EXPECT_EQ(p.slot(i), slots[static_cast<std::size_t>(i)]) << i;
  // A rank's range of unknowns [3, 6) (nodes 3 and 5) is the slots [3, 9).
  EXPECT_EQ(p.start(3), 3);
  EXPECT_EQ(p.start(6), 9);
}

TEST(NodePadding, MatrixHoldsAOnTheSlotsAndADiagonalOnThePadding) {
  const NodePadding p(kNodes, 6);
  const SparseMatrix A = spd(6);
  const Matrix P = Matrix(p.matrix(A, 0, 6));
  ASSERT_EQ(P.rows(), 9);
  for (Index i = 0; i < 6; ++i)
    for (Index j = 0; j < 6; ++j) EXPECT_EQ(P(p.slot(i), p.slot(j)), A.coeff(i, j)) << i << j;
  // Node 3's padding slots 4 and 5 and node 5's slot 8: the diagonal of the node's first unknown,
  // alone in their rows and columns.
  for (const auto& [s, d] : std::vector<std::pair<Index, double>>{
           {4, A.coeff(3, 3)}, {5, A.coeff(3, 3)}, {8, A.coeff(4, 4)}}) {
    EXPECT_EQ(P(s, s), d) << s;
    EXPECT_EQ(P.row(s).cwiseAbs().sum(), d) << s;
    EXPECT_EQ(P.col(s).cwiseAbs().sum(), d) << s;
  }
  // One rank's columns only: [3, 6) -> slots [3, 9), the others empty.
  const SparseMatrix part = p.matrix(A, 3, 6);
  for (Index s = 0; s < 9; ++s) {
    const Index entries = part.outerIndexPtr()[s + 1] - part.outerIndexPtr()[s];
    if (s < 3)
      EXPECT_EQ(entries, 0) << s;
    else
      EXPECT_GT(entries, 0) << s;
  }
  EXPECT_EQ(Matrix(part).rightCols(6), P.rightCols(6));
}

TEST(NodePadding, VectorsGoToTheSlotsAndBack) {
  const NodePadding p(kNodes, 6);
  const Vector v = Vector::LinSpaced(6, 1.0, 6.0);
  const Vector padded = p.rows(v, 0, 6);
  ASSERT_EQ(padded.size(), 9);
  EXPECT_EQ(padded(4), 0.0);
  EXPECT_EQ(padded(5), 0.0);
  EXPECT_EQ(padded(8), 0.0);
  EXPECT_EQ(p.unknowns(padded), v);
  const Matrix modes = Matrix::Ones(6, 2);
  EXPECT_EQ(p.rows(modes, 0, 6).colwise().sum(), Matrix::Constant(1, 2, 6.0));
  // One rank's rows [3, 6) (unknowns 3, 4, 5): slots [3, 9), their padding slots 4, 5 and 8.
  const Vector part = p.rows(Vector(v.segment(3, 3)), 3, 6);
  ASSERT_EQ(part.size(), 6);
  EXPECT_EQ(part, padded.segment(3, 6));
  const Matrix part_modes = p.rows(Matrix(modes.bottomRows(3)), 3, 6);
  ASSERT_EQ(part_modes.rows(), 6);
  EXPECT_EQ(part_modes.col(1), padded.segment(3, 6).cwiseSign());
}

TEST(NodePadding, LeavesWholeBlocksAlone) {
  const NodePadding whole({1, 1, 1, 4, 4, 4}, 6);
  EXPECT_FALSE(whole.active());
  EXPECT_EQ(whole.block(), 3);
  EXPECT_EQ(whole.slot(4), 4);
  const NodePadding unknown({}, 6);  // no node numbers: no blocks
  EXPECT_FALSE(unknown.active());
  EXPECT_EQ(unknown.block(), 1);
}

}  // namespace
}  // namespace signorini::petsc

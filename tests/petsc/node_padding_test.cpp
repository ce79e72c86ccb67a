// The unknowns of the PETSc path in whole node blocks (src/signorini/petsc/node_padding.hpp).

#include "signorini/petsc/node_padding.hpp"

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>

#include "signorini/core/error.hpp"

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
  // One rank's columns only: [3, 6) -> slots [3, 9), held as the result's 6 columns, from all
  // of A's columns or from a partitioned problem's A, which holds only the rank's (column i at
  // i - 3: ContactProblem::column_of).
  const SparseMatrix part = p.matrix(A, 3, 6);
  ASSERT_EQ(part.rows(), 9);
  ASSERT_EQ(part.cols(), 6);
  EXPECT_EQ(Matrix(part), P.rightCols(6));
  const SparseMatrix held_columns = A.rightCols(3);
  EXPECT_EQ(Matrix(p.matrix(held_columns, 3, 6)), P.rightCols(6));
  // Neither all columns nor the rank's: refused.
  EXPECT_THROW((void)p.matrix(SparseMatrix(A.rightCols(2)), 3, 6), NumericalError);
}

TEST(NodePadding, VectorsGoToTheSlotsAndBack) {
  const NodePadding p(kNodes, 6);
  const Vector v = Vector::LinSpaced(6, 1.0, 6.0);
  const Vector padded = p.rows(v, 0, 6);
  ASSERT_EQ(padded.size(), 9);
  EXPECT_EQ(padded(4), 0.0);
  EXPECT_EQ(padded(5), 0.0);
  EXPECT_EQ(padded(8), 0.0);
  EXPECT_EQ(p.own_unknowns(padded, 0, 6), v);
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

namespace signorini::petsc {
namespace {

// Each rank knowing only its own unknowns (the ranks' parts of the mesh): the same slots as the
// padding made from all of them, for its own unknowns and for the others' that it asks for, and
// its own unknowns back from its slots. On 1, 2 and 4 ranks, each rank a run of whole nodes.
TEST(NodePadding, EachRankKnowingItsOwnGetsTheWholeSlots) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  // Five nodes per rank: with 3, 1, 2, 3 and 2 free unknowns.
  std::vector<Index> nodes, starts{0};
  for (int r = 0; r < size; ++r) {
    for (Index k = 0; k < 5; ++k)
      for (Index c = 0; c < std::vector<Index>{3, 1, 2, 3, 2}[static_cast<std::size_t>(k)]; ++c)
        nodes.push_back(100 * r + k);
    starts.push_back(static_cast<Index>(nodes.size()));
  }
  const Index n = starts.back();
  const Index first = starts[static_cast<std::size_t>(rank)];
  const Index last = starts[static_cast<std::size_t>(rank) + 1];
  const NodePadding whole(nodes, n);
  std::vector<Index> ghosts;  // every other rank's first and last unknown
  for (int r = 0; r < size; ++r)
    if (r != rank) {
      ghosts.push_back(starts[static_cast<std::size_t>(r)]);
      ghosts.push_back(starts[static_cast<std::size_t>(r) + 1] - 1);
    }
  std::sort(ghosts.begin(), ghosts.end());
  const NodePadding own(std::vector<Index>(nodes.begin() + first, nodes.begin() + last), first,
                        last, n, ghosts, PETSC_COMM_WORLD);
  ASSERT_TRUE(own.active());
  EXPECT_EQ(own.block(), whole.block());
  EXPECT_EQ(own.size(), whole.size());
  EXPECT_EQ(own.start(first), whole.start(first));
  EXPECT_EQ(own.start(last), whole.start(last));
  for (Index i = first; i < last; ++i) EXPECT_EQ(own.slot(i), whole.slot(i)) << i;
  for (const Index g : ghosts) EXPECT_EQ(own.slot(g), whole.slot(g)) << g;
  const Vector values = Vector::LinSpaced(last - first, 1.0, 2.0);
  EXPECT_EQ(own.own_unknowns(own.rows(values, first, last), first, last), values);
}

}  // namespace
}  // namespace signorini::petsc

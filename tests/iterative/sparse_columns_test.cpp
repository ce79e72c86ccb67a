// The helpers of the products formed a group of columns at a time (sparse_columns.hpp): the rows
// of a matrix read by groups, and the columns whose rows repeat those of the one before (which
// the counting passes of the multigrid set-up skip).

#include "signorini/iterative/sparse_columns.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using RowMajor = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// A 3D prolongation: the six rigid-body modes of each aggregate share their rows.
SparseMatrix block_prolongation(const testing::ClampedBlock& block) {
  const AggregationLevel level =
      aggregate_level(block.A, block.modes, free_dof_nodes(block.dofs), {}, 0.0);
  return smoothed_prolongation(block.A, level.tentative, 0.5);
}

TEST(GroupRows, HoldEveryEntryOfTheMatrixOnce) {
  const testing::ClampedBlock block = testing::clamped_block(8, 6, 4);
  const SparseMatrix P = block_prolongation(block);
  const std::vector<Index> groups = same_row_groups(P);
  ASSERT_GT(P.cols(), 6);
  ASSERT_EQ(static_cast<Index>(groups.size()) - 1, P.cols() / 6);  // groups of six
  const GroupRows r = group_rows(P, groups);
  ASSERT_EQ(r.start.size(), static_cast<std::size_t>(P.rows()) + 1);

  // Rebuilt from the group rows, entry by entry, the matrix is P exactly.
  std::vector<Eigen::Triplet<double>> entries;
  for (Index k = 0; k < P.rows(); ++k)
    for (Index e = r.start[static_cast<std::size_t>(k)];
         e < r.start[static_cast<std::size_t>(k) + 1]; ++e) {
      const auto G = static_cast<std::size_t>(r.group[static_cast<std::size_t>(e)]);
      for (Index J = groups[G]; J < groups[G + 1]; ++J) {
        const int at = P.outerIndexPtr()[J] + r.position[static_cast<std::size_t>(e)];
        ASSERT_EQ(P.innerIndexPtr()[at], k);
        entries.emplace_back(k, J, P.valuePtr()[at]);
      }
    }
  SparseMatrix rebuilt(P.rows(), P.cols());
  rebuilt.setFromTriplets(entries.begin(), entries.end());
  EXPECT_EQ(rebuilt.nonZeros(), P.nonZeros());
  EXPECT_EQ((rebuilt - P).norm(), 0.0);

  // repeats[k]: row k has the columns of row k-1, as P's row-major copy says.
  const RowMajor rows(P);
  const auto columns_of = [&](Index k) {
    return std::vector<int>(rows.innerIndexPtr() + rows.outerIndexPtr()[k],
                            rows.innerIndexPtr() + rows.outerIndexPtr()[k + 1]);
  };
  Index repeated = 0;
  EXPECT_EQ(r.repeats[0], 0);
  for (Index k = 1; k < P.rows(); ++k) {
    const bool same = columns_of(k) == columns_of(k - 1);
    EXPECT_EQ(r.repeats[static_cast<std::size_t>(k)] != 0, same) << "row " << k;
    repeated += same ? 1 : 0;
  }
  EXPECT_GT(repeated, P.rows() / 2);  // the three unknowns of a node share their rows
}

TEST(RepeatsPreviousColumn, FindsTheColumnsWithTheRowsOfTheOneBefore) {
  // Columns 0 and 1 with rows {0, 2}, column 2 with {0, 1, 2}, column 3 with {1, 3}; column 4
  // with rows {1, 3} too, column 5 empty.
  SparseMatrix M(4, 6);
  const std::vector<Eigen::Triplet<double>> entries = {
      {0, 0, 1.0}, {2, 0, 1.0}, {0, 1, 2.0}, {2, 1, 3.0}, {0, 2, 1.0}, {1, 2, 1.0},
      {2, 2, 1.0}, {1, 3, 1.0}, {3, 3, 1.0}, {1, 4, 5.0}, {3, 4, 6.0}};
  M.setFromTriplets(entries.begin(), entries.end());
  EXPECT_EQ(repeats_previous_column(view_of(M)), (std::vector<char>{0, 1, 0, 0, 1, 0}));

  // The elasticity matrix of a block: the unknowns of a node share their columns' rows, except
  // where a clamp removed an unknown from its node.
  const testing::ClampedBlock block = testing::clamped_block(4, 3, 3);
  const std::vector<char> repeats = repeats_previous_column(view_of(block.A));
  Index repeated = 0;
  for (Index j = 1; j < block.A.cols(); ++j) {
    const SparseMatrix a = block.A.col(j), b = block.A.col(j - 1);
    const bool same =
        a.nonZeros() == b.nonZeros() &&
        std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr());
    EXPECT_EQ(repeats[static_cast<std::size_t>(j)] != 0, same) << "column " << j;
    repeated += same ? 1 : 0;
  }
  EXPECT_GT(repeated, block.A.cols() / 2);
}

TEST(NodeColumns, FindsThreeConsecutiveColumnsWithTheSameRows) {
  // Columns 0-2 share their rows, 3 differs from 2, 4-5 repeat 3, 6-8 share theirs again.
  const std::vector<char> repeats = {0, 1, 1, 0, 1, 1, 0, 1, 1};
  const std::vector<int> list = {0, 1, 2, 3, 4, 5, 6, 8};
  const int length = static_cast<int>(list.size());
  EXPECT_EQ(node_columns(list.data(), 0, length, 9, repeats), 3);
  EXPECT_EQ(node_columns(list.data(), 1, length, 9, repeats), 2);  // 1, 2: the node's last two
  EXPECT_EQ(node_columns(list.data(), 3, length, 9, repeats), 3);
  EXPECT_EQ(node_columns(list.data(), 3, length, 5, repeats), 2);  // 5 is past the limit
  EXPECT_EQ(node_columns(list.data(), 6, length, 9, repeats), 1);  // 7 is not in the list
  EXPECT_EQ(node_columns(list.data(), 5, 6, 9, repeats), 1);       // the list ends

  // The three columns read together are A's own.
  const testing::ClampedBlock block = testing::clamped_block(3, 3, 2);
  const std::vector<char> of_A = repeats_previous_column(view_of(block.A));
  Index checked = 0;
  for (Index i = 0; i + 2 < block.A.cols(); ++i) {
    if (!of_A[static_cast<std::size_t>(i + 1)] || !of_A[static_cast<std::size_t>(i + 2)]) continue;
    const ColumnsOfNode a(view_of(block.A), i);
    for (int r = 0; r < 3; ++r) {
      const SparseMatrix column = block.A.col(i + r);
      ASSERT_EQ(a.length, column.nonZeros());
      for (int e = 0; e < a.length; ++e) {
        EXPECT_EQ(a.rows[e], column.innerIndexPtr()[e]);
        EXPECT_EQ(a.values[r][e], column.valuePtr()[e]);
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 0);
}

}  // namespace
}  // namespace signorini

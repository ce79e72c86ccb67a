// The partition of the free dofs over the ranks (src/signorini/parallel/row_partition.hpp).

#include "signorini/parallel/row_partition.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

TEST(RowPartition, EqualRangesWithoutNodes) {
  const std::vector<Index> s = row_partition(10, 3, {}, SparseMatrix(0, 10));
  EXPECT_EQ(s, (std::vector<Index>{0, 3, 6, 10}));
}

TEST(RowPartition, NodesAndContactRowsAreNotSplit) {
  // 4 nodes of 3 dofs, then a node with 2 (one clamped): a boundary moves to a node's start.
  const std::vector<Index> nodes = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3, 4, 4};
  const std::vector<Index> s = row_partition(14, 3, nodes, SparseMatrix(0, 14));
  ASSERT_EQ(s.size(), 4U);
  EXPECT_EQ(s.front(), 0);
  EXPECT_EQ(s.back(), 14);
  for (std::size_t r = 1; r + 1 < s.size(); ++r) {
    EXPECT_NE(nodes[static_cast<std::size_t>(s[r])], nodes[static_cast<std::size_t>(s[r]) - 1]);
    EXPECT_LT(s[r - 1], s[r]);
  }
  // A contact row on dofs 4 and 7 (two nodes' dofs, as a row of N never is, but it must hold).
  SparseMatrix N(1, 14);
  N.insert(0, 4) = 1.0;
  N.insert(0, 7) = 1.0;
  const std::vector<Index> t = row_partition(14, 3, {}, N);
  for (std::size_t r = 1; r + 1 < t.size(); ++r) EXPECT_TRUE(t[r] <= 4 || t[r] > 7) << t[r];
}

TEST(RowPartition, TooManyRanksIsAnError) {
  EXPECT_THROW((void)row_partition(3, 4, {}, SparseMatrix(0, 3)), InputError);
  const std::vector<Index> one_node(6, 0);  // no boundary possible inside it
  EXPECT_THROW((void)row_partition(6, 2, one_node, SparseMatrix(0, 6)), InputError);
}

}  // namespace
}  // namespace signorini

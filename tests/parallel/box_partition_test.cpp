// The blocks of a box made in parts (src/signorini/parallel/box_partition.hpp): the grid that cuts
// the fewest faces, every lattice point owned by one rank whose block holds it, and parts whose
// two layers of cubes hold every cube around each of the rank's points.

#include "signorini/parallel/box_partition.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace signorini {
namespace {

BoxMeshOptions box(Index nx, Index ny, Index nz, CellType cell) {
  BoxMeshOptions o;
  o.nx = nx;
  o.ny = ny;
  o.nz = nz;
  o.cell = cell;
  return o;
}

TEST(BoxPartition, TheGridCutsTheFewestFaces) {
  EXPECT_EQ(BoxPartition(box(64, 64, 32, CellType::Hex8), 4).grid(), (std::array<int, 3>{2, 2, 1}));
  EXPECT_EQ(BoxPartition(box(64, 64, 32, CellType::Hex8), 2).grid(), (std::array<int, 3>{1, 2, 1}));
  EXPECT_EQ(BoxPartition(box(32, 32, 64, CellType::Hex8), 2).grid(), (std::array<int, 3>{1, 1, 2}));
  EXPECT_EQ(BoxPartition(box(8, 4, 4, CellType::Hex8), 2).grid(), (std::array<int, 3>{2, 1, 1}));
  EXPECT_EQ(BoxPartition(box(16, 16, 16, CellType::Hex8), 8).grid(), (std::array<int, 3>{2, 2, 2}));
  // 7 ranks need 7 cubes along one axis.
  EXPECT_FALSE(BoxPartition(box(4, 4, 4, CellType::Hex8), 7).possible());
  EXPECT_EQ(BoxPartition(box(4, 7, 4, CellType::Hex8), 7).grid(), (std::array<int, 3>{1, 7, 1}));
}

TEST(BoxPartition, EveryPointHasOneOwnerWhoseBlockAndPartHoldIt) {
  for (const CellType cell : {CellType::Hex8, CellType::Hex27}) {
    const BoxMeshOptions o = box(5, 4, 3, cell);
    for (const int ranks : {2, 3, 4, 6}) {
      SCOPED_TRACE(ranks);
      const BoxPartition p(o, ranks);
      ASSERT_TRUE(p.possible());
      const Index order = cell_order(cell);
      const std::array<Index, 3> cubes{5, 4, 3};
      const std::array<Index, 3> points{order * 5 + 1, order * 4 + 1, order * 3 + 1};
      std::vector<int> owned(static_cast<std::size_t>(ranks), 0);
      for (Index K = 0; K < points[2]; ++K)
        for (Index J = 0; J < points[1]; ++J)
          for (Index I = 0; I < points[0]; ++I) {
            const std::array<Index, 3> x{I, J, K};
            EXPECT_EQ(p.point(I + points[0] * (J + points[1] * K)), x);
            const int r = p.owner(x);
            ASSERT_GE(r, 0);
            ASSERT_LT(r, ranks);
            ++owned[static_cast<std::size_t>(r)];
            const auto first = p.first_point(r), end = p.end_point(r);
            const auto part_first = p.first_part_cube(r), part_end = p.end_part_cube(r);
            for (std::size_t a = 0; a < 3; ++a) {
              EXPECT_GE(x[a], first[a]);
              EXPECT_LT(x[a], end[a]);
              // Every cube around the point is in the part, and every cube around those.
              const Index lo = std::max<Index>(0, (x[a] - 1) / order - 1);
              const Index hi = std::min<Index>(cubes[a], x[a] / order + 2);
              EXPECT_LE(part_first[a], lo);
              EXPECT_GE(part_end[a], hi);
            }
          }
      Index total = 0;
      for (int r = 0; r < ranks; ++r) {
        Index count = 1;
        const auto first = p.first_point(r), end = p.end_point(r);
        for (std::size_t a = 0; a < 3; ++a) count *= end[a] - first[a];
        EXPECT_EQ(count, owned[static_cast<std::size_t>(r)]);
        total += count;
      }
      EXPECT_EQ(total, points[0] * points[1] * points[2]);
    }
  }
}

}  // namespace
}  // namespace signorini

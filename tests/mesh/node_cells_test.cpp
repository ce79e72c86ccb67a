// The cells around each node (mesh/node_cells.hpp).

#include "signorini/mesh/node_cells.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "signorini/mesh/box_mesh.hpp"

namespace signorini {
namespace {

TEST(NodeCells, ListsTheCellsThatHoldEachNodeInIncreasingOrder) {
  BoxMeshOptions box;
  box.nx = 3;
  box.ny = 2;
  box.nz = 2;
  box.cell = CellType::Tet4;
  const Mesh mesh = make_box_mesh(box);
  const NodeCells around(mesh);
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    std::vector<Index> expected;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto cell = mesh.cell(c);
      if (std::find(cell.begin(), cell.end(), v) != cell.end()) expected.push_back(c);
    }
    const auto got = around.of(v);
    EXPECT_TRUE(std::ranges::equal(got, expected)) << "node " << v;
  }
}

}  // namespace
}  // namespace signorini

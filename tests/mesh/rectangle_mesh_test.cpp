#include "signorini/mesh/rectangle_mesh.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

TEST(RectangleMesh, CountsCoordinatesAndParts) {
  const Mesh m = make_rectangle_mesh({0.0, 0.0, 3.0, 1.0, 60, 20});
  EXPECT_EQ(m.dim(), 2);
  EXPECT_EQ(m.cell_types(), std::vector<CellType>{CellType::Quad4});
  EXPECT_EQ(m.num_nodes(), 61 * 21);
  EXPECT_EQ(m.num_cells(), 1200);
  EXPECT_DOUBLE_EQ(m.node(60)(0), 3.0);  // far edges land exactly
  EXPECT_DOUBLE_EQ(m.node(m.num_nodes() - 1)(1), 1.0);
  for (const char* name : {"left", "right", "bottom", "top"})
    EXPECT_TRUE(m.has_boundary_part(name));
  EXPECT_EQ(m.boundary_part("bottom").facets.size(), 60u);
  EXPECT_EQ(m.boundary_part("left").facets.size(), 20u);
  EXPECT_EQ(m.boundary_part_nodes("bottom").size(), 61u);
  for (const Index n : m.boundary_part_nodes("top")) EXPECT_DOUBLE_EQ(m.node(n)(1), 1.0);
  for (const Index n : m.boundary_part_nodes("right")) EXPECT_DOUBLE_EQ(m.node(n)(0), 3.0);
}

TEST(RectangleMesh, CellsAreCounterclockwise) {
  const Mesh m = make_rectangle_mesh({1.0, 2.0, 2.0, 1.0, 3, 2});
  for (Index c = 0; c < m.num_cells(); ++c) {
    const auto v = m.cell(c);
    double area2 = 0.0;  // shoelace
    for (std::size_t a = 0; a < 4; ++a) {
      const auto p = m.node(v[a]);
      const auto q = m.node(v[(a + 1) % 4]);
      area2 += p(0) * q(1) - q(0) * p(1);
    }
    EXPECT_NEAR(area2, 2.0 * (2.0 / 3.0) * 0.5, 1e-14);
  }
}

TEST(RectangleMesh, BadSizesAndUnknownPartsAreErrors) {
  EXPECT_THROW(make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 0, 3}), InputError);
  EXPECT_THROW(make_rectangle_mesh({0.0, 0.0, -1.0, 1.0, 3, 3}), InputError);
  const Mesh m = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  try {
    (void)m.boundary_part("bottm");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("bottom"), std::string::npos) << e.what();
  }
}

// Every 2D cell type: counts, positive areas (shoelace over the corners), and boundary parts whose
// nodes lie on their edges, with the mid-edge nodes of quadratic cells among them.
TEST(RectangleMesh, EveryCellTypeHasTheRightCountsAndBoundaries) {
  struct Case {
    CellType type;
    Index cells, nodes, bottom_nodes;
  };
  const Index nx = 4, ny = 3;
  for (const Case k :
       {Case{CellType::Tri3, 2 * nx * ny, (nx + 1) * (ny + 1), nx + 1},
        Case{CellType::Tri6, 2 * nx * ny, (2 * nx + 1) * (2 * ny + 1), 2 * nx + 1},
        Case{CellType::Quad8, nx * ny, (2 * nx + 1) * (2 * ny + 1) - nx * ny, 2 * nx + 1},
        Case{CellType::Quad9, nx * ny, (2 * nx + 1) * (2 * ny + 1), 2 * nx + 1}}) {
    RectangleMeshOptions o{1.0, 2.0, 2.0, 1.5, nx, ny};
    o.cell = k.type;
    const Mesh m = make_rectangle_mesh(o);
    const std::string name(enum_to_string(kCellTypeNames, k.type));
    EXPECT_EQ(m.num_cells(), k.cells) << name;
    EXPECT_EQ(m.num_nodes(), k.nodes) << name;
    EXPECT_EQ(m.cell_types(), std::vector<CellType>{k.type}) << name;
    double area = 0.0;
    const int corners = (k.type == CellType::Tri3 || k.type == CellType::Tri6) ? 3 : 4;
    for (Index c = 0; c < m.num_cells(); ++c) {
      const auto v = m.cell(c);
      double area2 = 0.0;
      for (int a = 0; a < corners; ++a) {
        const auto p = m.node(v[static_cast<std::size_t>(a)]);
        const auto q = m.node(v[static_cast<std::size_t>((a + 1) % corners)]);
        area2 += p(0) * q(1) - q(0) * p(1);
      }
      EXPECT_GT(area2, 0.0) << name << " cell " << c;
      area += 0.5 * area2;
    }
    EXPECT_NEAR(area, 3.0, 1e-12) << name;
    EXPECT_EQ(static_cast<Index>(m.boundary_part_nodes("bottom").size()), k.bottom_nodes) << name;
    for (const Index n : m.boundary_part_nodes("bottom")) EXPECT_DOUBLE_EQ(m.node(n)(1), 2.0);
    for (const Index n : m.boundary_part_nodes("top")) EXPECT_DOUBLE_EQ(m.node(n)(1), 3.5);
    for (const Index n : m.boundary_part_nodes("left")) EXPECT_DOUBLE_EQ(m.node(n)(0), 1.0);
    for (const Index n : m.boundary_part_nodes("right")) EXPECT_DOUBLE_EQ(m.node(n)(0), 3.0);
  }
}

TEST(Mesh, MixedCellTypesAndTypeDimensionMismatch) {
  Eigen::MatrixXd xy(2, 5);
  xy << 0, 1, 1, 0, 2,  //
      0, 0, 1, 1, 0.5;
  const Mesh m({CellType::Quad4, CellType::Tri3}, xy, {0, 1, 2, 3, 1, 4, 2});
  EXPECT_EQ(m.num_cells(), 2);
  EXPECT_EQ(m.cell(1).size(), 3u);
  EXPECT_EQ(m.cell(1)[1], 4);
  EXPECT_EQ(m.max_nodes_per_cell(), 4);
  EXPECT_EQ(m.facet_nodes({1, 1}), (std::vector<Index>{4, 2}));
  EXPECT_THROW(Mesh({CellType::Quad4, CellType::Tri3}, xy, {0, 1, 2, 3, 1, 4}), InputError);
  EXPECT_THROW(Mesh({CellType::Hex8}, xy, {0, 1, 2, 3, 0, 1, 2, 3}), InputError);
}

TEST(Mesh, RejectsOutOfRangeConnectivity) {
  Eigen::MatrixXd xy(2, 3);
  xy << 0, 1, 0, 0, 0, 1;
  EXPECT_THROW(Mesh(CellType::Quad4, xy, {0, 1, 2, 3}), InputError);
}

}  // namespace
}  // namespace signorini

#include "signorini/mesh/rectangle_mesh.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

TEST(RectangleMesh, CountsCoordinatesAndParts) {
  const Mesh m = make_rectangle_mesh({0.0, 0.0, 3.0, 1.0, 60, 20});
  EXPECT_EQ(m.dim(), 2);
  EXPECT_EQ(m.cell_type(), CellType::Quad4);
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

TEST(Mesh, RejectsOutOfRangeConnectivity) {
  Eigen::MatrixXd xy(2, 3);
  xy << 0, 1, 0, 0, 0, 1;
  EXPECT_THROW(Mesh(CellType::Quad4, xy, {0, 1, 2, 3}), InputError);
}

}  // namespace
}  // namespace signorini

// The node order of VTK's quadratic cells, checked on the geometry of box meshes against VTK's
// documented definitions (vtkQuadraticTetra, vtkTriQuadraticHexahedron): each mid-edge point is
// the middle of the two corners VTK names for it, each mid-face point the centre of its face.
// A permutation that is wrong draws a crumpled cell in ParaView; here it fails.

#include "signorini/output/vtu_file.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "output/vtu_reader.hpp"
#include "signorini/mesh/box_mesh.hpp"

namespace signorini {
namespace {

// VTK's points of a cell read back from the file: point k of cell c.
struct WrittenCells {
  testing::VtuContents v;
  Eigen::Vector3d point(long c, int k, int per_cell) const {
    const auto id =
        static_cast<std::size_t>(v.connectivity.values[static_cast<std::size_t>(c * per_cell + k)]);
    return {v.coordinates.values[3 * id], v.coordinates.values[3 * id + 1],
            v.coordinates.values[3 * id + 2]};
  }
};

WrittenCells write_box(CellType cell) {
  BoxMeshOptions o;
  o.length = 1.0;
  o.width = 0.7;
  o.height = 0.4;
  o.nx = 2;
  o.ny = 2;
  o.nz = 1;
  o.cell = cell;
  const Mesh mesh = make_box_mesh(o);
  VtuFile file(mesh.coordinates());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    file.add_cell(mesh.cell_type(c), mesh.cell(c));
  }
  return {testing::read_vtu_text(file.take_text())};
}

TEST(VtuFile, QuadraticTetraInVtksOrder) {
  const WrittenCells w = write_box(CellType::Tet10);
  // vtkQuadraticTetra: points 4-9 on the edges (0,1), (1,2), (2,0), (0,3), (1,3), (2,3).
  const std::array<std::array<int, 2>, 6> edges{{{0, 1}, {1, 2}, {2, 0}, {0, 3}, {1, 3}, {2, 3}}};
  ASSERT_GT(w.v.cells, 0);
  for (long c = 0; c < w.v.cells; ++c) {
    EXPECT_EQ(w.v.types.values[static_cast<std::size_t>(c)], 24.0);
    for (int e = 0; e < 6; ++e) {
      const Eigen::Vector3d middle =
          0.5 * (w.point(c, edges[e][0], 10) + w.point(c, edges[e][1], 10));
      EXPECT_LT((w.point(c, 4 + e, 10) - middle).norm(), 1e-12) << "cell " << c << " edge " << e;
    }
  }
}

TEST(VtuFile, TriquadraticHexahedronInVtksOrder) {
  const WrittenCells w = write_box(CellType::Hex27);
  // vtkTriQuadraticHexahedron: corners 0-3 bottom and 4-7 top (counterclockwise), points 8-19 on
  // the edges (0,1), (1,2), (2,3), (3,0), (4,5), (5,6), (6,7), (7,4), (0,4), (1,5), (2,6), (3,7),
  // 20-25 the centres of the faces (0,3,7,4), (1,2,6,5), (0,1,5,4), (3,2,6,7), (0,1,2,3),
  // (4,5,6,7), 26 the centre of the cell.
  const std::array<std::array<int, 2>, 12> edges{{{0, 1},
                                                  {1, 2},
                                                  {2, 3},
                                                  {3, 0},
                                                  {4, 5},
                                                  {5, 6},
                                                  {6, 7},
                                                  {7, 4},
                                                  {0, 4},
                                                  {1, 5},
                                                  {2, 6},
                                                  {3, 7}}};
  const std::array<std::array<int, 4>, 6> faces{
      {{0, 3, 7, 4}, {1, 2, 6, 5}, {0, 1, 5, 4}, {3, 2, 6, 7}, {0, 1, 2, 3}, {4, 5, 6, 7}}};
  ASSERT_GT(w.v.cells, 0);
  for (long c = 0; c < w.v.cells; ++c) {
    EXPECT_EQ(w.v.types.values[static_cast<std::size_t>(c)], 29.0);
    // The corners counterclockwise seen from above, the top over the bottom.
    const Eigen::Vector3d p0 = w.point(c, 0, 27), p1 = w.point(c, 1, 27), p3 = w.point(c, 3, 27);
    EXPECT_GT((p1 - p0).cross(p3 - p0).z(), 0.0) << c;
    for (int k = 0; k < 4; ++k) EXPECT_GT(w.point(c, 4 + k, 27).z(), w.point(c, k, 27).z()) << c;
    for (int e = 0; e < 12; ++e) {
      const Eigen::Vector3d middle =
          0.5 * (w.point(c, edges[e][0], 27) + w.point(c, edges[e][1], 27));
      EXPECT_LT((w.point(c, 8 + e, 27) - middle).norm(), 1e-12) << "cell " << c << " edge " << e;
    }
    Eigen::Vector3d centre = Eigen::Vector3d::Zero();
    for (int f = 0; f < 6; ++f) {
      Eigen::Vector3d mean = Eigen::Vector3d::Zero();
      for (const int k : faces[f]) mean += 0.25 * w.point(c, k, 27);
      EXPECT_LT((w.point(c, 20 + f, 27) - mean).norm(), 1e-12) << "cell " << c << " face " << f;
      centre += mean / 6.0;
    }
    EXPECT_LT((w.point(c, 26, 27) - centre).norm(), 1e-12) << c;
  }
}

}  // namespace
}  // namespace signorini

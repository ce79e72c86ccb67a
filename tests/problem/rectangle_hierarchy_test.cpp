// The multigrid hierarchy of rectangle meshes (problem/rectangle_hierarchy.hpp): level sizes,
// exact interpolation of bilinear fields, and no coarse level for odd meshes.

#include "signorini/problem/rectangle_hierarchy.hpp"

#include <gtest/gtest.h>

#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

TEST(RectangleHierarchy, PaperMeshesCoarsenToFifteenByFive) {
  for (const Index nx : {60, 120, 240}) {
    const ProblemSpec spec = paper_benchmark(nx, nx / 3);
    const DofMap dofs = make_dof_map(make_rectangle_mesh(spec.mesh), spec.clamps);
    const auto P = make_rectangle_prolongations(spec.mesh, spec.clamps, dofs);
    ASSERT_FALSE(P.empty());
    EXPECT_EQ(P.front().rows(), dofs.num_free());
    for (std::size_t l = 1; l < P.size(); ++l) EXPECT_EQ(P[l].rows(), P[l - 1].cols());
    // 15 x 5 cells, 16 x 6 nodes, the 6 left nodes clamped in x and y.
    EXPECT_EQ(P.back().cols(), 2 * 16 * 6 - 12) << nx;
  }
}

TEST(RectangleHierarchy, InterpolatesBilinearFieldsExactly) {
  const ProblemSpec spec = paper_benchmark(24, 8);
  const Mesh fine = make_rectangle_mesh(spec.mesh);
  const DofMap fdofs = make_dof_map(fine, spec.clamps);
  const auto P = make_rectangle_prolongations(spec.mesh, spec.clamps, fdofs, 10);
  ASSERT_GE(P.size(), 2U);
  RectangleMeshOptions co = spec.mesh;
  co.nx /= 2;
  co.ny /= 2;
  const Mesh coarse = make_rectangle_mesh(co);
  const DofMap cdofs = make_dof_map(coarse, spec.clamps);
  // u = (x y, x (1 + y)): bilinear, and zero on the clamped edge x = 0, as corrections are.
  auto field = [](const Mesh& m, const DofMap& d) {
    Vector v(d.num_free());
    for (Index node = 0; node < m.num_nodes(); ++node) {
      const double x = m.coordinates()(0, node), y = m.coordinates()(1, node);
      if (d.free_index(node, 0) >= 0) v(d.free_index(node, 0)) = x * y;
      if (d.free_index(node, 1) >= 0) v(d.free_index(node, 1)) = x * (1.0 + y);
    }
    return v;
  };
  const Vector interpolated = P.front() * field(coarse, cdofs);
  EXPECT_LT((interpolated - field(fine, fdofs)).cwiseAbs().maxCoeff(), 1e-13);
  // Rows of P sum to 1 away from the clamped edge (constants are reproduced there).
  const Vector ones = P.front() * Vector::Ones(P.front().cols());
  for (Index node = 0; node < fine.num_nodes(); ++node)
    if (fine.coordinates()(0, node) > 3.0 / 12.0 + 1e-12) {
      EXPECT_NEAR(ones(fdofs.free_index(node, 1)), 1.0, 1e-14);
    }
}

TEST(RectangleHierarchy, OddMeshHasNoCoarseLevel) {
  const ProblemSpec spec = paper_benchmark(63, 21);
  const DofMap dofs = make_dof_map(make_rectangle_mesh(spec.mesh), spec.clamps);
  EXPECT_TRUE(make_rectangle_prolongations(spec.mesh, spec.clamps, dofs).empty());
}

}  // namespace
}  // namespace signorini

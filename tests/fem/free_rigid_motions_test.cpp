// Free rigid motions: which translations and rotations the clamps leave free, named, for every
// way of holding a rectangle, and for a mesh of two pieces.

#include "signorini/fem/free_rigid_motions.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

std::vector<std::string> free_motions(const Mesh& mesh, const std::vector<ClampSpec>& clamps) {
  std::vector<std::string> out;
  for (const RigidMotion& m : free_rigid_motions(mesh, make_dof_map(mesh, clamps)))
    out.push_back(m.description());
  return out;
}

using Names = std::vector<std::string>;

TEST(FreeRigidMotions, RectangleHeldInEveryWay) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 3.0, 1.0, 6, 2});
  const std::array<bool, 3> x{true, false, false}, y{false, true, false}, xy{true, true, true};
  EXPECT_EQ(free_motions(mesh, {{"left", xy}}), Names{});
  EXPECT_EQ(free_motions(mesh, {{"left", x}}), Names{"translation in y"});
  EXPECT_EQ(free_motions(mesh, {{"top", y}}), Names{"translation in x"});
  EXPECT_EQ(free_motions(mesh, {{"left", x}, {"bottom", y}}), Names{});
  EXPECT_EQ(free_motions(mesh, {}),
            (Names{"translation in x", "translation in y", "rotation about (1.5, 0.5)"}));
}

TEST(FreeRigidMotions, RotationAboutAPointOfARoller) {
  // y held along the left edge of a unit square: it may slide along x, and turn about the
  // middle of that edge (both nodes then move along x only).
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 1, 1});
  const std::array<bool, 3> y{false, true, false};
  EXPECT_EQ(free_motions(mesh, {{"left", y}}),
            (Names{"translation in x", "rotation about (0, 0.5)"}));
  // With x held too on the bottom edge, turning about the corner (0, 0) is left: the corners
  // (1, 0) and (0, 1) then move along y and x, where they are free.
  const std::array<bool, 3> x{true, false, false};
  EXPECT_EQ(free_motions(mesh, {{"left", y}, {"bottom", x}}), Names{"rotation about (0, 0)"});
  // x held on the right edge instead holds it: its two nodes, at different heights, would move
  // along x by different amounts.
  EXPECT_EQ(free_motions(mesh, {{"left", y}, {"right", x}}), Names{});
}

TEST(FreeRigidMotions, EachPieceOfTheMeshIsHeldOnItsOwn) {
  // Two unit squares that share no node: clamping one leaves the other free.
  Eigen::MatrixXd xy(2, 8);
  xy << 0, 1, 1, 0, 3, 4, 4, 3,  //
      0, 0, 1, 1, 0, 0, 1, 1;
  Mesh mesh(CellType::Quad4, xy, {0, 1, 2, 3, 4, 5, 6, 7});
  mesh.set_boundary_part("first", {{0, 0}});
  const std::array<bool, 3> xyz{true, true, true};
  EXPECT_EQ(count_mesh_pieces(mesh), 2);
  const auto motions = free_rigid_motions(mesh, make_dof_map(mesh, {{"first", xyz}}));
  ASSERT_EQ(motions.size(), 3U);
  for (const RigidMotion& m : motions) EXPECT_EQ(m.piece, 1);
  EXPECT_EQ(motions[2].description(), "rotation about (3.5, 0.5)");
  try {
    require_no_free_rigid_motion(mesh, make_dof_map(mesh, {{"first", xyz}}));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the mesh piece with node 4 at (3, 0): translation in x"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signorini

#include "signorini/interface/contact_boundary.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

TEST(ContactSet, BottomEdgeOfThePaperMesh) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 3.0, 1.0, 6, 2});
  const DofMap dofs = make_dof_map(mesh, {{"left"}});
  const ContactSet cs = make_contact_set(mesh, mesh.boundary_part("bottom"), dofs,
                                         [](const Point& x) { return 0.1 * x(0); });
  ASSERT_EQ(cs.size(), 7);
  // Boundary order: increasing x along the bottom edge.
  for (Index j = 0; j < cs.size(); ++j) {
    EXPECT_DOUBLE_EQ(mesh.node(cs.nodes[static_cast<std::size_t>(j)])(0),
                     0.5 * static_cast<double>(j));
    EXPECT_NEAR(cs.normals(0, j), 0.0, 1e-15);
    EXPECT_NEAR(cs.normals(1, j), -1.0, 1e-15);
    EXPECT_NEAR(cs.gaps(j), 0.05 * static_cast<double>(j), 1e-15);
  }
  // Trapezoid weights: h/2 at the ends, h inside; they sum to the edge length.
  EXPECT_DOUBLE_EQ(cs.weights(0), 0.25);
  EXPECT_DOUBLE_EQ(cs.weights(3), 0.5);
  EXPECT_NEAR(cs.weights.sum(), 3.0, 1e-14);
  // The corner node (0,0) is clamped: it stays in the set but cannot move.
  EXPECT_FALSE(cs.movable[0]);
  EXPECT_TRUE(cs.movable[1]);
  EXPECT_EQ(cs.N.row(0).norm(), 0.0);
  EXPECT_EQ(cs.num_movable(), 6);
  // The facets are kept, as positions in the set: (0,1), (1,2), ... (5,6).
  ASSERT_EQ(cs.facets.size(), 6U);
  for (std::size_t k = 0; k < cs.facets.size(); ++k) {
    const std::vector<Index> expected = {static_cast<Index>(k), static_cast<Index>(k + 1)};
    EXPECT_EQ(cs.facets[k], expected);
  }
}

TEST(ContactSet, CornerNormalsAverageTheFacets) {
  // The right and bottom edges together: the corner (1,0) gets the normal (1,-1)/sqrt(2).
  const Mesh base = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  Mesh mesh = base;
  auto facets = base.boundary_part("bottom").facets;
  for (const Facet& f : base.boundary_part("right").facets) facets.push_back(f);
  mesh.set_boundary_part("bottom_right", facets);
  const DofMap dofs = make_dof_map(mesh, {{"left"}});
  const ContactSet cs = make_contact_set(mesh, mesh.boundary_part("bottom_right"), dofs,
                                         [](const Point&) { return 0.0; });
  ASSERT_EQ(cs.size(), 5);
  EXPECT_NEAR(cs.normals(0, 2), std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(cs.normals(1, 2), -std::sqrt(0.5), 1e-15);
  EXPECT_DOUBLE_EQ(cs.weights(2), 0.5);
}

TEST(ContactSet, ContactOnTheClampedEdgeIsRejected) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  const DofMap dofs = make_dof_map(mesh, {{"left"}});
  EXPECT_THROW(
      make_contact_set(mesh, mesh.boundary_part("left"), dofs, [](const Point&) { return 0.0; }),
      InputError);
}

TEST(ContactSet, NonFiniteGapIsRejected) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  const DofMap dofs = make_dof_map(mesh, {{"left"}});
  EXPECT_THROW(make_contact_set(mesh, mesh.boundary_part("bottom"), dofs,
                                [](const Point& x) { return std::log(x(0) - 0.5); }),
               InputError);
}

TEST(ContactSet, EmptyBoundaryPartIsRejected) {
  // Not possible from a problem file today (every edge of a rectangle has facets), but a mesh read
  // from a file may name a part that has none.
  Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  mesh.set_boundary_part("nothing", {});
  const DofMap dofs = make_dof_map(mesh, {{"left"}});
  try {
    (void)make_contact_set(mesh, mesh.boundary_part("nothing"), dofs,
                           [](const Point&) { return 0.0; });
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "contact.boundary = 'nothing': the boundary part has no facets");
  }
}

}  // namespace
}  // namespace signorini

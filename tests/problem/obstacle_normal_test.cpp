// The constraint direction against a rigid obstacle of known shape (method.md section 3): the
// obstacle's normal at each node's closest point, the gap the signed distance to it. A contact
// part that turns a corner (the bottom and a side of a square, the base and the side of a block
// or of a quarter cylinder) pressed onto a frictionless plane must get the uniform pressure of
// uniaxial strain to round-off and no sideways force; a body placed inside its obstacle, or a
// contact part that faces away from it, is an input error.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <string>
#include <utility>

#include "expect_contains.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/resultants.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

using testing::input_error_of;

// A mesh with an extra boundary part `name` made of the facets of the parts `sides`.
std::shared_ptr<const Mesh> with_part(Mesh mesh, const std::string& name,
                                      const std::vector<std::string>& sides) {
  std::vector<Facet> facets;
  for (const std::string& s : sides)
    for (const Facet& f : mesh.boundary_part(s).facets) facets.push_back(f);
  mesh.set_boundary_part(name, facets);
  return std::make_shared<const Mesh>(std::move(mesh));
}

struct Solved {
  Model model;
  ContactResult result;
};

Solved solve_text(const std::string& text, std::shared_ptr<const Mesh> mesh,
                  const std::vector<std::string>& overrides = {}) {
  const LoadedProblem loaded = parse_problem_string(text, "corner.toml", overrides, mesh);
  Solved s{build_model(loaded.spec), {}};
  s.result = solve_contact(s.model.problem, s.model.solver, &s.model.multigrid);
  return s;
}

// The 10 x 10 mm square of the report: roller on the left, top moved down 0.002 mm, contact part
// "outer" (the bottom and the right side) on the rigid plane y = 0. Plane strain, E = 210 GPa,
// nu = 0.3: uniaxial strain -2e-4, so the pressure is E / (1 - nu^2) 2e-4 = 46.15 MPa
// everywhere on the bottom and the force (0, 461.5) N/mm. `contact`: another [contact] table.
std::string square(const std::string& contact = R"(
[contact]
boundary = "outer"
obstacle = "plane"
point = [0.0, 0.0]
normal = [0.0, 1.0]
)") {
  return R"(
units = "mm-MPa"
[material]
E = 210000.0
nu = 0.3
plane_model = "plane_strain"

[[clamp]]
boundary = "left"
components = ["x"]

[[displacement]]
boundary = "top"
y = -0.002
)" + contact;
}

TEST(ObstacleNormal, CornerOfASquareOnAPlaneGetsTheUniformPressure) {
  const auto mesh =
      with_part(make_rectangle_mesh({0.0, 0.0, 10.0, 10.0, 8, 8}), "outer", {"bottom", "right"});
  for (const std::string method : {"uzawa_gnm", "semismooth_newton"}) {
    SCOPED_TRACE(method);
    const Solved s = solve_text(square(), mesh, {"solver.method=" + method});
    ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
    const double p = 210000.0 / (1.0 - 0.09) * 2e-4;
    const ContactSet& c = s.model.problem.contact;
    ASSERT_EQ(c.size(), 17);
    for (Index j = 0; j < c.size(); ++j) {
      const Point x = s.model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
      // Every constraint acts along the plane's normal, the corner's too.
      EXPECT_NEAR(c.normals(0, j), 0.0, 1e-15);
      EXPECT_NEAR(c.normals(1, j), -1.0, 1e-15);
      // (less, at the top corner, the 0.002 that its prescribed displacement moves it down)
      EXPECT_NEAR(c.gaps(j), x(1) == 10.0 ? 10.0 - 0.002 : x(1), 1e-14);
      EXPECT_NEAR(s.result.l(j), x(1) == 0.0 ? p : 0.0, 1e-9 * p)
          << "at x = " << x(0) << ", " << x(1);
    }
    const Resultants r = compute_resultants(s.model, s.result);
    EXPECT_NEAR(r.contact(0), 0.0, 1e-9 * 10.0 * p);
    EXPECT_NEAR(r.contact(1), 10.0 * p, 1e-9 * 10.0 * p);
  }
}

// The 3D problems below: rollers on the parts `xsym` and `ysym`, the part `top` moved down by
// 0.002, the contact part "outer" on the plane z = 0.
std::string pushed_onto_a_plane(const std::string& xsym, const std::string& ysym,
                                const std::string& top) {
  return R"(
[material]
E = 210000.0
nu = 0.3

[[clamp]]
boundary = ")" +
         xsym + R"("
components = ["x"]

[[clamp]]
boundary = ")" +
         ysym + R"("
components = ["y"]

[[displacement]]
boundary = ")" +
         top + R"("
z = -0.002

[contact]
boundary = "outer"
obstacle = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
)";
}

// Uniaxial stress: the pressure E 2e-4 at every node of the contact part on z = 0, none at its
// other nodes, and the obstacle's force along z alone, that pressure times the weights on z = 0.
// Returns the contact nodes on z = 0 and elsewhere.
std::pair<Index, Index> expect_uniaxial_stress(const Solved& s) {
  EXPECT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  const double p = 210000.0 * 2e-4;
  const ContactSet& c = s.model.problem.contact;
  double base_area = 0.0;
  Index on_base = 0, elsewhere = 0;
  for (Index j = 0; j < c.size(); ++j) {
    const Point x = s.model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
    const bool base = std::abs(x(2)) < 1e-12;
    (base ? on_base : elsewhere) += 1;
    if (base) base_area += c.weights(j);
    EXPECT_NEAR(s.result.l(j), base ? p : 0.0, 1e-9 * p)
        << "at x = " << x(0) << ", " << x(1) << ", " << x(2);
  }
  const Resultants r = compute_resultants(s.model, s.result);
  const double force = p * base_area;
  EXPECT_NEAR(r.contact(0), 0.0, 1e-9 * force);
  EXPECT_NEAR(r.contact(1), 0.0, 1e-9 * force);
  EXPECT_NEAR(r.contact(2), force, 1e-9 * force);
  return {on_base, elsewhere};
}

// The same in 3D: a 10 x 10 x 10 block whose contact part holds its base and one side, on the
// plane z = 0, rollers on x = 0 and y = 0, its top moved down by 0.002, free on x = 10 and
// y = 10: uniaxial stress, the pressure E 2e-4 = 42 MPa on the whole base, its edges included.
TEST(ObstacleNormal, EdgeOfABlockOnAPlaneGetsTheUniformPressure) {
  BoxMeshOptions box;
  box.length = box.width = box.height = 10.0;
  box.nx = box.ny = box.nz = 3;
  const auto mesh = with_part(make_box_mesh(box), "outer", {"zmin", "xmax"});
  const Solved s = solve_text(pushed_onto_a_plane("xmin", "ymin", "zmax"), mesh);
  const auto [on_base, on_side] = expect_uniaxial_stress(s);
  EXPECT_EQ(on_base, 16);
  EXPECT_EQ(on_side, 12);
  const Resultants r = compute_resultants(s.model, s.result);
  EXPECT_NEAR(r.contact(2), 100.0 * 210000.0 * 2e-4, 1e-9 * 100.0 * 210000.0 * 2e-4);
}

// The report's 3D case: a quarter cylinder (radius 5, height 10) whose contact part holds its
// base and its curved side, rollers on its symmetry planes, its top moved down by 0.002 onto the
// plane z = 0: uniaxial stress, E 2e-4 = 42 MPa on the whole base, its rim included, and no
// sideways force. Gmsh's hexahedra, extruded from a structured quarter disc, so that the side's
// faces stand exactly upright (the faceted cylinder is then a prism, for which uniaxial stress
// is the exact solution; tetrahedra on the curved side lean a little and make it a near miss).
TEST(ObstacleNormal, QuarterCylinderOnAPlaneGetsTheUniformPressure) {
  if (std::system("command -v gmsh > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "the gmsh program is not installed (apt-get install gmsh)";
  const testing::TemporaryFolder dir;
  std::ofstream(dir / "quarter.geo") << R"(Point(1) = {0, 0, 0}; Point(2) = {5, 0, 0};
Point(3) = {0, 5, 0}; Point(4) = {5 * Cos(Pi / 4), 5 * Sin(Pi / 4), 0};
Line(1) = {1, 2}; Circle(2) = {2, 1, 4}; Circle(3) = {4, 1, 3}; Line(4) = {3, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Transfinite Curve{1, 2, 3, 4} = 5;
Transfinite Surface{1}; Recombine Surface{1};
out[] = Extrude {0, 0, 10} { Surface{1}; Layers{4}; Recombine; };
Physical Surface("outer") = {1, out[3], out[4]};
Physical Surface("top") = {out[0]};
Physical Surface("ysym") = {out[2]};
Physical Surface("xsym") = {out[5]};
Physical Volume("body") = {out[1]};
)";
  const auto mesh = std::make_shared<const Mesh>(read_mesh_file(dir / "quarter.geo"));
  const auto [on_base, on_side] =
      expect_uniaxial_stress(solve_text(pushed_onto_a_plane("xsym", "ysym", "top"), mesh));
  EXPECT_GT(on_base, 10);
  EXPECT_GT(on_side, 10);
}

TEST(ObstacleNormal, ABodyInsideItsObstacleIsAnInputError) {
  // The plane's normal turned the wrong way: the whole square lies inside the half-plane y >= 0.
  const auto mesh =
      with_part(make_rectangle_mesh({0.0, 0.0, 10.0, 10.0, 4, 4}), "outer", {"bottom", "right"});
  const std::string message =
      input_error_of([&] { (void)solve_text(square(), mesh, {"contact.normal=[0.0, -1.0]"}); });
  EXPECT_CONTAINS(message, "contact.boundary = 'outer'");
  EXPECT_CONTAINS(message, "the body starts inside the obstacle");
  EXPECT_CONTAINS(message, "plane through (0, 0) with normal (0, -1)");
  EXPECT_CONTAINS(message, "lies 10 deep");
  // A small initial interference is allowed (a tenth of the body's smallest extent) ...
  const Solved s = solve_text(square(), mesh, {"contact.point=[0.0, 0.5]"});
  EXPECT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  EXPECT_GT(s.result.l.maxCoeff(), 0.0);
  // ... a deeper one is not.
  EXPECT_CONTAINS(
      input_error_of([&] { (void)solve_text(square(), mesh, {"contact.point=[0.0, 1.5]"}); }),
      "lies 1.5 deep, more than the 1 (a tenth of the body's smallest extent)");
  // A gap formula likewise.
  EXPECT_CONTAINS(input_error_of([&] {
                    (void)solve_text(square("[contact]\nboundary = \"outer\"\ngap = \"-2\"\n"),
                                     mesh);
                  }),
                  "contact.gap = -2 at x = ");
}

TEST(ObstacleNormal, APartFacingAwayFromTheObstacleIsAnInputError) {
  // The bottom faces down, away from a plane above the square (the half-plane y >= 10.5): no
  // node of it can ever touch that plane.
  const auto mesh = std::make_shared<const Mesh>(make_rectangle_mesh({0.0, 0.0, 10.0, 10.0, 4, 4}));
  const std::string message = input_error_of([&] {
    (void)solve_text(
        square(), mesh,
        {"contact.boundary=\"bottom\"", "contact.point=[0.0, 10.5]", "contact.normal=[0.0, -1.0]"});
  });
  EXPECT_CONTAINS(message,
                  "contact.boundary = 'bottom': no contact node can move towards the obstacle");
}

TEST(ObstacleNormal, DiscObstacleActsAlongItsRadius) {
  // A roller of radius 2 about (5, -2) under the square: each constraint along the line from the
  // node to the roller's centre, the gap the distance to the circle.
  const auto mesh = std::make_shared<const Mesh>(make_rectangle_mesh({0.0, 0.0, 10.0, 10.0, 4, 4}));
  const Solved s = solve_text(square(R"(
[contact]
boundary = "bottom"
obstacle = "disc"
centre = [5.0, -2.0]
radius = 2.0
)"),
                              mesh);
  ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  const ContactSet& c = s.model.problem.contact;
  for (Index j = 0; j < c.size(); ++j) {
    const Point x = s.model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
    const Eigen::Vector2d d(x(0) - 5.0, x(1) + 2.0);
    EXPECT_NEAR(c.normals(0, j), -d(0) / d.norm(), 1e-15);
    EXPECT_NEAR(c.normals(1, j), -d(1) / d.norm(), 1e-15);
    EXPECT_NEAR(c.gaps(j), d.norm() - 2.0, 1e-14);
  }
  // Only the node over the roller's top touches; the force points along its radius (up).
  const Resultants r = compute_resultants(s.model, s.result);
  EXPECT_NEAR(r.contact(0), 0.0, 1e-9 * r.contact.norm());
  EXPECT_GT(r.contact(1), 0.0);
}

}  // namespace
}  // namespace signorini

// Prescribed displacements ([[displacement]]), normal pressure ([[pressure]]) and several contact
// boundaries ([[contact]]), against analytic answers: a uniform stretch imposed by a displacement,
// the resultant of a uniform pressure on a quarter circle, and a block pressed between two rigid
// obstacles, solved by two methods that must agree.

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "expect_contains.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/problem/resultants.hpp"
#include "temporary_folder.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::input_error_of;

ContactResult run(const Model& model, const ProblemSpec& spec, ContactMethod method) {
  ContactSolverOptions o = spec.solver;
  o.method = method;
  o.uzawa_tolerance = 1e-12;
  return solve_contact(model.problem, o);
}

// A 2 x 1 block of 8 x 4 `cell`s held by `conditions` ([[clamp]] and [[displacement]] tables),
// with a contact boundary on top far from its obstacle.
std::string block(const std::string& conditions, const std::string& cell = "quad4") {
  return R"(
[mesh]
type = "rectangle"
length = 2.0
height = 1.0
nx = 8
ny = 4
cell = ")" +
         cell + R"("

[material]
E = 1000.0
nu = 0.3
)" + conditions +
         R"(
[contact]
boundary = "top"
gap = "1"
)";
}

// The block on rollers (left: x held, bottom: y held), its right side moved by `right`
// (a [[displacement]] entry's keys).
std::string stretched_block(const std::string& right, const std::string& cell = "quad4") {
  return block(R"(
[[clamp]]
boundary = "left"
components = ["x"]

[[clamp]]
boundary = "bottom"
components = ["y"]

[[displacement]]
boundary = "right"
)" + right + "\n",
               cell);
}

// Plane strain, sigma_yy = 0, eps_xx = d / L: eps_yy = -nu / (1 - nu) eps_xx and
// sigma_xx = E / (1 - nu^2) eps_xx, everywhere; every element reproduces it exactly.
TEST(PrescribedDisplacement, UniformStretchIsExact) {
  for (const char* cell : {"quad4", "tri3", "quad9", "tri6"}) {
    SCOPED_TRACE(cell);
    const ProblemSpec spec =
        parse_problem_string(stretched_block("x = \"0.001*x\"", cell), "t.toml").spec;
    const Model model = build_model(spec);
    const double E = 1000.0, nu = 0.3, exx = 0.001, eyy = -nu / (1.0 - nu) * exx;
    for (const auto method : {ContactMethod::SemismoothNewton, ContactMethod::UzawaGnm}) {
      const ContactResult result = run(model, spec, method);
      ASSERT_TRUE(result.summary.converged()) << result.summary.message;
      EXPECT_EQ(result.summary.num_active, 0);
      const Vector u = model.dofs.expand(result.u);
      for (Index v = 0; v < model.mesh.num_nodes(); ++v) {
        const Point x = model.mesh.point(v);
        EXPECT_NEAR(u(2 * v), exx * x(0), 1e-13) << "node " << v;
        EXPECT_NEAR(u(2 * v + 1), eyy * x(1), 1e-13) << "node " << v;
      }
      // The right side's reaction pulls with sigma_xx times the height; the left one holds it.
      const Resultants r = compute_resultants(model, result.u, result.l);
      const double pull = E / (1.0 - nu * nu) * exx * 1.0;
      ASSERT_EQ(r.reactions.size(), 3U);
      EXPECT_EQ(r.reactions[2].boundary, "right");
      EXPECT_NEAR(r.reactions[2].force(0), pull, 1e-10 * pull);
      EXPECT_NEAR(r.reactions[0].force(0), -pull, 1e-10 * pull);
      EXPECT_NEAR(r.reactions[1].force(1), 0.0, 1e-10 * pull);
      EXPECT_LT(r.relative_balance, 1e-12);
      // The stored energy: 1/2 sigma_xx eps_xx over the 2 x 1 block.
      const double stored = 0.5 * pull * exx * 2.0;
      EXPECT_NEAR(r.strain_energy, stored, 1e-10 * stored);
    }
  }
}

// A body moved rigidly by a prescribed displacement stores no energy, while J of the free
// unknowns (which leaves out the energy of u_D) is negative: the summary reports both.
TEST(PrescribedDisplacement, RigidMotionStoresNoEnergy) {
  const std::string text = block(R"(
[[displacement]]
boundary = "left"
x = 0.01
y = 0.02
)");
  for (const std::string refine : {"8", "16"}) {
    const ProblemSpec spec =
        parse_problem_string(text, "t.toml", {"mesh.nx=" + refine, "mesh.ny=" + refine}).spec;
    const Model model = build_model(spec);
    const ContactResult result = run(model, spec, ContactMethod::SemismoothNewton);
    ASSERT_TRUE(result.summary.converged()) << result.summary.message;
    const Resultants r = compute_resultants(model, result);
    EXPECT_LT(result.summary.energy, 0.0);
    EXPECT_LT(std::abs(r.strain_energy), 1e-12 * std::abs(result.summary.energy))
        << "J = " << result.summary.energy;
  }
}

// On a side parallel to an axis the normal component is that axis's: the same dofs, the same
// values, the same solution.
TEST(PrescribedDisplacement, NormalOnAStraightSideIsItsComponent) {
  const ProblemSpec by_x = parse_problem_string(stretched_block("x = 0.002"), "t.toml").spec;
  const ProblemSpec by_n = parse_problem_string(stretched_block("normal = 0.002"), "t.toml").spec;
  const Model a = build_model(by_x), b = build_model(by_n);
  ASSERT_EQ(a.dofs.num_free(), b.dofs.num_free());
  EXPECT_EQ((a.problem.b - b.problem.b).norm(), 0.0);
  const ContactResult ra = run(a, by_x, ContactMethod::SemismoothNewton);
  const ContactResult rb = run(b, by_n, ContactMethod::SemismoothNewton);
  EXPECT_EQ((a.dofs.expand(ra.u) - b.dofs.expand(rb.u)).norm(), 0.0);
}

TEST(PrescribedDisplacement, ClampsWinAndBadEntriesAreRefused) {
  // The bottom-right corner is held in y by the bottom roller and moved in y by the
  // displacement: the roller wins there, so that node stays at y = 0.
  const ProblemSpec spec =
      parse_problem_string(stretched_block("x = 0.002\ny = -0.001"), "t.toml").spec;
  const Model model = build_model(spec);
  const Index corner = nearest_node(model.mesh, Point(2.0, 0.0, 0.0));
  const Index above = nearest_node(model.mesh, Point(2.0, 0.25, 0.0));
  EXPECT_EQ(model.dofs.value(corner, 1), 0.0);
  EXPECT_EQ(model.dofs.value(corner, 0), 0.002);
  EXPECT_EQ(model.dofs.value(above, 1), -0.001);

  EXPECT_CONTAINS(input_error_of([] {
                    (void)parse_problem_string(stretched_block("x = 0.002\nnormal = 0.001"),
                                               "t.toml");
                  }),
                  "give either normal or the components x and y");
  EXPECT_CONTAINS(input_error_of([] { (void)parse_problem_string(stretched_block(""), "t.toml"); }),
                  "missing required key 'displacement[0].x'");
  EXPECT_CONTAINS(input_error_of([] {
                    (void)parse_problem_string(stretched_block("x = \"1/(x - 2)\""), "t.toml")
                        .spec.displacements[0]
                        .values[0](Point(2.0, 0.0, 0.0));
                  }),
                  "displacement[0].x = '1/(x - 2)' is infinite");
}

// A structured mesh of ni x nj quadrilaterals as a Gmsh 2.2 file `name` in `dir`: node (i, j) at
// point(s, t), s = i / ni, t = j / nj; physical lines sides[0] (i = 0), sides[1] (j = 0),
// sides[2] (i = ni), sides[3] (j = nj), and the surface "body".
template <class Point2>
std::string structured_msh(const testing::TemporaryFolder& dir, const std::string& name, int ni,
                           int nj, const Point2& point, const std::array<const char*, 4>& sides) {
  std::ostringstream out;
  out << "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n5\n";
  for (int k = 0; k < 4; ++k) out << "1 " << k + 1 << " \"" << sides[k] << "\"\n";
  out << "2 5 \"body\"\n$EndPhysicalNames\n$Nodes\n" << (ni + 1) * (nj + 1) << "\n";
  const auto id = [&](int i, int j) { return 1 + i + j * (ni + 1); };
  out.precision(17);
  for (int j = 0; j <= nj; ++j)
    for (int i = 0; i <= ni; ++i) {
      const Eigen::Vector2d x = point(1.0 * i / ni, 1.0 * j / nj);
      out << id(i, j) << " " << x(0) << " " << x(1) << " 0\n";
    }
  out << "$EndNodes\n$Elements\n" << ni * nj + 2 * (ni + nj) << "\n";
  int e = 1;
  for (int j = 0; j < nj; ++j) {
    out << e++ << " 1 2 1 1 " << id(0, j) << " " << id(0, j + 1) << "\n";
    out << e++ << " 1 2 3 3 " << id(ni, j) << " " << id(ni, j + 1) << "\n";
  }
  for (int i = 0; i < ni; ++i) {
    out << e++ << " 1 2 2 2 " << id(i, 0) << " " << id(i + 1, 0) << "\n";
    out << e++ << " 1 2 4 4 " << id(i, nj) << " " << id(i + 1, nj) << "\n";
  }
  for (int j = 0; j < nj; ++j)
    for (int i = 0; i < ni; ++i)
      out << e++ << " 3 2 5 5 " << id(i, j) << " " << id(i + 1, j) << " " << id(i + 1, j + 1) << " "
          << id(i, j + 1) << "\n";
  out << "$EndElements\n";
  const std::string path = (dir / name).string();
  std::ofstream(path) << out.str();
  return path;
}

// The stretched block of UniformStretchIsExact (2 x 1) turned by `angle`: every side inclined.
std::string turned_block_msh(const testing::TemporaryFolder& dir, double angle, int nx, int ny) {
  const double c = std::cos(angle), s = std::sin(angle);
  return structured_msh(
      dir, "turned.msh", nx, ny,
      [&](double u, double v) { return Eigen::Vector2d(c * 2.0 * u - s * v, s * 2.0 * u + c * v); },
      {"left", "bottom", "right", "top"});
}

// The uniform stretch again, turned by 30 degrees: the rollers and the pull are normal
// displacements on inclined sides, held in local axes at each node (the corners by both of their
// sides' normals). The answer is the turned uniform strain, exactly, by every method.
TEST(PrescribedDisplacement, NormalOnInclinedSidesIsExact) {
  const testing::TemporaryFolder dir;
  const double angle = std::numbers::pi / 6.0, c = std::cos(angle), s = std::sin(angle);
  const std::string text = R"(
[mesh]
type = "gmsh"
file = ")" + turned_block_msh(dir, angle, 8, 4) +
                           R"("

[material]
E = 1000.0
nu = 0.3

[[displacement]]
boundary = "left"
normal = 0

[[displacement]]
boundary = "bottom"
normal = 0

[[displacement]]
boundary = "right"
normal = 0.002

[contact]
boundary = "top"
gap = "1"
)";
  const ProblemSpec spec = parse_problem_string(text, "t.toml").spec;
  const Model model = build_model(spec);
  EXPECT_TRUE(model.dofs.has_frames());
  const double E = 1000.0, nu = 0.3, exx = 0.001, eyy = -nu / (1.0 - nu) * exx;
  for (const auto method :
       {ContactMethod::SemismoothNewton, ContactMethod::UzawaGnm, ContactMethod::ClassicalUzawa}) {
    const ContactResult result = run(model, spec, method);
    ASSERT_TRUE(result.summary.converged()) << result.summary.message;
    const Vector u = model.dofs.expand(result.u);
    for (Index v = 0; v < model.mesh.num_nodes(); ++v) {
      const Point x = model.mesh.point(v);
      const double xi = c * x(0) + s * x(1), eta = -s * x(0) + c * x(1);  // the block's axes
      const double u_xi = exx * xi, u_eta = eyy * eta;
      EXPECT_NEAR(u(2 * v), c * u_xi - s * u_eta, 1e-12) << "node " << v;
      EXPECT_NEAR(u(2 * v + 1), s * u_xi + c * u_eta, 1e-12) << "node " << v;
    }
    // The pull of the right side: sigma_xx times the height, along the side's normal. The corner
    // (2, 0) counts for the bottom, the first entry that holds it; the left side holds back.
    const Resultants r = compute_resultants(model, result.u, result.l);
    const double pull = E / (1.0 - nu * nu) * exx;
    ASSERT_EQ(r.reactions.size(), 3U);
    const Eigen::Vector3d right = r.reactions[1].force + r.reactions[2].force;
    EXPECT_NEAR(right(0), pull * c, 1e-9 * pull);
    EXPECT_NEAR(right(1), pull * s, 1e-9 * pull);
    EXPECT_NEAR(r.reactions[0].force(0), -pull * c, 1e-9 * pull);
    EXPECT_NEAR(r.reactions[0].force(1), -pull * s, 1e-9 * pull);
    EXPECT_LT(r.relative_balance, 1e-10);
  }
}

// A quarter of a ring 1 <= r <= 2 (nr x nt quadrilaterals, its nodes on the circles; physical
// lines inner, outer, axis_x, axis_y).
std::string quarter_ring_msh(const testing::TemporaryFolder& dir, int nr, int nt) {
  return structured_msh(dir, "ring.msh", nr, nt,
                        [](double u, double v) {
                          const double r = 1.0 + u, t = std::numbers::pi / 2.0 * v;
                          return Eigen::Vector2d(r * std::cos(t), r * std::sin(t));
                        },
                        {"inner", "axis_x", "outer", "axis_y"});
}

// On a curved part the normal turns from node to node. A quarter ring 1 <= r <= 2 on rollers
// along its cut lines, its outer circle moved by u . n = d, its inner one free (a contact
// boundary far from its obstacle): Lame's solution u_r = A r + B / r with sigma_rr(1) = 0 and
// u_r(2) = d, approached as the mesh is refined.
TEST(PrescribedDisplacement, NormalOnACurvedPartGivesLamesSolution) {
  const testing::TemporaryFolder dir;
  const double E = 1000.0, nu = 0.3, d = -0.002;
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu)), mu = E / (2.0 * (1.0 + nu));
  const double A = d / (2.0 + (lambda + mu) / (2.0 * mu)), B = (lambda + mu) / mu * A;
  std::vector<double> errors;
  for (const int n : {4, 8}) {
    ProblemSpec spec;
    spec.mesh_type = MeshType::Gmsh;
    spec.mesh_file = quarter_ring_msh(dir, 2 * n, 6 * n);
    spec.elasticity.material = {E, nu};
    spec.clamps = {{"axis_x", {false, true, false}}, {"axis_y", {true, false, false}}};
    DisplacementSpec outer;
    outer.boundary = "outer";
    outer.normal = [&](const Point&) { return d; };
    spec.displacements = {outer};
    spec.contacts.resize(1);
    spec.contacts[0].boundary = "inner";
    spec.contacts[0].gap = [](const Point&) { return 1.0; };
    const Model model = build_model(spec);
    EXPECT_TRUE(model.dofs.has_frames());
    const ContactResult result = run(model, spec, ContactMethod::SemismoothNewton);
    ASSERT_TRUE(result.summary.converged()) << result.summary.message;
    const Vector u = model.dofs.expand(result.u);
    double error = 0.0;
    for (Index v = 0; v < model.mesh.num_nodes(); ++v) {
      const Point x = model.mesh.point(v);
      const double r = x.head<2>().norm(), u_r = A * r + B / r;
      error = std::max(error, (u.segment<2>(2 * v) - u_r * x.head<2>() / r).norm());
    }
    errors.push_back(error / std::abs(d));
    // The rollers and the outer circle hold the ring: their reactions balance, the nodes at
    // the ends of the circle (a roller's component and u . n) included.
    const Resultants res = compute_resultants(model, result.u, result.l);
    ASSERT_EQ(res.reactions.size(), 3U);
    EXPECT_LT(res.relative_balance, 1e-10);
    EXPECT_GT(res.reactions[2].force.norm(), 0.0);
    // At every node of the outer circle u . nu_j is d, exactly (at its ends, where a roller holds
    // one component at 0, the other is what u . nu_j = d asks).
    const BoundaryNodes b = boundary_nodes(model.mesh, model.mesh.boundary_part("outer"), "outer");
    for (std::size_t j = 0; j < b.nodes.size(); ++j)
      EXPECT_NEAR(b.normals.col(static_cast<Index>(j)).dot(u.segment<2>(2 * b.nodes[j])), d, 1e-15);
  }
  // Measured: 0.11 % and 0.028 % of d, a ratio of 4.0: second order.
  EXPECT_LT(errors[1], errors[0] / 3.5);
  EXPECT_LT(errors[1], 5e-4);
}

// The load of a pressure p on a straight side is that of the traction -p n.
TEST(Pressure, OnAStraightSideEqualsTheTraction) {
  ProblemSpec traction = paper_benchmark(30, 10);
  ProblemSpec pressure = traction;
  pressure.tractions.pop_back();  // (0, -2/3 (3 - x)) on top, whose outward normal is (0, 1)
  pressure.pressures.push_back(
      {"top", [](const Point& x) { return 2.0 / 3.0 * (3.0 - x(0)); }, "2/3*(3 - x)"});
  const Model a = build_model(traction), b = build_model(pressure);
  EXPECT_LT((a.problem.b - b.problem.b).norm(), 1e-15 * a.problem.b.norm());
}

// On a quarter circle, int n ds is the chord turned, (1, 1) for the unit radius, on any mesh of
// it: a uniform pressure p has the resultant -p (1, 1), on straight and on curved edges.
TEST(Pressure, ResultantOnAQuarterCircle) {
  for (const char* file : {"disc_quarter.msh", "hertz_p2.msh"}) {
    SCOPED_TRACE(file);
    const Mesh mesh = read_gmsh_mesh(std::string(SIGNORINI_EXAMPLES_DIR "/gmsh/") + file);
    Vector f = Vector::Zero(2 * mesh.num_nodes());
    add_pressure_forces(
        mesh, mesh.boundary_part("arc"), [](const Point&) { return 3.0; }, 2, f);
    double fx = 0.0, fy = 0.0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      fx += f(2 * v);
      fy += f(2 * v + 1);
    }
    // The two arcs: the disc's quarter from (1, 0) to (0, 1); Hertz's lower half circle of the
    // cylinder centred at (0, 1), from (1, 1) round to (-1, 1): int n ds = (0, -2).
    const bool hertz = std::string(file) == "hertz_p2.msh";
    EXPECT_NEAR(fx, hertz ? 0.0 : -3.0, 1e-12);
    EXPECT_NEAR(fy, hertz ? 6.0 : -3.0, 1e-12);
  }
}

// The paper's block, also pressed on its right side by a rigid plane that starts 1e-5 inside it:
// two contact boundaries, each with its obstacle, in one contact set. The two methods agree, both
// boundaries carry load, and the forces balance.
TEST(SeveralContacts, BlockBetweenFoundationAndWall) {
  ProblemSpec spec = paper_benchmark(30, 10);
  ContactSpec wall;
  wall.boundary = "right";
  wall.obstacle.shape = ObstacleShape::Plane;
  wall.obstacle.point = Eigen::Vector3d(3.0 - 1e-5, 0.0, 0.0);
  wall.obstacle.normal = Eigen::Vector3d(-1.0, 0.0, 0.0);
  spec.tractions.erase(spec.tractions.begin());  // the right side is the wall's now
  spec.contacts.push_back(wall);
  const Model model = build_model(spec);
  ASSERT_EQ(model.contact_boundaries, (std::vector<std::string>{"bottom", "right"}));
  ASSERT_EQ(model.contact_starts, (std::vector<Index>{0, 31, 42}));
  EXPECT_EQ(model.contact_boundary_of(30), "bottom");
  EXPECT_EQ(model.contact_boundary_of(31), "right");
  const ContactResult ssn = run(model, spec, ContactMethod::SemismoothNewton);
  const ContactResult gnm = run(model, spec, ContactMethod::UzawaGnm);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  ASSERT_TRUE(gnm.summary.converged()) << gnm.summary.message;
  EXPECT_LT(testing::relative_difference(gnm.u, ssn.u), 1e-8);
  EXPECT_LT(testing::relative_difference(gnm.l, ssn.l), 1e-8);
  EXPECT_GT(ssn.l.head(31).maxCoeff(), 0.0);
  EXPECT_GT(ssn.l.tail(11).maxCoeff(), 0.0);
  const Resultants r = compute_resultants(model, ssn.u, ssn.l);
  EXPECT_LT(r.contact(0), 0.0);  // the wall pushes the block to the left
  EXPECT_LT(r.relative_balance, 1e-10);
}

// The effective settings of examples/pressed_block.toml ([[displacement]], [[pressure]], two
// [[contact]] tables) read back to the same discrete problem.
TEST(SeveralContacts, EffectiveSettingsReadBack) {
  const LoadedProblem file =
      read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/pressed_block.toml");
  for (const char* section : {"[[displacement]]", "[[pressure]]", "[[contact]]"})
    EXPECT_NE(file.effective_toml.find(section), std::string::npos) << file.effective_toml;
  const LoadedProblem again = parse_problem_string(file.effective_toml, "effective.toml");
  EXPECT_EQ(again.effective_toml, file.effective_toml);
  const Model a = build_model(file.spec), b = build_model(again.spec);
  EXPECT_EQ((a.problem.b - b.problem.b).norm(), 0.0);
  EXPECT_EQ((a.problem.contact.gaps - b.problem.contact.gaps).norm(), 0.0);
  EXPECT_EQ(a.contact_boundaries, b.contact_boundaries);
}

}  // namespace
}  // namespace signorini

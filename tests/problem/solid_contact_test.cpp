// Contact in 3D, through the same model and solvers as in 2D: a block of each 3D cell type pressed
// onto a rigid half-space by its top, moved down by delta = p H / E, held sideways by rollers on
// two faces. The exact solution is uniaxial compression: u = (nu p/E x, nu p/E y, -p/E z), every
// node of the bottom in contact, sigma_zz = -p; the contact force is p times the bottom's area, and
// the nodal pressures are p where the weights are the integrals of the shape functions (all types
// but tet10, whose corner functions integrate to zero on a face and whose weights are lumped). The
// three methods agree, with small KKT residuals. A ball pressed into a block agrees between the
// methods too.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/tool_run.hpp"
#include "problem/ball_on_block.hpp"
#include "problem/each_method.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/problem/model.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

constexpr double kE = 1000.0, kNu = 0.3, kP = 2.0;
constexpr std::initializer_list<ContactMethod> kAllMethods{
    ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton, ContactMethod::ClassicalUzawa};

ProblemSpec pressed_block(CellType cell) {
  ProblemSpec spec;
  spec.name = "block";
  spec.mesh_type = MeshType::Box;
  spec.box.length = 1.0;
  spec.box.width = 0.8;
  spec.box.height = 0.5;
  spec.box.nx = 4;
  spec.box.ny = 3;
  spec.box.nz = 2;
  spec.box.cell = cell;
  spec.elasticity.material = {kE, kNu};
  spec.clamps = {{"xmin", {true, false, false}}, {"ymin", {false, true, false}}};
  DisplacementSpec top;
  top.boundary = "zmax";
  top.values[2] = [](const Point&) { return -kP * 0.5 / kE; };  // delta = p H / E
  top.texts[2] = "-0.001";
  spec.displacements = {top};
  ContactSpec contact;
  contact.boundary = "zmin";
  contact.obstacle.shape = ObstacleShape::Plane;
  contact.obstacle.point = Eigen::Vector3d::Zero();
  contact.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  spec.contacts = {contact};
  spec.solver.uzawa_tolerance = 1e-12;
  return spec;
}

class SolidContact : public ::testing::TestWithParam<CellType> {};

TEST_P(SolidContact, BlockOnAHalfSpaceIsUniaxialCompression) {
  const ProblemSpec spec = pressed_block(GetParam());
  const Model model = build_model(spec);
  ASSERT_EQ(model.mesh.dim(), 3);
  const ContactSet& c = model.problem.contact;
  EXPECT_NEAR(c.weights.sum(), 1.0 * 0.8, 1e-12);  // the bottom's area
  for (Index j = 0; j < c.size(); ++j)
    EXPECT_LT((c.normals.col(j) - Eigen::Vector3d(0, 0, -1)).norm(), 1e-14);

  std::vector<ContactResult> results;
  ASSERT_NO_FATAL_FAILURE(testing::solve_by_each(model, spec.solver, kAllMethods, results));
  for (const ContactResult& r : results) {
    SCOPED_TRACE(std::string(enum_to_string(kContactMethodNames, r.summary.method)));
    const Vector u = model.dofs.expand(r.u);
    for (Index n = 0; n < model.mesh.num_nodes(); ++n) {
      const Point x = model.mesh.point(n);
      EXPECT_NEAR(u(3 * n), kNu * kP / kE * x(0), 1e-12) << "node " << n;
      EXPECT_NEAR(u(3 * n + 1), kNu * kP / kE * x(1), 1e-12) << "node " << n;
      EXPECT_NEAR(u(3 * n + 2), -kP / kE * x(2), 1e-12) << "node " << n;
    }
    EXPECT_NEAR(r.summary.contact_force, kP * 1.0 * 0.8, 1e-9);
    if (GetParam() != CellType::Tet10) {
      for (Index j = 0; j < c.size(); ++j) EXPECT_NEAR(r.l(j), kP, 1e-8) << "contact node " << j;
    }
    const NodalStress s = nodal_stress(model.mesh, model.elasticity, u);
    for (Index n = 0; n < model.mesh.num_nodes(); ++n) EXPECT_NEAR(s.sigma(2, n), -kP, 1e-9);
  }
  testing::expect_same_solution(results, 1e-8, 1e-8);
}

INSTANTIATE_TEST_SUITE_P(CellTypes, SolidContact,
                         ::testing::Values(CellType::Tet4, CellType::Tet10, CellType::Hex8,
                                           CellType::Hex27),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

// A rigid ball (a sphere obstacle) under a block clamped on its top, a small initial
// interference: only the nodes near the ball's pole touch, and the methods agree on u and l.
TEST(SolidContactBall, BallPressedIntoABlockMethodsAgree) {
  ProblemSpec spec = pressed_block(CellType::Hex8);
  spec.box.nx = 8;
  spec.box.ny = 8;
  spec.box.nz = 4;
  spec.box.width = 1.0;
  spec.displacements.clear();
  spec.clamps = {{"zmax", {true, true, true}}};
  ContactSpec& ball = spec.contacts[0];
  ball.obstacle = RigidObstacle{};
  ball.obstacle.shape = ObstacleShape::Disc;  // a sphere in 3D
  ball.obstacle.radius = 2.0;
  ball.obstacle.centre = Eigen::Vector3d(0.5, 0.5, -2.0 + 2e-3);  // 2e-3 into the block
  const Model model = build_model(spec);
  std::vector<ContactResult> results;
  ASSERT_NO_FATAL_FAILURE(testing::solve_by_each(model, spec.solver, kAllMethods, results));
  for (const ContactResult& r : results) {
    EXPECT_GT(r.summary.num_active, 0);
    EXPECT_LT(r.summary.num_active, model.problem.contact.size());
    EXPECT_EQ(r.summary.num_active, results[0].summary.num_active);
  }
  testing::expect_same_solution(results, 1e-8, 1e-8);
  // The contact zone is round: symmetric about the ball's axis (x = y = 0.5).
  const ContactSet& c = model.problem.contact;
  for (Index j = 0; j < c.size(); ++j) {
    const Point x = model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
    for (Index k = 0; k < c.size(); ++k) {
      const Point y = model.mesh.point(c.nodes[static_cast<std::size_t>(k)]);
      const bool mirrored = std::abs(y(0) - (1.0 - x(0))) < 1e-12 && std::abs(y(1) - x(1)) < 1e-12;
      const bool swapped = std::abs(y(0) - x(1)) < 1e-12 && std::abs(y(1) - x(0)) < 1e-12;
      if (mirrored || swapped) {
        EXPECT_NEAR(results[1].l(j), results[1].l(k), 1e-9 * results[1].l.maxCoeff());
      }
    }
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// The paper's problem extruded: a slab of hex8 cells one cell thick, held by u_z = 0 on both faces
// z = 0 and z = t, loaded and clamped as the 2D problem. Its displacement does not depend on z and
// it is the plane-strain solution: the 3D discrete problem is t times the 2D one (the element
// matrices, loads and contact weights, split between the two faces), so the iterates are the same
// and the Uzawa and GNM counts too.
TEST(SolidContactSlab, ExtrudedPaperProblemIsThePlaneStrainSolution) {
  const Index nx = 30, ny = 10;
  const double t = 0.25;
  const ProblemSpec plane = paper_benchmark(nx, ny);
  ProblemSpec slab = plane;
  slab.mesh_type = MeshType::Box;
  slab.box.length = 3.0;
  slab.box.width = 1.0;
  slab.box.height = t;
  slab.box.nx = nx;
  slab.box.ny = ny;
  slab.box.nz = 1;
  slab.clamps = {
      {"xmin", {true, true, true}}, {"zmin", {false, false, true}}, {"zmax", {false, false, true}}};
  slab.tractions[0].boundary = "xmax";
  slab.tractions[1].boundary = "ymax";
  slab.contacts[0].boundary = "ymin";

  const Model m2 = build_model(plane);
  const Model m3 = build_model(slab);
  const ContactResult r2 = solve_contact(m2.problem, plane.solver);
  const ContactResult r3 = solve_contact(m3.problem, slab.solver);
  ASSERT_TRUE(r2.summary.converged()) << r2.summary.message;
  ASSERT_TRUE(r3.summary.converged()) << r3.summary.message;
  EXPECT_EQ(r3.summary.outer_iterations, r2.summary.outer_iterations);
  EXPECT_EQ(r3.summary.inner_iterations(), r2.summary.inner_iterations());
  EXPECT_NEAR(r3.summary.energy / t, r2.summary.energy, 1e-10 * std::abs(r2.summary.energy));

  const Vector u2 = m2.dofs.expand(r2.u);
  const Vector u3 = m3.dofs.expand(r3.u);
  const Index layer = (nx + 1) * (ny + 1);
  double difference = 0.0;
  for (Index n = 0; n < layer; ++n)
    for (Index k = 0; k < 2; ++k) {
      const Index n3 = n + k * layer;
      ASSERT_LT((m3.mesh.point(n3).head<2>() - m2.mesh.point(n).head<2>()).norm(), 1e-14);
      difference = std::max({difference, std::abs(u3(3 * n3) - u2(2 * n)),
                             std::abs(u3(3 * n3 + 1) - u2(2 * n + 1)), std::abs(u3(3 * n3 + 2))});
    }
  EXPECT_LT(difference, 1e-10 * u2.cwiseAbs().maxCoeff());

  // The contact pressures: both nodes of the slab at x_j carry the 2D node's pressure.
  std::map<Index, double> l2;
  for (Index j = 0; j < m2.problem.contact.size(); ++j)
    l2[m2.problem.contact.nodes[static_cast<std::size_t>(j)]] = r2.l(j);
  ASSERT_EQ(m3.problem.contact.size(), 2 * m2.problem.contact.size());
  for (Index j = 0; j < m3.problem.contact.size(); ++j) {
    const Index n3 = m3.problem.contact.nodes[static_cast<std::size_t>(j)];
    EXPECT_NEAR(r3.l(j), l2.at(n3 % layer), 1e-10 * r2.l.maxCoeff()) << "contact node " << j;
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// The iterative path in 3D: conjugate gradients preconditioned by smoothed-aggregation multigrid
// built on the six rigid-body modes, against the direct (condensed) path, on a ball pressed into
// a block.
TEST(SolidContactPaths, IterativeWithAggregationMultigridAgreesWithDirect) {
  // 3,042 free unknowns: above the 1,000 of the coarsest level
  ProblemSpec spec = testing::ball_on_block(12, 2e-3);
  spec.solver.uzawa_tolerance = 1e-10;
  const ContactResult direct = solve_contact(build_model(spec).problem, spec.solver);
  ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;

  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  const Model model = build_model(spec);
  ASSERT_EQ(model.multigrid.kind, HierarchyKind::Aggregation);
  ASSERT_FALSE(model.multigrid.prolongations.empty());
  const ContactResult cg = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(cg.summary.converged()) << cg.summary.message;
  EXPECT_LT(cg.summary.kkt.max(), 1e-8);
  EXPECT_EQ(cg.summary.num_active, direct.summary.num_active);
  EXPECT_LT((cg.u - direct.u).norm(), 1e-8 * direct.u.norm());
  EXPECT_LT((cg.l - direct.l).norm(), 1e-7 * direct.l.norm());
  int iterations = 0;
  for (const auto& step : cg.summary.steps) iterations += step.linear_iterations;
  EXPECT_GT(iterations, 0);
}

// Semismooth Newton on the iterative path (projected CG with the multigrid of the penalised
// Newton matrix) against semismooth Newton with a sparse factorisation: the same active sets in
// the same order (each Newton step is solved exactly by either), the same u and l, and the KKT
// conditions of the active set exactly; and against Uzawa-GNM on the same path.
TEST(SolidContactPaths, SemismoothNewtonOnTheIterativePathAgreesWithDirect) {
  ProblemSpec spec = testing::ball_on_block(12, 2e-3);
  spec.solver.method = ContactMethod::SemismoothNewton;
  spec.solver.schur_complement = false;
  const ContactResult direct = solve_contact(build_model(spec).problem, spec.solver);
  ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;

  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  const Model model = build_model(spec);
  ASSERT_FALSE(model.multigrid.prolongations.empty());
  const ContactResult cg = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(cg.summary.converged()) << cg.summary.message;
  EXPECT_EQ(cg.summary.path, SolvePath::Backend);
  EXPECT_FALSE(cg.summary.multigrid_levels.empty());
  ASSERT_EQ(cg.summary.steps.size(), direct.summary.steps.size());
  int iterations = 0;  // none in the first step: no load, no active node, x = 0 solves it
  for (std::size_t k = 0; k < cg.summary.steps.size(); ++k) {
    EXPECT_EQ(cg.summary.steps[k].active_set_size, direct.summary.steps[k].active_set_size) << k;
    iterations += cg.summary.steps[k].linear_iterations;
  }
  EXPECT_GT(iterations, 0);
  EXPECT_GT(cg.summary.num_active, 0);
  EXPECT_EQ(cg.summary.num_active, direct.summary.num_active);
  EXPECT_LT((cg.u - direct.u).norm(), 1e-10 * direct.u.norm());
  EXPECT_LT((cg.l - direct.l).norm(), 1e-9 * direct.l.norm());
  EXPECT_LT(cg.summary.kkt.equilibrium, 1e-11);
  EXPECT_LT(cg.summary.kkt.penetration, 1e-11);
  EXPECT_EQ(cg.summary.kkt.sign, 0.0);

  spec.solver.method = ContactMethod::UzawaGnm;
  spec.solver.uzawa_tolerance = 1e-10;
  const ContactResult gnm = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(gnm.summary.converged()) << gnm.summary.message;
  EXPECT_LT((gnm.u - cg.u).norm(), 1e-8 * cg.u.norm());
  EXPECT_LT((gnm.l - cg.l).norm(), 1e-7 * cg.l.norm());
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// Inexact semismooth Newton steps (inner_tolerance = adaptive, as the tool plans the iterative
// path): loose steps until the active set repeats, then exact ones. The same answer as exact
// steps, and on a mesh where CG needs more than a few iterations (22,500 unknowns), fewer of them.
TEST(SolidContactPaths, InexactSemismoothNewtonStepsGiveTheExactAnswer) {
  ProblemSpec spec = testing::ball_on_block(24, 2e-3);
  spec.solver.method = ContactMethod::SemismoothNewton;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  const Model model = build_model(spec);
  const auto cg_iterations = [](const ContactResult& r) {
    int n = 0;
    for (const auto& step : r.summary.steps) n += step.linear_iterations;
    return n;
  };
  const ContactResult exact = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(exact.summary.converged()) << exact.summary.message;
  spec.solver.inner_tolerance = InnerTolerance::Adaptive;
  const ContactResult inexact = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(inexact.summary.converged()) << inexact.summary.message;
  EXPECT_GT(inexact.summary.num_active, 0);
  EXPECT_EQ(inexact.summary.num_active, exact.summary.num_active);
  EXPECT_LT((inexact.u - exact.u).norm(), 1e-10 * exact.u.norm());
  EXPECT_LT((inexact.l - exact.l).norm(), 1e-9 * exact.l.norm());
  EXPECT_LT(inexact.summary.kkt.equilibrium, 1e-11);
  // (round-off: the ball's oblique normals make each active row's N x - g a sum of products)
  EXPECT_LT(inexact.summary.kkt.complementarity, 1e-15);
  EXPECT_LT(cg_iterations(inexact), cg_iterations(exact));
  // The last two steps have the same active set: a loose step, then the exact one.
  const auto& steps = inexact.summary.steps;
  ASSERT_GE(steps.size(), 2U);
  EXPECT_EQ(steps[steps.size() - 1].active_set_size, steps[steps.size() - 2].active_set_size);
}

// The result files of a 3D solve: contact.csv with three coordinates, the normal displacement and
// the tangential displacement vector; contact.vtu with the contact faces; solution.vtu with the
// 3D cells; summary.json. Read back: the block pressed onto a half-space has u_n = 0 and the
// pressure p at every contact node, and the files agree with the solution.
TEST(SolidContactFiles, ResultFilesOfA3DSolve) {
  const ProblemSpec spec = pressed_block(CellType::Hex27);
  const Model model = build_model(spec);
  const ContactResult r = solve_contact(model.problem, spec.solver);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  const testing::TemporaryFolder dir;
  write_results(dir / "out", r, model, spec);

  std::ifstream csv(dir / "out" / "contact.csv");
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z,boundary");
  Index rows = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::stringstream s(line);
    for (std::string v; std::getline(s, v, ',');) f.push_back(v);
    ASSERT_EQ(f.size(), 13U) << line;
    const Point x(std::stod(f[0]), std::stod(f[1]), std::stod(f[2]));
    EXPECT_NEAR(x(2), 0.0, 1e-15);
    EXPECT_NEAR(std::stod(f[3]), 0.0, 1e-14);                   // u_n: in contact
    EXPECT_NEAR(std::stod(f[4]), kNu * kP / kE * x(0), 1e-12);  // u_t = (u_x, u_y, 0)
    EXPECT_NEAR(std::stod(f[5]), kNu * kP / kE * x(1), 1e-12);
    EXPECT_NEAR(std::stod(f[6]), 0.0, 1e-15);
    EXPECT_NEAR(std::stod(f[7]), kP, 1e-8);
    EXPECT_EQ(f[11], "-1");
    EXPECT_EQ(f[12], "zmin");
    ++rows;
  }
  EXPECT_EQ(rows, model.problem.contact.size());

  const std::string contact = testing::read_text(dir / "out" / "contact.vtu");
  // 4 x 3 biquadratic faces (VTK type 28) with 9 x 7 nodes.
  EXPECT_NE(contact.find("NumberOfPoints=\"63\" NumberOfCells=\"12\""), std::string::npos);
  const std::string solution = testing::read_text(dir / "out" / "solution.vtu");
  EXPECT_NE(solution.find(fmt::format("NumberOfPoints=\"{}\" NumberOfCells=\"{}\"",
                                      model.mesh.num_nodes(), model.mesh.num_cells())),
            std::string::npos);
  const nlohmann::json summary =
      nlohmann::json::parse(testing::read_text(dir / "out" / "summary.json"));
  EXPECT_NEAR(summary["contact_force"].get<double>(), kP * 0.8, 1e-9);
  // Pushed up by the half-space: (0, 0, p A).
  ASSERT_EQ(summary["contact_force_vector"].size(), 3U);
  EXPECT_NEAR(summary["contact_force_vector"][2].get<double>(), kP * 0.8, 1e-9);
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// A block on a rigid roller (a cylinder along y): the contact is a strip along the roller's axis,
// the same at every y away from the block's ends, symmetric about x = 0.5; the methods agree.
TEST(SolidContactCylinder, BlockOnARollerMethodsAgree) {
  ProblemSpec spec = pressed_block(CellType::Hex8);
  spec.box.nx = 8;
  spec.box.ny = 6;
  spec.box.nz = 3;
  spec.displacements.clear();
  spec.clamps = {{"zmax", {true, true, true}}};
  RigidObstacle& roller = spec.contacts[0].obstacle;
  roller = RigidObstacle{};
  roller.shape = ObstacleShape::Cylinder;
  roller.radius = 1.0;
  roller.centre = Eigen::Vector3d(0.5, 0.0, -1.0 + 1e-3);  // 1e-3 into the block
  roller.axis = Eigen::Vector3d(0.0, 1.0, 0.0);
  const Model model = build_model(spec);
  std::vector<ContactResult> results;
  ASSERT_NO_FATAL_FAILURE(testing::solve_by_each(
      model, spec.solver, {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton}, results));
  testing::expect_same_solution(results, 1e-8, 1e-7);
  const ContactSet& c = model.problem.contact;
  const Vector& l = results[1].l;
  bool touches_at_the_middle = false;
  for (Index j = 0; j < c.size(); ++j) {
    const Point x = model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
    if (std::abs(x(0) - 0.5) < 1e-12 && l(j) > 0.0) touches_at_the_middle = true;
    if (std::abs(x(0) - 0.5) > 0.3) {
      EXPECT_EQ(l(j), 0.0) << "far from the roller's top line, at x = " << x(0);
    }
    for (Index k = 0; k < c.size(); ++k) {  // mirrored about x = 0.5
      const Point y = model.mesh.point(c.nodes[static_cast<std::size_t>(k)]);
      if (std::abs(y(0) - (1.0 - x(0))) < 1e-12 && std::abs(y(1) - x(1)) < 1e-12) {
        EXPECT_NEAR(l(j), l(k), 1e-9 * l.maxCoeff());
      }
    }
  }
  EXPECT_TRUE(touches_at_the_middle);
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// Local axes per node (a normal displacement on an inclined part) are 2D so far: in 3D the
// entry is refused by name instead of being read with two components.
TEST(SolidContactLimits, NormalDisplacementIsRefusedIn3D) {
  ProblemSpec spec = pressed_block(CellType::Hex8);
  spec.displacements[0].values[2] = {};
  spec.displacements[0].normal = [](const Point&) { return -1e-3; };
  try {
    (void)build_model(spec);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "displacement[0].normal: a normal displacement is supported on 2D meshes only so "
              "far; give the components x, y, z");
  }
}

}  // namespace
}  // namespace signorini

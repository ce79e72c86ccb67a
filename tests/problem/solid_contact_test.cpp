// Contact in 3D, through the same model and solvers as in 2D: a block of each 3D cell type pressed
// onto a rigid half-space by its top, moved down by delta = p H / E, held sideways by rollers on
// two faces. The exact solution is uniaxial compression: u = (nu p/E x, nu p/E y, -p/E z), every
// node of the bottom in contact, sigma_zz = -p; the contact force is p times the bottom's area, and
// the nodal pressures are p where the weights are the integrals of the shape functions (all types
// but tet10, whose corner functions integrate to zero on a face and whose weights are lumped). The
// three methods agree, with small KKT residuals. A ball pressed into a block agrees between the
// methods too.

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

constexpr double kE = 1000.0, kNu = 0.3, kP = 2.0;

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
  for (const ContactMethod method :
       {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton, ContactMethod::ClassicalUzawa}) {
    SCOPED_TRACE(std::string(enum_to_string(kContactMethodNames, method)));
    ContactSolverOptions o = spec.solver;
    o.method = method;
    const ContactResult r = solve_contact(model.problem, o);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(r.summary.kkt.max(), 1e-8);
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
    results.push_back(r);
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_LT((results[i].u - results[0].u).norm(), 1e-8 * results[0].u.norm());
    EXPECT_LT((results[i].l - results[0].l).norm(), 1e-8 * results[0].l.norm());
  }
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
  for (const ContactMethod method :
       {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton, ContactMethod::ClassicalUzawa}) {
    SCOPED_TRACE(std::string(enum_to_string(kContactMethodNames, method)));
    ContactSolverOptions o = spec.solver;
    o.method = method;
    const ContactResult r = solve_contact(model.problem, o);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(r.summary.kkt.max(), 1e-8);
    EXPECT_GT(r.summary.num_active, 0);
    EXPECT_LT(r.summary.num_active, model.problem.contact.size());
    results.push_back(r);
  }
  for (std::size_t i = 1; i < results.size(); ++i) {
    EXPECT_LT((results[i].u - results[0].u).norm(), 1e-8 * results[0].u.norm());
    EXPECT_LT((results[i].l - results[0].l).norm(), 1e-8 * results[0].l.norm());
    EXPECT_EQ(results[i].summary.num_active, results[0].summary.num_active);
  }
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

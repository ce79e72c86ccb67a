// Patch test: a uniform stress state on a mesh of distorted quadrilaterals is reproduced exactly
// (displacements and stresses), for plane strain and plane stress.

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

// The rectangle (0,2)x(0,1) in 6x4 cells with interior nodes moved off the grid; boundary nodes
// stay on their edges so that the edges remain straight.
Mesh distorted_rectangle() {
  const Mesh grid = make_rectangle_mesh({0.0, 0.0, 2.0, 1.0, 6, 4});
  Eigen::MatrixXd xy = grid.coordinates();
  for (Index n = 0; n < grid.num_nodes(); ++n) {
    const double x = xy(0, n), y = xy(1, n);
    const bool interior = x > 1e-12 && x < 2.0 - 1e-12 && y > 1e-12 && y < 1.0 - 1e-12;
    if (interior) {
      xy(0, n) += 0.09 * std::sin(7.0 * x + 3.0 * y);
      xy(1, n) += 0.06 * std::cos(5.0 * x - 4.0 * y);
    }
  }
  std::vector<Index> cells;
  for (Index c = 0; c < grid.num_cells(); ++c)
    for (const Index v : grid.cell(c)) cells.push_back(v);
  Mesh mesh(CellType::Quad4, xy, cells);
  for (const auto& name : grid.boundary_part_names())
    mesh.set_boundary_part(name, grid.boundary_part(name).facets);
  return mesh;
}

class PatchTest : public ::testing::TestWithParam<PlaneModel> {};

TEST_P(PatchTest, UniformUniaxialStressIsExact) {
  const Mesh mesh = distorted_rectangle();
  ElasticityOptions opt;
  opt.material = {1000.0, 0.3};
  opt.plane_model = GetParam();
  // Rollers: u_x = 0 on the left, u_y = 0 on the bottom; traction (sigma, 0) on the right.
  const DofMap dofs =
      make_dof_map(mesh, {{"left", {true, false, false}}, {"bottom", {false, true, false}}});
  const double sigma = 2.5;
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  Vector b = Vector::Zero(dofs.num_free());
  add_traction_load(
      mesh, dofs, mesh.boundary_part("right"),
      [&](const Point&) { return Eigen::Vector3d(sigma, 0.0, 0.0); }, 2, b);
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  Vector u(dofs.num_free());
  solver->solve(b, u);
  const Vector full = dofs.expand(u);

  const double E = opt.material.E, nu = opt.material.nu;
  const bool strain = GetParam() == PlaneModel::PlaneStrain;
  const double exx = strain ? (1.0 - nu * nu) / E * sigma : sigma / E;
  const double eyy = strain ? -nu * (1.0 + nu) / E * sigma : -nu * sigma / E;
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    EXPECT_NEAR(full(2 * n), exx * mesh.node(n)(0), 1e-13) << "node " << n;
    EXPECT_NEAR(full(2 * n + 1), eyy * mesh.node(n)(1), 1e-13) << "node " << n;
  }
  const NodalStress s = nodal_stress(mesh, opt, full);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    EXPECT_NEAR(s.sigma(0, n), sigma, 1e-10);
    EXPECT_NEAR(s.sigma(1, n), 0.0, 1e-10);
    EXPECT_NEAR(s.sigma(2, n), strain ? nu * sigma : 0.0, 1e-10);
    EXPECT_NEAR(s.sigma(3, n), 0.0, 1e-10);
    const double vm = strain ? std::sqrt(sigma * sigma * (1.0 - nu + nu * nu)) : sigma;
    EXPECT_NEAR(s.von_mises(n), vm, 1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(PlaneModels, PatchTest,
                         ::testing::Values(PlaneModel::PlaneStrain, PlaneModel::PlaneStress),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kPlaneModelNames, param_info.param));
                         });

TEST(Assembly, StiffnessIsSymmetricAndLoadsBalance) {
  const Mesh mesh = distorted_rectangle();
  ElasticityOptions opt;
  const DofMap dofs = make_dof_map(mesh, {{"left", {true, true, true}}});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  EXPECT_LT((A - SparseMatrix(A.transpose())).norm(), 1e-12 * A.norm());
  // A linear traction p = (0, -(3 - x)) on the top edge (0,2) integrates exactly with 2 points:
  // total vertical load = -int_0^2 (3 - x) dx = -4, plus nothing clamped on that edge but x = 0.
  const DofMap none = make_dof_map(mesh, {});
  Vector b = Vector::Zero(none.num_free());
  add_traction_load(
      mesh, none, mesh.boundary_part("top"),
      [](const Point& x) { return Eigen::Vector3d(0.0, -(3.0 - x(0)), 0.0); }, 2, b);
  double fy = 0.0, moment = 0.0;
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    fy += b(2 * n + 1);
    moment += b(2 * n + 1) * mesh.node(n)(0);
  }
  EXPECT_NEAR(fy, -4.0, 1e-13);
  EXPECT_NEAR(moment, -(3.0 * 2.0 - 8.0 / 3.0), 1e-13);  // -int_0^2 x (3 - x) dx
}

TEST(Assembly, NonFiniteLoadIsReported) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  const DofMap dofs = make_dof_map(mesh, {{"left", {true, true, true}}});
  Vector b = Vector::Zero(dofs.num_free());
  EXPECT_THROW(
      add_traction_load(
          mesh, dofs, mesh.boundary_part("top"),
          [](const Point& x) { return Eigen::Vector3d(0.0, 1.0 / (x(0) - 0.25), 0.0); }, 1, b),
      InputError);
}

}  // namespace
}  // namespace signorini

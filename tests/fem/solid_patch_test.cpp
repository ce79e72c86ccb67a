// Patch tests in 3D: on a box of distorted cells of each 3D type (curved ones for Tet10 and
// Hex27), a linear displacement prescribed on the boundary is reproduced exactly inside, with its
// uniform stress; and uniaxial tension by a traction (or a pressure) on one face, held by rollers
// on three others, gives the exact displacement (sigma/E x, -nu sigma/E y, -nu sigma/E z).

#include <gtest/gtest.h>

#include <cmath>

#include "fem/uniaxial_tension.hpp"
#include "mesh/moved_mesh.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/material.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

constexpr double kLx = 2.0, kLy = 1.0, kLz = 1.5;

bool on_boundary(const Point& x) {
  const double eps = 1e-12;
  return x(0) < eps || x(0) > kLx - eps || x(1) < eps || x(1) > kLy - eps || x(2) < eps ||
         x(2) > kLz - eps;
}

// The box (0, 2) x (0, 1) x (0, 1.5) in 3 x 2 x 2 cubes of `type` cells, its interior nodes moved
// by a smooth map (half as far for quadratic cells, whose nodes are half as close).
Mesh distorted_box(CellType type) {
  BoxMeshOptions o;
  o.length = kLx;
  o.width = kLy;
  o.height = kLz;
  o.nx = 3;
  o.ny = 2;
  o.nz = 2;
  o.cell = type;
  const Mesh grid = make_box_mesh(o);
  Eigen::MatrixXd xyz = grid.coordinates();
  const double a = 1.0 / cell_order(type);
  for (Index n = 0; n < grid.num_nodes(); ++n) {
    const Point x = grid.point(n);
    if (on_boundary(x)) continue;
    xyz(0, n) += a * 0.08 * std::sin(3.0 * x(0) + 2.0 * x(1) - x(2));
    xyz(1, n) += a * 0.05 * std::cos(2.0 * x(0) - 3.0 * x(1) + x(2));
    xyz(2, n) += a * 0.06 * std::sin(x(0) + x(1) + 2.0 * x(2));
  }
  return testing::with_coordinates(grid, std::move(xyz));
}

class SolidPatchTest : public ::testing::TestWithParam<CellType> {};

TEST_P(SolidPatchTest, LinearDisplacementPrescribedOnTheBoundaryIsExactInside) {
  const Mesh mesh = distorted_box(GetParam());
  ElasticityOptions opt;
  opt.material = {1000.0, 0.3};
  Eigen::Matrix3d G;       // u = G x + c: strain sym(G), a rotation in its skew part
  G << 1e-3, 4e-4, -2e-4,  //
      -1e-4, -5e-4, 3e-4,  //
      6e-4, 1e-4, 8e-4;
  const Eigen::Vector3d c(1e-3, -2e-3, 5e-4);
  DofMap dofs(mesh.num_nodes(), 3);
  for (Index n = 0; n < mesh.num_nodes(); ++n)
    if (on_boundary(mesh.point(n))) {
      const Eigen::Vector3d u = G * mesh.point(n) + c;
      for (int k = 0; k < 3; ++k) dofs.prescribe(n, k, u(k));
    }
  dofs.finalize();
  ASSERT_GT(dofs.num_free(), 0);
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  // b = -K u_D on the free dofs (the lifting of the prescribed values).
  const Vector b = dofs.restrict_to_free(-internal_forces(mesh, opt, dofs.prescribed_values()));
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  Vector x(dofs.num_free());
  solver->solve(b, x);
  const Vector u = dofs.expand(x);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Vector3d exact = G * mesh.point(n) + c;
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(u(3 * n + k), exact(k), 1e-13) << "node " << n;
  }
  // The stress of the strain sym(G), at every node, in VTK's order (xx, yy, zz, xy, yz, xz).
  const Eigen::Matrix3d e = 0.5 * (G + G.transpose());
  Eigen::Matrix<double, 6, 1> voigt;
  voigt << e(0, 0), e(1, 1), e(2, 2), 2 * e(1, 2), 2 * e(0, 2), 2 * e(0, 1);
  const Eigen::Matrix<double, 6, 1> s = elasticity_matrix_3d(opt.material) * voigt;
  const NodalStress stress = nodal_stress(mesh, opt, u);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const Eigen::Matrix<double, 6, 1> expected{s(0), s(1), s(2), s(5), s(3), s(4)};
    EXPECT_LT((stress.sigma.col(n) - expected).norm(), 1e-10 * s.norm()) << "node " << n;
  }
}

TEST_P(SolidPatchTest, UniaxialTensionByATractionOrAPressure) {
  const Mesh mesh = distorted_box(GetParam());
  ElasticityOptions opt;
  opt.material = {1000.0, 0.3};
  const double sigma = 2.5, E = 1000.0, nu = 0.3;
  const DofMap dofs = make_dof_map(mesh, {{"xmin", {true, false, false}},
                                          {"ymin", {false, true, false}},
                                          {"zmin", {false, false, true}}});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  for (const bool pressure : {false, true}) {
    SCOPED_TRACE(pressure ? "pressure -sigma" : "traction (sigma, 0, 0)");
    Vector f = Vector::Zero(dofs.num_dofs());
    if (pressure)
      add_pressure_forces(
          mesh, mesh.boundary_part("xmax"), [&](const Point&) { return -sigma; }, 2, f);
    else
      add_traction_forces(
          mesh, mesh.boundary_part("xmax"),
          [&](const Point&) { return Eigen::Vector3d(sigma, 0.0, 0.0); }, 2, f);
    // The whole load, sigma times the face's area, whatever the face's cells.
    double fx = 0.0;
    for (Index n = 0; n < mesh.num_nodes(); ++n) fx += f(3 * n);
    EXPECT_NEAR(fx, sigma * kLy * kLz, 1e-12);
    Vector x(dofs.num_free());
    solver->solve(dofs.restrict_to_free(f), x);
    const Vector u = dofs.expand(x);
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      const Point p = mesh.point(n);
      EXPECT_NEAR(u(3 * n), sigma / E * p(0), 1e-13) << "node " << n;
      EXPECT_NEAR(u(3 * n + 1), -nu * sigma / E * p(1), 1e-13) << "node " << n;
      EXPECT_NEAR(u(3 * n + 2), -nu * sigma / E * p(2), 1e-13) << "node " << n;
    }
  }
}

TEST_P(SolidPatchTest, BodyForceTotalIsTheVolumeTimesTheForce) {
  const Mesh mesh = distorted_box(GetParam());
  Vector f = Vector::Zero(3 * mesh.num_nodes());
  add_body_forces(
      mesh, [](const Point&) { return Eigen::Vector3d(0.5, -2.0, 3.0); }, 2, f);
  const double volume = kLx * kLy * kLz;
  for (int k = 0; k < 3; ++k) {
    double total = 0.0;
    for (Index n = 0; n < mesh.num_nodes(); ++n) total += f(3 * n + k);
    EXPECT_NEAR(total, volume * Eigen::Vector3d(0.5, -2.0, 3.0)(k), 1e-12) << "component " << k;
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, SolidPatchTest,
                         ::testing::Values(CellType::Tet4, CellType::Tet10, CellType::Hex8,
                                           CellType::Hex27),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

}  // namespace
}  // namespace signorini

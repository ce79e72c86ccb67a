// Convergence under refinement for a linear-elastic problem with a known solution: on the unit
// square, clamped on all edges, u_1 = u_2 = sin(pi x) sin(pi y) with the matching body force.
// First-order elements (P1, Q1) converge at O(h) in the energy norm and O(h^2) in L2, second-order
// ones (P2, Q8, Q2) at O(h^2) and O(h^3).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/isoparametric_element.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

constexpr double kPi = std::numbers::pi;

struct Errors {
  double l2;
  double energy;
};

Errors solve_and_measure(CellType type, Index n) {
  ElasticityOptions opt;
  opt.material = {100.0, 0.3};
  const double E = opt.material.E, nu = opt.material.nu;
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  const double mu = E / (2.0 * (1.0 + nu));
  // f = -div sigma(u) = -(mu Lap u + (lambda + mu) grad div u) for u_1 = u_2 = s.
  const VectorField f = [&](const Point& x) {
    const double s = std::sin(kPi * x(0)) * std::sin(kPi * x(1));
    const double cc = std::cos(kPi * x(0)) * std::cos(kPi * x(1));
    const double v = kPi * kPi * ((lambda + 3.0 * mu) * s - (lambda + mu) * cc);
    return Eigen::Vector3d(v, v, 0.0);
  };
  RectangleMeshOptions o{0.0, 0.0, 1.0, 1.0, n, n};
  o.cell = type;
  const Mesh mesh = make_rectangle_mesh(o);
  const DofMap dofs = make_dof_map(mesh, {{"left"}, {"right"}, {"bottom"}, {"top"}});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  Vector b = Vector::Zero(dofs.num_free());
  add_body_force_load(mesh, dofs, f, 3, b);
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  Vector u(dofs.num_free());
  solver->solve(b, u);
  const Vector full = dofs.expand(u);

  const Eigen::Matrix3d D = plane_elasticity_matrix(opt.material, opt.plane_model);
  double l2 = 0.0, energy = 0.0;
  ShapeValues N;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType t = mesh.cell_type(c);
    const CellCoordinates X = cell_coordinates(mesh, c);
    const auto nodes = mesh.cell(c);
    const auto nn = static_cast<Index>(nodes.size());
    ElementVector ue(2 * nn);
    for (Index a = 0; a < nn; ++a)
      ue.segment<2>(2 * a) = full.segment<2>(2 * nodes[static_cast<std::size_t>(a)]);
    // Errors integrated with more points than the stiffness uses: 4x4 on Q1 cells, the degree-4
    // rule on triangles.
    const CellType rule_type = (t == CellType::Tri3 || t == CellType::Tri6) ? CellType::Tri6 : t;
    for (const QuadraturePoint& q : cell_quadrature(rule_type, 4)) {
      double det_j = 0.0;
      const StrainMatrix B = strain_matrix(t, X, q.xi, det_j);
      shape_functions(t, q.xi, N);
      const Eigen::Vector2d x = X * N;
      const double w = det_j * q.w;
      const double s = std::sin(kPi * x(0)) * std::sin(kPi * x(1));
      const double cx = kPi * std::cos(kPi * x(0)) * std::sin(kPi * x(1));
      const double cy = kPi * std::sin(kPi * x(0)) * std::cos(kPi * x(1));
      Eigen::Vector2d uh = Eigen::Vector2d::Zero();
      for (Index a = 0; a < nn; ++a) uh += N(a) * ue.segment<2>(2 * a);
      l2 += w * ((uh - Eigen::Vector2d(s, s)).squaredNorm());
      const Eigen::Vector3d e = Eigen::Vector3d(cx, cy, cy + cx) - B * ue;
      energy += w * e.dot(D * e);
    }
  }
  return {std::sqrt(l2), std::sqrt(energy)};
}

struct RateCase {
  CellType type;
  int order;
  std::array<Index, 3> meshes;
};

class Convergence : public ::testing::TestWithParam<RateCase> {};

TEST_P(Convergence, EnergyNormOrderPAndL2OrderPPlusOne) {
  const RateCase k = GetParam();
  const Errors e0 = solve_and_measure(k.type, k.meshes[0]);
  const Errors e1 = solve_and_measure(k.type, k.meshes[1]);
  const Errors e2 = solve_and_measure(k.type, k.meshes[2]);
  const double rate_energy = std::log2(e1.energy / e2.energy);
  const double rate_l2 = std::log2(e1.l2 / e2.l2);
  const double p = k.order;
  EXPECT_NEAR(rate_energy, p, 0.06) << e0.energy << " " << e1.energy << " " << e2.energy;
  EXPECT_NEAR(rate_l2, p + 1.0, 0.12) << e0.l2 << " " << e1.l2 << " " << e2.l2;
  EXPECT_GT(std::log2(e0.energy / e1.energy), p - 0.1);
  EXPECT_GT(std::log2(e0.l2 / e1.l2), p + 0.8);
}

INSTANTIATE_TEST_SUITE_P(CellTypes, Convergence,
                         ::testing::Values(RateCase{CellType::Quad4, 1, {8, 16, 32}},
                                           RateCase{CellType::Tri3, 1, {8, 16, 32}},
                                           RateCase{CellType::Quad8, 2, {4, 8, 16}},
                                           RateCase{CellType::Quad9, 2, {4, 8, 16}},
                                           RateCase{CellType::Tri6, 2, {4, 8, 16}}),
                         [](const auto& param_info) {
                           return std::string(
                               enum_to_string(kCellTypeNames, param_info.param.type));
                         });

}  // namespace
}  // namespace signorini

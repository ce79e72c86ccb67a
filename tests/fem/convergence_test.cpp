// Convergence under refinement for a linear-elastic problem with a known solution: on the unit
// square, clamped on all edges, u_1 = u_2 = sin(pi x) sin(pi y) with the matching body force.
// Q1 elements converge at O(h) in the energy norm and O(h^2) in L2.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/q1_element.hpp"
#include "signorini/fem/quadrature.hpp"
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

Errors solve_and_measure(Index n) {
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
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, n, n});
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
  const auto rule = gauss_legendre(4);
  double l2 = 0.0, energy = 0.0;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    Q1Coordinates X;
    Eigen::Matrix<double, 8, 1> ue;
    const auto nodes = mesh.cell(c);
    for (int a = 0; a < 4; ++a) {
      const Index v = nodes[static_cast<std::size_t>(a)];
      X.col(a) = mesh.node(v);
      ue.segment<2>(2 * a) = full.segment<2>(2 * v);
    }
    for (const auto& qx : rule)
      for (const auto& qy : rule) {
        double det_j = 0.0;
        const Q1Strain B = q1_strain_matrix(X, qx.x, qy.x, det_j);
        const Eigen::Vector2d x = X * q1_shape(qx.x, qy.x);
        const double w = det_j * qx.w * qy.w;
        const double s = std::sin(kPi * x(0)) * std::sin(kPi * x(1));
        const double cx = kPi * std::cos(kPi * x(0)) * std::sin(kPi * x(1));
        const double cy = kPi * std::sin(kPi * x(0)) * std::cos(kPi * x(1));
        Eigen::Vector2d uh = Eigen::Vector2d::Zero();
        const Eigen::Vector4d N = q1_shape(qx.x, qy.x);
        for (int a = 0; a < 4; ++a) uh += N(a) * ue.segment<2>(2 * a);
        l2 += w * ((uh - Eigen::Vector2d(s, s)).squaredNorm());
        const Eigen::Vector3d e = Eigen::Vector3d(cx, cy, cy + cx) - B * ue;
        energy += w * e.dot(D * e);
      }
  }
  return {std::sqrt(l2), std::sqrt(energy)};
}

TEST(Convergence, EnergyNormOrderOneAndL2OrderTwo) {
  const Errors e8 = solve_and_measure(8);
  const Errors e16 = solve_and_measure(16);
  const Errors e32 = solve_and_measure(32);
  const double rate_energy = std::log2(e16.energy / e32.energy);
  const double rate_l2 = std::log2(e16.l2 / e32.l2);
  EXPECT_NEAR(rate_energy, 1.0, 0.05) << e8.energy << " " << e16.energy << " " << e32.energy;
  EXPECT_NEAR(rate_l2, 2.0, 0.1) << e8.l2 << " " << e16.l2 << " " << e32.l2;
  EXPECT_GT(std::log2(e8.energy / e16.energy), 0.9);
  EXPECT_GT(std::log2(e8.l2 / e16.l2), 1.8);
}

}  // namespace
}  // namespace signorini

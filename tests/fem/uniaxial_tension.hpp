#pragma once
// The patch tests' load case, for tests in several folders: rollers (u_x = 0 on the boundary
// part "left", u_y = 0 on "bottom") and a uniform traction (sigma, 0) on "right", solved with
// the default linear solver. Returns the full, node-major displacement.

#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::testing {

inline Vector solve_uniaxial_tension(const Mesh& mesh, const ElasticityOptions& options,
                                     double sigma) {
  const DofMap dofs =
      make_dof_map(mesh, {{"left", {true, false, false}}, {"bottom", {false, true, false}}});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, options);  // throws on an inverted cell
  Vector b = Vector::Zero(dofs.num_free());
  add_traction_load(
      mesh, dofs, mesh.boundary_part("right"),
      [&](const Point&) { return Eigen::Vector3d(sigma, 0.0, 0.0); }, 2, b);
  auto solver = make_linear_solver({});
  solver->analyze(A);
  solver->factorize(A);
  Vector u(dofs.num_free());
  solver->solve(b, u);
  return dofs.expand(u);
}

}  // namespace signorini::testing

#pragma once
// Shared fixtures for the tests: the paper's benchmark at small sizes, solved once per size.

#include <Eigen/Eigenvalues>
#include <map>
#include <string>
#include <utility>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/rectangle_hierarchy.hpp"

namespace signorini::testing {

/// The paper's benchmark model on nx x nx/3 cells, built once and cached.
inline const Model& paper_model(Index nx) {
  static std::map<Index, Model> cache;
  auto it = cache.find(nx);
  if (it == cache.end()) it = cache.emplace(nx, build_model(paper_benchmark(nx, nx / 3))).first;
  return it->second;
}

/// The paper's benchmark problem and its geometric multigrid hierarchy (for the multigrid
/// preconditioner, a set-up argument of the solver).
struct ProblemWithHierarchy {
  const ContactProblem& problem;
  MultigridHierarchy multigrid;
};
inline ProblemWithHierarchy paper_problem_with_hierarchy(Index nx) {
  const Model& model = paper_model(nx);
  const ProblemSpec spec = paper_benchmark(nx, nx / 3);
  MultigridHierarchy h;
  h.prolongations = make_rectangle_prolongations(spec.mesh, spec.clamps, model.dofs);
  h.kind = HierarchyKind::Geometric;
  return {model.problem, std::move(h)};
}

/// An elastic block of nx x ny x nz cells of `cell` (E = 1000, nu = 0.3) clamped at its bottom
/// (zmin): its stiffness and rigid-body modes, for the multigrid tests.
struct ClampedBlock {
  Mesh mesh;
  DofMap dofs;
  SparseMatrix A;
  Matrix modes;
};
inline ClampedBlock clamped_block(Index nx, Index ny, Index nz, CellType cell = CellType::Hex8) {
  BoxMeshOptions box;
  box.nx = nx;
  box.ny = ny;
  box.nz = nz;
  box.cell = cell;
  Mesh mesh = make_box_mesh(box);
  ClampSpec bottom;
  bottom.boundary = "zmin";
  DofMap dofs = make_dof_map(mesh, {bottom});
  ElasticityOptions elasticity;
  elasticity.material = {1000.0, 0.3};
  SparseMatrix A = assemble_stiffness(mesh, dofs, elasticity);
  Matrix modes = rigid_body_modes(mesh, dofs);
  return {std::move(mesh), std::move(dofs), std::move(A), std::move(modes)};
}

/// `spec` with every contact boundary given the friction law `model`: Coulomb's coefficient
/// `value`, or Tresca's constant slip bound `value`.
inline ProblemSpec with_friction(ProblemSpec spec, FrictionModel model, double value) {
  for (ContactSpec& c : spec.contacts) {
    c.friction = model;
    if (model == FrictionModel::Coulomb) c.mu = value;
    if (model == FrictionModel::Tresca) {
      c.slip_bound = [value](const Point&) { return value; };
      c.slip_bound_text = std::to_string(value);
    }
  }
  return spec;
}

/// Relative difference ||a - b|| / ||b||.
/// `problem` with `law`, not owned (it must outlive the copy): tests that keep their law on the
/// stack or count its calls.
inline ContactProblem with_law(ContactProblem problem, const ContactLaw& law) {
  problem.law = std::shared_ptr<const ContactLaw>(std::shared_ptr<const ContactLaw>(), &law);
  return problem;
}

inline double relative_difference(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

/// lambda_max(D^-1 M) of a symmetric positive definite M, densely (the eigenvalues of
/// D^-1/2 M D^-1/2): the reference for the Jacobi-scaled Lanczos estimates.
inline double dense_jacobi_lambda_max(const Matrix& M) {
  const Vector s = M.diagonal().cwiseSqrt().cwiseInverse();
  const Matrix scaled = s.asDiagonal() * M * s.asDiagonal();
  return Eigen::SelfAdjointEigenSolver<Matrix>(scaled, Eigen::EigenvaluesOnly)
      .eigenvalues()
      .maxCoeff();
}

}  // namespace signorini::testing

#pragma once
// Semismooth Newton for frictional contact (docs/method.md, "Friction"): the reference solver
// that the friction issue asks for as the independent check of the Uzawa-GNM methods to come.
//
// Unknowns: the displacement x (free dofs) and per contact node the force lambda_j = (normal,
// tangential) in R^d. With B = [N; T] (the normal and tangential rows of each node), W the
// nodal weights and g^ = (g_j, 0), the KKT conditions are
//   A x - b + B^T W lambda = 0,    lambda = P(lambda + c (B x - g^)),
// P the node's projection (friction_projection.hpp): Tresca's or Coulomb's. Newton on them with
// P's generalised derivative D:
//   [ A        B^T W ] [dx     ]     [ A x - b + B^T W lambda ]
//   [ -c D B   I - D ] [dlambda] = - [ lambda - P(z)           ]
// solved by a sparse LU (UMFPACK: the matrix is not symmetric). A node without a free normal
// unknown keeps lambda_j = 0. A frictional law starts from the frictionless solution (the same law
// with zero bounds), and each step is halved until the residual decreases.
//
// It is `solver.method = "semismooth_newton"` for a frictional problem (contact_methods.hpp),
// for small and medium problems (a sparse LU of the whole KKT matrix at each step). The constant c
// decides whether it converges at large friction coefficients: with a tenth of the body's normal
// stiffness per area it solves the paper's strip for Coulomb from mu = 0.3 to 5 on every mesh
// tried (tests/contact/friction_ssn_test.cpp), with the stiffness itself it cycled from mu = 5.

#include <vector>

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/friction_law.hpp"

namespace signorini {

struct FrictionLawSpec {
  FrictionKind kind = FrictionKind::Tresca;
  /// Per contact node: Tresca's slip bound s_j or Coulomb's coefficient mu_j (>= 0).
  Vector bound;
};

struct FrictionSsnOptions {
  int max_iterations = 100;
  /// Converged when ||A x - b + B^T W lambda|| <= tolerance max(||b||, ||B^T W lambda||) and
  /// ||lambda - P(z)|| <= tolerance ||lambda||.
  double tolerance = 1e-12;
  /// Also converged at the rounding floor: a step that kept every node's state and did not
  /// halve the residual, when that is below this (the KKT matrix's factorisation resolves
  /// the residual to a level that grows with the mesh: 2e-12 at 240 x 80 on the paper's strip).
  double floor_tolerance = 1e-9;
  /// The complementarity constant c; 0: a tenth of the body's normal stiffness per area at the
  /// contact nodes (automatic_r(problem, 0.1)).
  double c = 0.0;
};

struct FrictionSsnResult {
  Vector u;               ///< free dofs
  Eigen::MatrixXd force;  ///< d x n_c: lambda_j (normal, then tangential)
  std::vector<bool> in_contact, sliding;
  int iterations = 0;
  double equilibrium = 0.0;  ///< ||A u - b + B^T W lambda|| / ||b||
  double projection = 0.0;   ///< ||lambda - P(z)|| / ||lambda||
  bool converged = false;
  bool at_rounding_floor = false;  ///< converged by FrictionSsnOptions::floor_tolerance
  std::vector<double> history;  ///< max(equilibrium, projection) at each iterate, the start first
};

/// `T`: the tangential rows (interface/contact_tangents.hpp, tangential_operator).
[[nodiscard]] FrictionSsnResult solve_friction_ssn(const ContactProblem& problem,
                                                   const SparseMatrix& T,
                                                   const FrictionLawSpec& law,
                                                   const FrictionSsnOptions& options = {});

/// The same on a frictional problem (its contact set with the tangential rows in N,
/// add_tangential_rows) with a law of d components (FrictionLaw: Tresca's s_j or Coulomb's mu_j per
/// node, ContactLaw::project_node; the slip origin of
/// the set honoured). `u0`, `l0` (d values per node): a start instead of the frictionless
/// solution (empty: that).
[[nodiscard]] FrictionSsnResult solve_friction_ssn(const ContactProblem& frictional,
                                                   const ContactLaw& law,
                                                   const FrictionSsnOptions& options = {},
                                                   const Vector& u0 = {}, const Vector& l0 = {});

}  // namespace signorini

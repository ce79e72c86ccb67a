#pragma once
// The per-node nonlinearity of frictional contact (issue: friction; docs/method.md section 6,
// "Friction"): the projection of a node's shifted multiplier z = (z_n, z_t) (normal, then the
// d - 1 tangential components) onto the admissible contact forces, and its generalised
// derivative, as the unilateral law's max(z_n, 0) and its active set are for frictionless
// contact (contact_law.hpp).
//
//   Tresca, slip bound s >= 0:  P(z) = (max(z_n, 0), proj_{|.| <= s}(z_t))
//   Coulomb, coefficient mu >= 0: P(z) = (max(z_n, 0), proj_{|.| <= mu max(z_n, 0)}(z_t))
//
// where proj onto the ball of radius rho keeps z_t inside it (sticking) and scales it to rho
// outside (sliding, along t = z_t / |z_t|). Their generalised derivatives (the Newton matrices'
// per-node blocks): Tresca's is symmetric, diag(H(z_n), I or (s / |z_t|)(I - t t^T)); Coulomb's
// couples the tangential force to z_n (mu t) when sliding, so it is not symmetric.
//
// FrictionLaw (friction_law.hpp) projects with them; tests/contact/friction_projection_test.cpp.

#include <Eigen/Dense>

#include "signorini/contact/contact_law.hpp"

namespace signorini {

/// A node's contact force and its derivative for one z (NodeProjection: force, derivative,
/// in_contact, sliding), and Tresca's potential.
struct FrictionProjection : NodeProjection {
  /// Tresca only: psi(z) = (|z|^2 - dist(z, K)^2) / 2, K the admissible forces, whose gradient
  /// is P(z): the node's term of the merit function Phi (16) with friction, as max(z, 0)^2 / 2
  /// is without. (Coulomb's K moves with z_n: no such potential; NaN.)
  double potential = 0.0;
};

/// Tresca friction with slip bound `slip_bound` (>= 0): the tangential force is bounded by it
/// whatever the normal force.
[[nodiscard]] FrictionProjection project_tresca(const Eigen::VectorXd& z, double slip_bound);

/// Coulomb friction with coefficient `mu` (>= 0): the tangential force bounded by mu times the
/// normal force.
[[nodiscard]] FrictionProjection project_coulomb(const Eigen::VectorXd& z, double mu);

}  // namespace signorini

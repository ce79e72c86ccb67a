#pragma once
// The resultants of a solution, for checking equilibrium by hand: the total applied load, the
// reaction of each clamp, the force of the foundation, and their balance (zero at equilibrium),
// as forces and as moments about a reference point. In 2D forces are per unit thickness.

#include <string>
#include <vector>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

struct ClampReaction {
  std::string boundary;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();   ///< on the body, from the clamp
  Eigen::Vector3d moment = Eigen::Vector3d::Zero();  ///< about Resultants::reference
};

struct Resultants {
  Eigen::Vector3d reference = Eigen::Vector3d::Zero();  ///< moments are about this point
  Eigen::Vector3d applied = Eigen::Vector3d::Zero();    ///< tractions, body force, point loads
  Eigen::Vector3d applied_moment = Eigen::Vector3d::Zero();
  std::vector<ClampReaction> reactions;               ///< one per [[clamp]] entry
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();  ///< -sum_j h_j l_j nu_j: the foundation's
  Eigen::Vector3d contact_moment = Eigen::Vector3d::Zero();
  /// applied + reactions + contact: zero at equilibrium, up to the solve's residual.
  Eigen::Vector3d balance = Eigen::Vector3d::Zero();
  Eigen::Vector3d moment_balance = Eigen::Vector3d::Zero();
  /// |balance| / (|applied| + sum |reactions| + |contact|), and likewise for the moments (with
  /// at least the forces times the body's size, from the reference point, as their scale).
  double relative_balance = 0.0;
  double relative_moment_balance = 0.0;
  /// 1/2 u . K u over every dof of the whole displacement (prescribed values included): the
  /// elastic energy stored in the body, 0 for a rigid motion. J(u) of the summary (1/2 x.Ax -
  /// b.x over the free unknowns) differs from it where displacements are prescribed.
  double strain_energy = 0.0;
};

/// The resultants of the displacement u (free dofs) and contact pressure l of `model`. The
/// reactions are (K u - f - c) at the clamped dofs, f the applied loads and c the contact forces,
/// with K u formed cell by cell (fem/elasticity_assembly.hpp internal_forces). With friction,
/// `tangential` (ContactResult::tangential) adds the tangential contact forces.
Resultants compute_resultants(const Model& model, const Vector& u, const Vector& l,
                              const Matrix& tangential = {}, double load_factor = 1.0,
                              int load_step = 0);
/// The resultants of a solution (its tangential forces and load factor included).
Resultants compute_resultants(const Model& model, const ContactResult& result);

/// A few lines for a terminal: the applied load, each reaction, the contact force, the balance.
std::string resultants_report(const Resultants& r, int dim);

}  // namespace signorini

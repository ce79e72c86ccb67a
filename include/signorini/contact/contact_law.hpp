#pragma once
// The contact law: the per-node nonlinearity of the modified Lagrangian, kept apart from the loops
// that use it. For a node j with shifted multiplier z_j = l_j + r ((N x)_j - g_j) (method.md
// section 2) a law gives
//   - the projection P(z), which is the multiplier update of Uzawa's step (ii) (13), the contact
//     force h P(z) in the gradient G of (16), and the classical Uzawa update;
//   - the generalised derivative of P (whether the node is active), which makes the Newton
//     matrix H = A + r N^T diag(h on the active set) N of (17);
//   - the change P(z0 + dz)^2 - P(z0)^2 of the penalty term of Phi (16) and M (10), without
//     cancellation, for the Armijo rule and the reported M.
// Frictionless unilateral contact (the paper's) has P(z) = max(z, 0). Friction laws (Tresca,
// Coulomb) project a normal-and-tangential z onto their admissible set instead: they are
// ContactLaw classes with more components per node (friction_law.hpp), not new loops.
//
// A law holds all of its behaviour behind these virtual functions, and the problem owns it
// (ContactProblem::law): the loops never ask which law they have. The geometry the law acts on
// (which nodes, their constraint rows N, gaps and weights) is the contact interface's
// (interface/contact_set.hpp).

#include <Eigen/Dense>
#include <string_view>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

/// Which contact nodes are active: the generalised derivative of P is 1 there (method.md
/// section 4).
using ActiveSet = std::vector<bool>;

/// The generalised derivative of P at z, which makes the Newton matrix of (17). For a law with
/// one component per node it is the active set alone. A frictional law (m components per node)
/// adds, per node j, D_j = dP/dz (m x m, column-major) and the offset c_j = P(z_j) - D_j z_j
/// of P's linearisation; `active` then says which nodes are in contact (z_n > 0).
struct Linearization {
  ActiveSet active;
  std::vector<double> blocks;   ///< m^2 per node; empty for one component
  std::vector<double> offsets;  ///< m per node; empty for one component
  /// Where every D_j is diagonal with entries 0 and 1 (friction in 2D: a node sticks or slides
  /// along its one tangent), the rows of N whose entry is 1: H = A + r sum over these rows of
  /// h b b^T, as for the frictionless law, so that the sparse systems can update their factor
  /// row by row. Empty otherwise.
  ActiveSet rows;
  bool operator==(const Linearization&) const = default;
};

/// One node's projection: P(z_j) and a generalised derivative D_j = dP/dz (m x m).
struct NodeProjection {
  Eigen::VectorXd force;       ///< P(z_j): the normal force, then the tangential ones
  Eigen::MatrixXd derivative;  ///< D_j
  bool in_contact = false;     ///< z_n > 0
  bool sliding = false;        ///< friction: z_t at or beyond the slip bound
};

/// The largest violations of a law's conditions over the movable nodes, unscaled
/// (kkt_residuals.hpp scales them into KktResiduals): the gap residual (N u - g)_n > 0, a negative
/// pressure, |l_n (N u - g)_n|, and with friction a tangential force above its bound and slip
/// against the tangential force (s |v| - l_t . v).
struct LawViolations {
  double penetration = 0.0, sign = 0.0, complementarity = 0.0, friction_bound = 0.0, slip = 0.0;
};

class ContactLaw {
 public:
  virtual ~ContactLaw() = default;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Values per contact node in z and l: 1 for frictionless laws, d for frictional ones
  /// (friction_law.hpp), whose contact sets have d rows of N per node.
  [[nodiscard]] virtual int components() const { return 1; }
  /// P(z_j) for every node; a non-finite z_j (a node that cannot move, method.md section 4) gives
  /// 0.
  [[nodiscard]] virtual Vector project(const Vector& z) const = 0;
  /// Where the generalised derivative of P is 1.
  [[nodiscard]] virtual ActiveSet active_set(const Vector& z) const = 0;
  /// P(z0 + dz)^2 - P(z0)^2 for one node, evaluated without cancellation where both are active
  /// (as dz (z0 + z1)).
  [[nodiscard]] virtual double penalty_change(double z0, double dz) const = 0;
  /// The contact nodes the law has parameters for (bounds, coefficients); -1: any number.
  [[nodiscard]] virtual Index nodes() const { return -1; }
  /// Whether some node has friction (a nonzero slip bound or coefficient).
  [[nodiscard]] virtual bool has_friction() const { return false; }
  /// The tangential traction at which each node slides, at multipliers l (components() values
  /// per node): what tells a sliding node from a sticking one in the results
  /// (friction_law.hpp, friction_states). Empty for a law of one component, which has no
  /// tangential rows.
  [[nodiscard]] virtual Vector slip_bounds(const Vector& /*l*/) const { return {}; }

  // Step (i) of Uzawa minimises Phi (16) with what the law holds fixed at the multipliers l of
  // the step: Coulomb's slip bound mu (l_n)_+, so that Phi is convex (method.md, "Friction").
  // A law of z alone holds nothing: its step functions are the law's own.

  /// The per-node parameters step (i) holds fixed at multipliers l; empty for a law of z alone.
  [[nodiscard]] virtual Vector step_parameters(const Vector& /*l*/) const { return {}; }
  /// P(z) with those parameters: the projection whose gradient potential is Phi's penalty term.
  [[nodiscard]] virtual Vector step_project(const Vector& z, const Vector& /*parameters*/) const {
    return project(z);
  }
  /// Its generalised derivative at z (the Newton matrix of (17)); nodes that are not `movable`
  /// stay inactive with D_j = 0.
  [[nodiscard]] virtual Linearization step_linearize(const Vector& z, const Vector& /*parameters*/,
                                                     const std::vector<bool>& /*movable*/) const {
    return {active_set(z), {}, {}, {}};
  }
  /// psi(z0 + dz) - psi(z0) for node j (m values at z0 and dz), psi the potential whose gradient
  /// is step_project (max(z, 0)^2 / 2 for the unilateral law), without cancellation.
  [[nodiscard]] virtual double potential_change(Index /*j*/, const double* z0, const double* dz,
                                                const Vector& /*parameters*/) const {
    return 0.5 * penalty_change(z0[0], dz[0]);
  }

  /// Node j's P(z_j) and its generalised derivative with the law's own parameters (semismooth
  /// Newton's complementarity function).
  [[nodiscard]] virtual NodeProjection project_node(Index j, const Eigen::VectorXd& zj) const;
  /// The violations of the law's conditions at multipliers l (m per node) and constraint rows
  /// N u - g^ (m per node), over the `movable` nodes.
  [[nodiscard]] virtual LawViolations violations(const Vector& l, const Vector& rows,
                                                 const std::vector<bool>& movable) const;
};

/// P(z) = max(z, 0): frictionless unilateral (Signorini) contact.
class UnilateralContactLaw final : public ContactLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "unilateral"; }
  [[nodiscard]] Vector project(const Vector& z) const override;
  [[nodiscard]] ActiveSet active_set(const Vector& z) const override;
  [[nodiscard]] double penalty_change(double z0, double dz) const override;
};

/// The law of the paper's problem, shared (it has no state).
const ContactLaw& unilateral_contact_law();

}  // namespace signorini

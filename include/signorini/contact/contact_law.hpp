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

#pragma once
// Frictional contact laws (docs/method.md, "Friction"): Tresca's and Coulomb's, as ContactLaw
// classes with d components per contact node (the normal, then the d - 1 tangential ones), so
// that the one Uzawa-GNM loop solves them (contact laws, not new loops).
//
// A frictional problem's contact set has d rows per node in N (ContactSet::components = d):
// row d j is node j's normal, rows d j + 1 .. its tangents (add_tangential_rows). The
// multipliers l and the shifted multipliers z = l + r (N x - g^), g^ = (g_j, 0, ..), are then
// d values per node, and the law projects each node's z_j onto its admissible forces
// (friction_projection.hpp):
//   Tresca, slip bound s_j >= 0:       P(z) = (max(z_n, 0), proj_{|.| <= s_j}(z_t))
//   Coulomb, coefficient mu_j >= 0:    the same with s_j = mu_j times the normal pressure.
// For Uzawa-GNM, Coulomb's bound is taken from the multipliers of the Uzawa step, s_j =
// mu_j (l_n)_j, so that each step (i) minimises a Tresca Phi (convex, its Newton matrix
// symmetric) and step (ii) updates the bound with the pressure: the fixed point of Tresca
// problems carried out inside the Uzawa loop (method.md, "Friction").

#include <string_view>
#include <vector>

#include "signorini/contact/contact_law.hpp"
#include "signorini/core/enum_names.hpp"
#include "signorini/interface/contact_set.hpp"

namespace signorini {

enum class FrictionKind { Tresca, Coulomb };

class FrictionLaw final : public ContactLaw {
 public:
  /// One law for every node: `dim` 2 or 3; `bound` per contact node, Tresca's slip bound s_j or
  /// Coulomb's mu_j, finite and >= 0 (std::invalid_argument otherwise).
  FrictionLaw(FrictionKind kind, int dim, Vector bound);
  /// A law per node (contact boundaries with different laws): Tresca's s_j where mu_j = 0,
  /// Coulomb's mu_j where s_j = 0 (a frictionless node has both 0; not both positive).
  /// `kinds`: the laws the problem states (Tresca with s = 0 is still Tresca), for name();
  /// empty: read from which of s and mu has a positive value.
  FrictionLaw(int dim, Vector slip_bound, Vector mu, std::vector<FrictionKind> kinds = {});

  /// "tresca", "coulomb", or "tresca and coulomb" for a mixture: the laws stated (or, where none
  /// were, those with a positive bound; "coulomb" when neither has).
  [[nodiscard]] std::string_view name() const override;
  [[nodiscard]] int components() const override { return dim_; }
  [[nodiscard]] Index size() const { return s_.size(); }
  [[nodiscard]] const Vector& slip_bound() const { return s_; }
  [[nodiscard]] const Vector& mu() const { return mu_; }

  /// The slip bounds that step (i) of Uzawa uses with multipliers l (d per node):
  /// s_j + mu_j max(l_n, 0), Tresca's own or Coulomb's with the pressure of l.
  [[nodiscard]] Vector slip_bounds(const Vector& l) const override;

  /// P(z) node by node with Coulomb's true radius mu_j max(z_n, 0) (classical Uzawa's update and
  /// the KKT check); non-finite components give 0.
  [[nodiscard]] Vector project(const Vector& z) const override;
  /// Per node: z_n > 0.
  [[nodiscard]] ActiveSet active_set(const Vector& z) const override;
  /// Scalar laws only: throws std::logic_error.
  [[nodiscard]] double penalty_change(double z0, double dz) const override;
  [[nodiscard]] Index nodes() const override { return size(); }
  /// Some node has a positive slip bound or coefficient.
  [[nodiscard]] bool has_friction() const override;

  /// Step (i): the slip bounds slip_bounds(l), Coulomb's from the pressure of l.
  [[nodiscard]] Vector step_parameters(const Vector& l) const override { return slip_bounds(l); }
  /// Tresca's projection with the step's bounds, node by node; non-finite nodes give 0.
  [[nodiscard]] Vector step_project(const Vector& z, const Vector& bounds) const override;
  /// Tresca's derivative blocks and offsets with the step's bounds; in 2D also the rows of N
  /// that the blocks select (Linearization::rows).
  [[nodiscard]] Linearization step_linearize(const Vector& z, const Vector& bounds,
                                             const std::vector<bool>& movable) const override;
  /// Tresca's psi with node j's bound: |z_t|^2 / 2 inside the ball, s |z_t| - s^2 / 2 outside,
  /// plus max(z_n, 0)^2 / 2.
  [[nodiscard]] double potential_change(Index j, const double* z0, const double* dz,
                                        const Vector& bounds) const override;
  /// Coulomb's projection (true radius mu_j max(z_n, 0)) where mu_j > 0, Tresca's elsewhere.
  [[nodiscard]] NodeProjection project_node(Index j, const Eigen::VectorXd& zj) const override;
  /// Adds the tangential conditions: |l_t| <= s_j (friction_bound) and s_j |v| - l_t . v = 0
  /// for the slip v (slip), with s_j = slip_bounds(l).
  [[nodiscard]] LawViolations violations(const Vector& l, const Vector& rows,
                                         const std::vector<bool>& movable) const override;

 private:
  int dim_;
  Vector s_, mu_;
  bool tresca_ = false, coulomb_ = false;  // the laws stated, for name()
};

/// What a contact node does at a frictional solution.
enum class FrictionState { Separated, Sticking, Sliding };

inline constexpr EnumNames<FrictionState, 3> kFrictionStateNames{{
    {FrictionState::Separated, "separated"},
    {FrictionState::Sticking, "sticking"},
    {FrictionState::Sliding, "sliding"},
}};

/// Per node from the pressure l_n and the tangential multipliers l_t (ContactResult::l and
/// ::tangential): separated where l_n = 0 (Tresca's bound holds on the whole contact part, so a
/// separated node may still carry a tangential traction up to it: method.md, "Friction"); of
/// the nodes in contact, sliding where |l_t| reaches the slip bound (to 1e-6 relative, above the
/// solver's tolerances; a zero bound slides freely), sticking otherwise.
/// `law`: the problem's law, with tangential rows (components() > 1: a friction law).
[[nodiscard]] std::vector<FrictionState> friction_states(const ContactLaw& law,
                                                         const Vector& pressure,
                                                         const Matrix& tangential);

/// Nodes with a positive normal multiplier in l, `components` values per node (the layout of
/// the methods: the normal first).
[[nodiscard]] Index count_in_contact(const Vector& l, Index components);

/// The methods' layout, d values per node (the normal, then the tangents), from a pressure per
/// node and the tangential multipliers ((d - 1) x nodes, ContactResult::tangential).
[[nodiscard]] Vector node_multipliers(const Vector& pressure, const Matrix& tangential);

}  // namespace signorini

#pragma once
// The discrete contact boundary (method.md section 3) as the solvers see it: contact nodes P,
// their outward unit normals nu_j, nodal quadrature weights h_j and gaps g_j, and the sparse
// operator N with (N x)_j = (x . nu)_j over the free dofs of node j, and, with friction, the
// tangential rows: the constraint rows of a contact interface. Pure algebra: it is built from a
// mesh (interface/contact_boundary.hpp), or by hand. The law that acts on these rows (frictionless,
// Tresca, Coulomb: contact/contact_law.hpp) is kept apart.

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

/// What the constraint rows of an interface touch, which decides where they can be solved
/// (contact/method_table.hpp).
enum class InterfaceKind {
  /// Each row on the free dofs of its own node: a body against a rigid obstacle.
  Obstacle,
  /// Rows that also touch the dofs of other nodes, of the same body or of another: a node of
  /// one body against its partner's face (contact between deformable bodies).
  BetweenBodies,
};

struct ContactSet {
  std::vector<Index> nodes;  ///< mesh node numbers, in order along the boundary part
  Eigen::MatrixXd normals;   ///< dim x size(): outward unit normal nu_j
  /// h_j = int N_j ds over the contact facets: half the lengths of the straight two-node facets
  /// that touch node j; on quadratic facets the integrals of the quadratic shape functions.
  Vector weights;
  Vector gaps;  ///< g_j = g(x_j), the initial gap to the foundation
  /// size() x num_free; (components size()) x num_free with friction. Row j holds the
  /// components of nu_j on node j's free dofs, and (BetweenBodies) minus their combination on
  /// the partner's dofs: (N x)_j is then the normal displacement of node j relative to its
  /// partner.
  SparseMatrix N;
  /// Rows of N per node: 1 (the normal), or d for frictional contact, where rows d j + 1 ..
  /// are node j's tangential directions (add_tangential_rows below).
  int components = 1;
  /// Frictional contact only: (d - 1) values per node, the tangential displacement (T x)_j from
  /// which slip is measured (the previous load step's); empty: 0.
  Vector slip_origin;
  /// false where node j has no free unknown in its normal direction (clamped): its multiplier is
  /// kept at 0 (method.md section 4, last paragraph).
  std::vector<bool> movable;
  /// The contact facets, each as the positions j (in `nodes`) of its nodes (two ends, then the
  /// middle node of a quadratic facet): what the result
  /// files draw (contact.vtu). Empty for a contact set made by hand without facets.
  std::vector<std::vector<Index>> facets;

  /// Obstacle unless a row touches other nodes' dofs than its own (set by whoever makes such
  /// rows; append_contact_set keeps BetweenBodies). Row j is still node j's: its normal, weight
  /// and gap, and its multipliers, are those of `nodes[j]`.
  InterfaceKind kind = InterfaceKind::Obstacle;

  [[nodiscard]] Index size() const { return static_cast<Index>(nodes.size()); }
  [[nodiscard]] Index num_movable() const;
};

/// B = [N; T] node by node: row d j is N's row j, rows d j + 1 .. d j + d - 1 the tangential
/// rows (d - 1) j .. of T (interface/contact_tangents.hpp). Sets contact.components = d. Throws
/// InputError when T does not have (d - 1) rows per node over N's columns.
void add_tangential_rows(ContactSet& contact, const SparseMatrix& T);

/// g^ per row of N: g_j on the normal rows, the slip origin (0 by default) on the tangential
/// rows, so that the constraint rows read N x - g^ (the gaps alone for a frictionless set).
[[nodiscard]] Vector row_offsets(const ContactSet& contact);

/// h per row of N: node j's weight on each of its rows (the weights alone for a frictionless
/// set).
[[nodiscard]] Vector row_weights(const ContactSet& contact);

/// The normal rows of a frictional N (rows d j): the frictionless N of the same set.
[[nodiscard]] SparseMatrix normal_rows(const ContactSet& contact);

}  // namespace signorini

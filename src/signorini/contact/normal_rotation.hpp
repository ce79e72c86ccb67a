#pragma once
// A change of the free dofs of the contact nodes that makes each node's normal displacement one
// unknown: (N x)_j = s_j y_{a_j} with x = Q y. Where nu_j has a single nonzero component over the
// node's free dofs (an edge along an axis), that dof is taken as it is with s_j the signed
// component; elsewhere a Householder reflection Q_j on the node's free dofs, whose first column
// is nu_j restricted to them and normalised, with s_j the norm of that restriction. Used by the
// condensation onto the contact boundary and by the semismooth Newton solver, which both need the
// normal displacement as a single unknown.

#include <vector>

#include "signorini/interface/contact_set.hpp"

namespace signorini {

struct NormalRotation {
  SparseMatrix Q;                          ///< block-diagonal and symmetric; empty when Q = I
  std::vector<Index> normal_dof;           ///< per contact node: a_j, or -1 if not movable
  Vector scale;                            ///< s_j per contact node (0 if not movable)
  std::vector<std::vector<Index>> blocks;  ///< free dofs of each rotated node
  [[nodiscard]] bool identity() const { return Q.rows() == 0; }
  /// Q^T v (or v when Q = I).
  [[nodiscard]] Vector to_rotated(const Vector& v) const;
  /// Q y (or y when Q = I).
  [[nodiscard]] Vector from_rotated(const Vector& y) const;
};

/// Throws InputError where two movable rows share a free dof (a node in two contact parts, as a
/// corner against two obstacles; rows between bodies whose partners share a node): one unknown
/// per row cannot then be had by a rotation. Rows between bodies that share no dof (matching
/// nodes) are rotated on the dofs of both of their nodes.
NormalRotation make_normal_rotation(const ContactSet& contact, Index num_free);

/// Whether two movable rows of the contact set touch the same free dof.
[[nodiscard]] bool rows_share_dofs(const ContactSet& contact);

/// Q^T A Q, computed in place on a copy of A where the node blocks allow it (A itself when Q = I).
/// A may hold only the columns [first_column, first_column + A.cols()) (a partitioned problem's
/// A, ContactProblem::column_of; each node's unknowns in one such range), and so does the result.
SparseMatrix rotate_matrix(const SparseMatrix& A, const NormalRotation& rotation,
                           Index first_column = 0);

}  // namespace signorini

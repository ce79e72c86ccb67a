#pragma once
// The discrete contact boundary (method.md section 3) as the solvers see it: contact nodes P,
// their outward unit normals nu_j, nodal quadrature weights h_j and gaps g_j, and the sparse
// operator N with (N x)_j = (x . nu)_j over the free dofs of node j. Pure algebra: it is built
// from a mesh in fem/ (fem/contact_boundary.hpp), or by hand.

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

struct ContactSet {
  std::vector<Index> nodes;  ///< mesh node numbers, in order along the boundary part
  Eigen::MatrixXd normals;   ///< dim x size(): outward unit normal nu_j
  /// h_j = int N_j ds over the contact facets: half the lengths of the straight two-node facets
  /// that touch node j; on quadratic facets the integrals of the quadratic shape functions.
  Vector weights;
  Vector gaps;     ///< g_j = g(x_j), the initial gap to the foundation
  SparseMatrix N;  ///< size() x num_free; (components size()) x num_free with friction
  /// Rows of N per node: 1 (the normal), or d for frictional contact, where rows d j + 1 ..
  /// are node j's tangential directions (contact/friction_law.hpp, add_tangential_rows).
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

  [[nodiscard]] Index size() const { return static_cast<Index>(nodes.size()); }
  [[nodiscard]] Index num_movable() const;
};

}  // namespace signorini

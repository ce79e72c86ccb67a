#pragma once
// The discrete contact problem (14) in the free dofs: minimise 1/2 <A x, x> - <b, x> subject to
// (N x)_j <= g_j for the contact nodes j.

#include <vector>

#include "signorini/contact/contact_set.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

struct ContactProblem {
  SparseMatrix A;  ///< reduced stiffness, SPD, both triangles stored
  Vector b;        ///< load vector
  ContactSet contact;
  /// Multigrid transfer operators, finest first: prolongations[l] interpolates level l+1 onto
  /// level l (free dofs). Empty unless a multigrid preconditioner was asked for: from the mesh
  /// (problem/rectangle_hierarchy.hpp) or from A (iterative/smoothed_aggregation.hpp).
  std::vector<SparseMatrix> prolongations;
  /// The matrices of the coarse levels when the coarsening already formed them (aggregation);
  /// empty: the multigrid preconditioner forms them (Galerkin products).
  std::vector<SparseMatrix> coarse_operators;
  HierarchyKind hierarchy = HierarchyKind::None;  ///< how the levels were made
};

}  // namespace signorini

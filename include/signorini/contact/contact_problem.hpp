#pragma once
// The discrete contact problem (14) in the free dofs: minimise 1/2 <A x, x> - <b, x> subject to
// (N x)_j <= g_j for the contact nodes j.

#include <vector>

#include "signorini/contact/contact_set.hpp"

namespace signorini {

struct ContactProblem {
  SparseMatrix A;  ///< reduced stiffness, SPD, both triangles stored
  Vector b;        ///< load vector
  ContactSet contact;
  /// Optional aids for a distributed solve (docs/distributed.md), empty unless build_model plans
  /// one: the near-null space of A for algebraic multigrid (the rigid-body modes on the free
  /// dofs, n x 3 in 2D, n x 6 in 3D), and the mesh node of each free dof, so that the dofs of a
  /// node stay on one rank.
  Matrix near_null_space = {};
  std::vector<Index> node_of_unknown = {};
  /// Non-empty for a partitioned problem (docs/distributed.md): rank r of a distributed run owns
  /// the free dofs [row_starts[r], row_starts[r + 1]), and A holds only their columns (by
  /// symmetry their rows), the other columns empty; products with A are then sums over the
  /// ranks (parallel/distributed_engine.hpp, stiffness_product). Only the distributed path
  /// solves such a problem.
  std::vector<Index> row_starts = {};

  [[nodiscard]] bool partitioned() const { return !row_starts.empty(); }
};

}  // namespace signorini

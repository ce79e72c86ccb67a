#pragma once
// The sparsity pattern of a nodal finite-element matrix in the free dofs, built from the mesh
// connectivity (dof (m, k) couples with every free dof of the nodes that share a cell with m), and
// the positions of each cell's entries in it, so that assembly adds element matrices in place
// instead of sorting triplets.

#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

class SparsityPattern {
 public:
  SparsityPattern(const Mesh& mesh, const DofMap& dofs);

  /// A compressed matrix with this pattern and zero values.
  [[nodiscard]] SparseMatrix zero_matrix() const;
  /// The positions of the whole dim x dim block coupling node_a (rows) and node_b (columns):
  /// out[ka * dim + kb], -1 for clamped components.
  void block_positions(Index node_a, Index node_b, Index* out) const;

 private:
  const DofMap& dofs_;
  std::vector<Index> neighbor_start_;  // CSR over nodes: neighbours (sorted), incl. the node
  std::vector<Index> neighbors_;
  std::vector<Index> row_offset_;  // per neighbour entry: rows before it in the column
  std::vector<int> outer_;         // column pointers over free dofs
  std::vector<int> inner_;
};

}  // namespace signorini

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
  /// `columns_of` (optional, one flag per node): the columns of only these nodes are filled, the
  /// others left empty (a distributed run's part of the symmetric matrix: docs/distributed.md).
  SparsityPattern(const Mesh& mesh, const DofMap& dofs,
                  const std::vector<bool>* columns_of = nullptr);

  /// The compressed matrix with this pattern and zero values, handed over once (the pattern
  /// keeps what block_positions needs, not a second copy of the row numbers).
  [[nodiscard]] SparseMatrix take_zero_matrix();
  /// The positions of the whole dim x dim block coupling node_a (rows) and node_b (columns):
  /// out[ka * dim + kb], -1 for clamped components and for columns left empty.
  void block_positions(Index node_a, Index node_b, Index* out) const;

 private:
  const DofMap& dofs_;
  std::vector<Index> neighbor_start_;  // CSR over nodes: neighbours (in the numbering's order),
                                       // incl. the node
  std::vector<int> neighbors_;
  std::vector<int> row_offset_;  // per neighbour entry: rows before it in the column
  std::vector<int> outer_;       // column pointers over free dofs
  SparseMatrix matrix_;          // until take_zero_matrix()
  bool taken_ = false;
};

}  // namespace signorini

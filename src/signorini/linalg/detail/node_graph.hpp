#pragma once
// Internal to linalg: the graph of the mesh nodes behind a stiffness matrix, for the orderings and
// the partitioner. Adjacent unknowns whose columns have the same pattern (the components of one
// node) form one vertex, which makes METIS and AMD several times cheaper and, for nested
// dissection, better (docs/performance.md).

#include <cholmod.h>

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini::detail {

struct NodeGraph {
  std::vector<Index> group;  // unknown -> vertex, -1 for unknowns left out of the graph
  std::vector<Index>
      group_start;  // first unknown of each vertex (a vertex's unknowns are adjacent)
  std::vector<SuiteSparse_long> colptr;  // upper triangle of the vertex graph, pattern only
  std::vector<SuiteSparse_long> rows;

  [[nodiscard]] Index size() const { return static_cast<Index>(group_start.size()); }
  /// A CHOLMOD view (stype = 1, pattern) of the graph; valid while the graph lives.
  [[nodiscard]] cholmod_sparse view();
};

/// The vertex graph of A (symmetric pattern, both triangles stored). Unknowns with
/// `singled_out[i]` are vertices of their own when `keep_singled_out`, and left out of the graph
/// otherwise; `singled_out` may be empty (none).
NodeGraph node_graph(const SparseMatrix& A, const std::vector<bool>& singled_out,
                     bool keep_singled_out);

}  // namespace signorini::detail

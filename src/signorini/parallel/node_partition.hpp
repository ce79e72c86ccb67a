#pragma once
// The partition of the mesh's nodes among the ranks of a distributed run (docs/distributed.md,
// "The partition").
//
// The graph's vertices are the nodes that have free unknowns, weighted by how many, and two are
// joined where a cell holds both: the nodes whose unknowns couple in A. Each rank builds the
// rows of its share of the vertices; the engine's graph partitioner (PETSc's MatPartitioning, by
// PT-Scotch or ParMETIS) gives every vertex its rank. The unknowns are then numbered rank by rank,
// so that each rank owns one range of them (ContactProblem::row_starts) with as few neighbours
// across the ranks as the partitioner finds.

#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/mesh/node_cells.hpp"

namespace signorini {

struct NodeGraph {
  Index vertices = 0;             ///< nodes with free unknowns, in the numbering's order
  Index first = 0, last = 0;      ///< this rank's vertices [first, last)
  std::vector<Index> offsets;     ///< this rank's rows: neighbours of vertex first + i at
  std::vector<Index> neighbours;  ///< [offsets[i], offsets[i + 1]), sorted, itself excluded
  std::vector<Index> weights;     ///< free unknowns of each of this rank's vertices
  std::vector<Index> node;        ///< the mesh node of every vertex (may be left empty)
};

/// The first vertex of rank `rank`'s even share of `vertices` (rank = ranks: the end): the rows
/// that node_graph gives a rank, and what a partitioner starts from.
[[nodiscard]] inline Index vertex_share_start(Index vertices, int rank, int ranks) {
  return vertices * rank / ranks;
}

/// The graph of `dofs`'s free nodes, with the rows of the vertices of `rank` of `ranks` (an even
/// split of the vertices in the numbering's order).
[[nodiscard]] NodeGraph node_graph(const Mesh& mesh, const DofMap& dofs, int rank, int ranks);

/// The same graph's rows, rank by rank from the cells of each node: rank 0 of a distributed run
/// makes each rank's rows in time proportional to them and sends them, never holding the whole
/// graph (about 27 neighbours per node on hexahedra).
class NodeGraphRows {
 public:
  NodeGraphRows(const Mesh& mesh, const DofMap& dofs);
  /// The rows of the vertices of `rank` of `ranks`; with the node of every vertex or not.
  [[nodiscard]] NodeGraph rows(int rank, int ranks, bool with_nodes = true) const;

 private:
  const Mesh& mesh_;
  NodeCells node_cells_;
  std::vector<Index> vertex_of_;        // per mesh node, -1 without free unknowns
  std::vector<Index> node_, unknowns_;  // per vertex
};

/// Where a partition puts the unknowns: the node order that numbers them rank by rank (each
/// rank's nodes in their former order, the nodes without free unknowns last), and the first
/// unknown of each rank.
struct NodePartition {
  std::vector<Index> node_order;
  std::vector<Index> row_starts;
};

/// From the rank of every vertex of `graph`. Empty (node_order and row_starts) where a rank got
/// no unknown: the caller then keeps the order it had.
[[nodiscard]] NodePartition partition_order(const NodeGraph& graph, const DofMap& dofs,
                                            const std::vector<int>& owner, int ranks);

/// The edges of `graph` (on this rank's rows) whose ends lie on different ranks: the interface
/// that the products exchange.
[[nodiscard]] Index cut_edges(const NodeGraph& graph, const std::vector<int>& owner);

}  // namespace signorini

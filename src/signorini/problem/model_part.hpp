#pragma once
// A rank's part of a distributed run's model (docs/distributed.md, "The mesh in parts"): rank 0
// reads the mesh, numbers and partitions the unknowns, and sends every other rank only the cells
// it needs, with their nodes and their numbering, and the rows of b it owns; the contact set,
// which every rank holds whole, goes to all. These are the pieces, and their bytes.

#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/interface/contact_set.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/mesh/node_cells.hpp"
#include "signorini/parallel/byte_message.hpp"
#include "signorini/parallel/node_partition.hpp"

namespace signorini {

/// The cells of each rank's part: those that touch a node of a cell that touches one of the
/// rank's nodes (two layers). From the first the rank assembles the columns of its unknowns
/// (every cell around its nodes); with the second every node of the first layer has all its
/// cells, so that the rank's piece of solution.pvtu averages the stresses there as the whole
/// mesh does. Made once for a mesh (the cells of each node), then asked rank by rank, each in
/// time proportional to its part.
class PartCells {
 public:
  explicit PartCells(const Mesh& mesh);
  /// The cells of the part around `own` (nodes of the mesh), increasing.
  [[nodiscard]] std::vector<Index> cells(const std::vector<Index>& own);
  /// The cells around each node of the mesh.
  [[nodiscard]] const NodeCells& node_cells() const { return node_cells_; }

 private:
  const Mesh& mesh_;
  NodeCells node_cells_;
  std::vector<int> cell_mark_, near_mark_, node_mark_;  // the call that last met each
  int call_ = 0;
};

/// Some cells of a mesh as a mesh of their own, with their nodes in increasing order (node i of
/// the part is global_nodes[i]), their types, regions (all the mesh's names) and source tags,
/// and no boundary parts.
struct MeshPart {
  Mesh mesh;
  std::vector<Index> global_nodes;
};
[[nodiscard]] MeshPart mesh_part(const Mesh& mesh, const std::vector<Index>& cells);

/// The free dofs of a part's numbering (its nodes' global free numbers), increasing: the
/// unknowns whose values the rank's solution holds (ContactProblem::solution_unknowns).
[[nodiscard]] std::vector<Index> part_unknowns(const DofMap& dofs);

// The bytes of each, for ByteWriter and ByteReader (parallel/byte_message.hpp).
void pack(ByteWriter& out, const Mesh& mesh);
[[nodiscard]] Mesh unpack_mesh(ByteReader& in);
void pack(ByteWriter& out, const DofMap& dofs);
[[nodiscard]] DofMap unpack_dof_map(ByteReader& in);
void pack(ByteWriter& out, const ContactSet& contact);
[[nodiscard]] ContactSet unpack_contact_set(ByteReader& in);
void pack(ByteWriter& out, const NodeGraph& graph);
[[nodiscard]] NodeGraph unpack_node_graph(ByteReader& in);

}  // namespace signorini

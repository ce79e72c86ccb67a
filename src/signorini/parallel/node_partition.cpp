#include "signorini/parallel/node_partition.hpp"

#include <algorithm>

#include "signorini/fem/rigid_body_modes.hpp"

namespace signorini {

NodeGraph node_graph(const Mesh& mesh, const DofMap& dofs, int rank, int ranks) {
  NodeGraph g;
  // The vertices: the nodes of the free unknowns, in the numbering's order.
  const std::vector<Index> node_of = free_dof_nodes(dofs);
  std::vector<Index> vertex_of(static_cast<std::size_t>(mesh.num_nodes()), -1);
  std::vector<Index> unknowns;
  for (std::size_t i = 0; i < node_of.size(); ++i) {
    const auto node = static_cast<std::size_t>(node_of[i]);
    if (i == 0 || node_of[i - 1] != node_of[i]) {
      vertex_of[node] = static_cast<Index>(g.node.size());
      g.node.push_back(node_of[i]);
      unknowns.push_back(0);
    }
    ++unknowns.back();
  }
  g.vertices = static_cast<Index>(g.node.size());
  g.first = vertex_share_start(g.vertices, rank, ranks);
  g.last = vertex_share_start(g.vertices, rank + 1, ranks);
  g.weights.assign(unknowns.begin() + g.first, unknowns.begin() + g.last);

  // This rank's rows: for each cell, each of its own vertices meets the cell's other vertices.
  std::vector<std::vector<Index>> rows(static_cast<std::size_t>(g.last - g.first));
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::span<const Index> nodes = mesh.cell(c);
    for (const Index a : nodes) {
      const Index va = vertex_of[static_cast<std::size_t>(a)];
      if (va < g.first || va >= g.last) continue;
      std::vector<Index>& row = rows[static_cast<std::size_t>(va - g.first)];
      for (const Index b : nodes) {
        const Index vb = vertex_of[static_cast<std::size_t>(b)];
        if (vb >= 0 && vb != va) row.push_back(vb);
      }
    }
  }
  g.offsets.assign(1, 0);
  for (std::vector<Index>& row : rows) {
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    g.neighbours.insert(g.neighbours.end(), row.begin(), row.end());
    g.offsets.push_back(static_cast<Index>(g.neighbours.size()));
    std::vector<Index>().swap(row);
  }
  return g;
}

NodePartition partition_order(const NodeGraph& graph, const DofMap& dofs,
                              const std::vector<int>& owner, int ranks) {
  NodePartition p;
  std::vector<std::vector<Index>> nodes_of(static_cast<std::size_t>(ranks));
  std::vector<bool> placed(static_cast<std::size_t>(dofs.num_nodes()), false);
  for (Index v = 0; v < graph.vertices; ++v) {
    const int r = owner[static_cast<std::size_t>(v)];
    const Index node = graph.node[static_cast<std::size_t>(v)];
    nodes_of[static_cast<std::size_t>(r)].push_back(node);
    placed[static_cast<std::size_t>(node)] = true;
  }
  p.row_starts.assign(1, 0);
  for (const std::vector<Index>& nodes : nodes_of) {
    if (nodes.empty()) return {};  // a rank without unknowns
    Index unknowns = 0;
    for (const Index node : nodes)
      for (int k = 0; k < dofs.dim(); ++k) unknowns += dofs.free_index(node, k) >= 0 ? 1 : 0;
    p.row_starts.push_back(p.row_starts.back() + unknowns);
    p.node_order.insert(p.node_order.end(), nodes.begin(), nodes.end());
  }
  for (Index node = 0; node < dofs.num_nodes(); ++node)
    if (!placed[static_cast<std::size_t>(node)]) p.node_order.push_back(node);
  return p;
}

Index cut_edges(const NodeGraph& graph, const std::vector<int>& owner) {
  Index cut = 0;
  for (Index v = graph.first; v < graph.last; ++v) {
    const auto i = static_cast<std::size_t>(v - graph.first);
    for (Index e = graph.offsets[i]; e < graph.offsets[i + 1]; ++e)
      cut += owner[static_cast<std::size_t>(v)] !=
                     owner[static_cast<std::size_t>(graph.neighbours[static_cast<std::size_t>(e)])]
                 ? 1
                 : 0;
  }
  return cut;
}

}  // namespace signorini

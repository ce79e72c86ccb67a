#include "signorini/parallel/node_partition.hpp"

#include <algorithm>

#include "signorini/fem/rigid_body_modes.hpp"

namespace signorini {

NodeGraphRows::NodeGraphRows(const Mesh& mesh, const DofMap& dofs)
    : mesh_(mesh), node_cells_(mesh), vertex_of_(static_cast<std::size_t>(mesh.num_nodes()), -1) {
  // The vertices: the nodes of the free unknowns, in the numbering's order.
  const std::vector<Index> node_of = free_dof_nodes(dofs);
  for (std::size_t i = 0; i < node_of.size(); ++i) {
    const auto node = static_cast<std::size_t>(node_of[i]);
    if (i == 0 || node_of[i - 1] != node_of[i]) {
      vertex_of_[node] = static_cast<Index>(node_.size());
      node_.push_back(node_of[i]);
      unknowns_.push_back(0);
    }
    ++unknowns_.back();
  }
}

NodeGraph NodeGraphRows::rows(int rank, int ranks, bool with_nodes) const {
  NodeGraph g;
  g.vertices = static_cast<Index>(node_.size());
  g.first = vertex_share_start(g.vertices, rank, ranks);
  g.last = vertex_share_start(g.vertices, rank + 1, ranks);
  g.weights.assign(unknowns_.begin() + g.first, unknowns_.begin() + g.last);
  if (with_nodes) g.node = node_;
  // Each vertex meets the other vertices of the cells around its node.
  g.offsets.assign(1, 0);
  std::vector<Index> row;
  for (Index v = g.first; v < g.last; ++v) {
    row.clear();
    for (const Index c : node_cells_.of(node_[static_cast<std::size_t>(v)]))
      for (const Index b : mesh_.cell(c)) {
        const Index vb = vertex_of_[static_cast<std::size_t>(b)];
        if (vb >= 0 && vb != v) row.push_back(vb);
      }
    std::sort(row.begin(), row.end());
    row.erase(std::unique(row.begin(), row.end()), row.end());
    g.neighbours.insert(g.neighbours.end(), row.begin(), row.end());
    g.offsets.push_back(static_cast<Index>(g.neighbours.size()));
  }
  return g;
}

NodeGraph node_graph(const Mesh& mesh, const DofMap& dofs, int rank, int ranks) {
  return NodeGraphRows(mesh, dofs).rows(rank, ranks);
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

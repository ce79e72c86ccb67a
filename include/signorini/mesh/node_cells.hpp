#pragma once
// The cells around each node of a mesh, in one array (compressed rows): what a node's
// neighbourhood takes to walk in time proportional to it, as a rank's part of the mesh and its
// rows of the node graph do (docs/distributed.md, "The mesh in parts").

#include <span>
#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

class NodeCells {
 public:
  explicit NodeCells(const Mesh& mesh);
  /// The cells that hold node `node`, increasing.
  [[nodiscard]] std::span<const Index> of(Index node) const {
    const auto v = static_cast<std::size_t>(node);
    return {cells_.data() + first_[v], cells_.data() + first_[v + 1]};
  }

 private:
  std::vector<Index> first_, cells_;  // the cells of node v: cells_[first_[v] .. first_[v + 1])
};

}  // namespace signorini

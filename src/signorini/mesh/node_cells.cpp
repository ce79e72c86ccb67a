#include "signorini/mesh/node_cells.hpp"

namespace signorini {

NodeCells::NodeCells(const Mesh& mesh) : first_(static_cast<std::size_t>(mesh.num_nodes()) + 1, 0) {
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const Index v : mesh.cell(c)) ++first_[static_cast<std::size_t>(v) + 1];
  for (std::size_t v = 0; v + 1 < first_.size(); ++v) first_[v + 1] += first_[v];
  cells_.resize(static_cast<std::size_t>(first_.back()));
  std::vector<Index> next(first_.begin(), first_.end() - 1);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const Index v : mesh.cell(c))
      cells_[static_cast<std::size_t>(next[static_cast<std::size_t>(v)]++)] = c;
}

}  // namespace signorini

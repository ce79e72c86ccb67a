#include "signorini/fem/sparsity_pattern.hpp"

#include <algorithm>
#include <limits>

#include "signorini/core/error.hpp"

namespace signorini {

SparsityPattern::SparsityPattern(const Mesh& mesh, const DofMap& dofs) : dofs_(dofs) {
  const Index n = mesh.num_nodes();
  const int dim = dofs.dim();
  // Node adjacency through cells, as sorted unique lists.
  std::vector<std::vector<Index>> adj(static_cast<std::size_t>(n));
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    for (const Index a : nodes)
      for (const Index b : nodes) adj[static_cast<std::size_t>(a)].push_back(b);
  }
  neighbor_start_.assign(static_cast<std::size_t>(n + 1), 0);
  for (Index m = 0; m < n; ++m) {
    auto& list = adj[static_cast<std::size_t>(m)];
    std::sort(list.begin(), list.end());
    list.erase(std::unique(list.begin(), list.end()), list.end());
    neighbor_start_[static_cast<std::size_t>(m + 1)] =
        neighbor_start_[static_cast<std::size_t>(m)] + static_cast<Index>(list.size());
  }
  neighbors_.reserve(static_cast<std::size_t>(neighbor_start_.back()));
  row_offset_.reserve(neighbors_.capacity());
  for (Index m = 0; m < n; ++m) {
    Index rows = 0;
    for (const Index b : adj[static_cast<std::size_t>(m)]) {
      neighbors_.push_back(b);
      row_offset_.push_back(rows);
      for (int k = 0; k < dim; ++k) rows += dofs.free_index(b, k) >= 0 ? 1 : 0;
    }
    adj[static_cast<std::size_t>(m)].clear();
    adj[static_cast<std::size_t>(m)].shrink_to_fit();
  }
  // Columns: the free dofs in order; the rows of column (m, k) are the free dofs of m's
  // neighbours, already sorted since free numbers follow (node, component).
  const Index nf = dofs.num_free();
  outer_.assign(static_cast<std::size_t>(nf + 1), 0);
  Index nnz = 0;
  for (Index m = 0; m < n; ++m) {
    const Index s0 = neighbor_start_[static_cast<std::size_t>(m)];
    const Index s1 = neighbor_start_[static_cast<std::size_t>(m + 1)];
    Index rows = 0;
    for (Index s = s0; s < s1; ++s)
      for (int k = 0; k < dim; ++k)
        rows += dofs.free_index(neighbors_[static_cast<std::size_t>(s)], k) >= 0 ? 1 : 0;
    for (int k = 0; k < dim; ++k) {
      const Index col = dofs.free_index(m, k);
      if (col < 0) continue;
      nnz += rows;
      if (nnz > std::numeric_limits<int>::max())
        throw InputError("mesh too large: the stiffness matrix would have more than 2^31 entries");
      outer_[static_cast<std::size_t>(col + 1)] = static_cast<int>(nnz);
      for (Index s = s0; s < s1; ++s)
        for (int kk = 0; kk < dim; ++kk) {
          const Index row = dofs.free_index(neighbors_[static_cast<std::size_t>(s)], kk);
          if (row >= 0) inner_.push_back(static_cast<int>(row));
        }
    }
  }
}

SparseMatrix SparsityPattern::zero_matrix() const {
  const auto nf = static_cast<Index>(outer_.size()) - 1;
  const auto nnz = static_cast<Index>(inner_.size());
  SparseMatrix A(nf, nf);
  A.resizeNonZeros(nnz);  // compressed storage, filled directly
  std::copy(outer_.begin(), outer_.end(), A.outerIndexPtr());
  std::copy(inner_.begin(), inner_.end(), A.innerIndexPtr());
  std::fill(A.valuePtr(), A.valuePtr() + nnz, 0.0);
  return A;
}

void SparsityPattern::block_positions(Index node_a, Index node_b, Index* out) const {
  const int dim = dofs_.dim();
  const Index s0 = neighbor_start_[static_cast<std::size_t>(node_b)];
  const Index s1 = neighbor_start_[static_cast<std::size_t>(node_b + 1)];
  const auto it = std::lower_bound(neighbors_.begin() + s0, neighbors_.begin() + s1, node_a);
  const Index base = row_offset_[static_cast<std::size_t>(it - neighbors_.begin())];
  Index within = 0;
  for (int ka = 0; ka < dim; ++ka) {
    const bool row_free = dofs_.free_index(node_a, ka) >= 0;
    for (int kb = 0; kb < dim; ++kb) {
      const Index col = dofs_.free_index(node_b, kb);
      out[ka * dim + kb] =
          (row_free && col >= 0) ? outer_[static_cast<std::size_t>(col)] + base + within : -1;
    }
    within += row_free ? 1 : 0;
  }
}

}  // namespace signorini

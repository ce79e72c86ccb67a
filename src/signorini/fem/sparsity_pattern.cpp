#include "signorini/fem/sparsity_pattern.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

#include "signorini/core/error.hpp"
#include "signorini/fem/cell_threads.hpp"

namespace signorini {

SparsityPattern::SparsityPattern(const Mesh& mesh, const DofMap& dofs,
                                 const std::vector<bool>* columns_of)
    : dofs_(dofs) {
  const auto kept = [&](Index m) {
    return columns_of == nullptr || (*columns_of)[static_cast<std::size_t>(m)];
  };
  const Index n = mesh.num_nodes();
  const int dim = dofs.dim();
  // The cells of each node (CSR), then each node's neighbours through them as a sorted unique
  // list: a few numbers per node at a time, where lists of every cell pair would hold the
  // square of the cell size per node (512 bytes per hex8 node) all at once.
  std::vector<Index> cell_start(static_cast<std::size_t>(n + 1), 0);
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const Index a : mesh.cell(c)) ++cell_start[static_cast<std::size_t>(a + 1)];
  for (Index m = 0; m < n; ++m)
    cell_start[static_cast<std::size_t>(m + 1)] += cell_start[static_cast<std::size_t>(m)];
  std::vector<Index> cells_of(static_cast<std::size_t>(cell_start.back()));
  {
    std::vector<Index> next(cell_start.begin(), cell_start.end() - 1);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (const Index a : mesh.cell(c))
        cells_of[static_cast<std::size_t>(next[static_cast<std::size_t>(a)]++)] = c;
  }
  // Each node's list, in parallel over shares of the nodes (each thread its own lists, joined
  // in the nodes' order: the same arrays whatever the number of threads).
  const int threads = cell_loop_threads(mesh.num_cells());
  std::vector<std::vector<int>> share_neighbors(static_cast<std::size_t>(threads));
  std::vector<std::vector<int>> share_offsets(static_cast<std::size_t>(threads));
  std::vector<Index> count(static_cast<std::size_t>(n), 0);
#pragma omp parallel for schedule(static, 1) num_threads(threads) if (threads > 1)
  for (int t = 0; t < threads; ++t) {
    std::vector<int>& out = share_neighbors[static_cast<std::size_t>(t)];
    std::vector<int>& offsets = share_offsets[static_cast<std::size_t>(t)];
    std::vector<Index> list;
    for (Index m = n * t / threads; m < n * (t + 1) / threads; ++m) {
      if (!kept(m)) continue;  // an empty column: no neighbours kept
      list.clear();
      for (Index s = cell_start[static_cast<std::size_t>(m)];
           s < cell_start[static_cast<std::size_t>(m + 1)]; ++s)
        for (const Index b : mesh.cell(cells_of[static_cast<std::size_t>(s)])) list.push_back(b);
      // In the order of the free dofs (the nodes' places in the numbering, DofMap::node_place).
      std::sort(list.begin(), list.end(),
                [&](Index a, Index b) { return dofs.node_place(a) < dofs.node_place(b); });
      list.erase(std::unique(list.begin(), list.end()), list.end());
      Index rows = 0;
      for (const Index b : list) {
        out.push_back(static_cast<int>(b));
        offsets.push_back(static_cast<int>(rows));
        for (int k = 0; k < dim; ++k) rows += dofs.free_index(b, k) >= 0 ? 1 : 0;
      }
      count[static_cast<std::size_t>(m)] = static_cast<Index>(list.size());
    }
  }
  neighbor_start_.assign(static_cast<std::size_t>(n + 1), 0);
  for (Index m = 0; m < n; ++m)
    neighbor_start_[static_cast<std::size_t>(m + 1)] =
        neighbor_start_[static_cast<std::size_t>(m)] + count[static_cast<std::size_t>(m)];
  std::vector<Index>().swap(count);
  if (threads == 1) {
    neighbors_ = std::move(share_neighbors.front());
    row_offset_ = std::move(share_offsets.front());
  } else {
    neighbors_.reserve(static_cast<std::size_t>(neighbor_start_.back()));
    row_offset_.reserve(static_cast<std::size_t>(neighbor_start_.back()));
    for (int t = 0; t < threads; ++t) {
      auto& part = share_neighbors[static_cast<std::size_t>(t)];
      auto& offsets = share_offsets[static_cast<std::size_t>(t)];
      neighbors_.insert(neighbors_.end(), part.begin(), part.end());
      row_offset_.insert(row_offset_.end(), offsets.begin(), offsets.end());
      std::vector<int>().swap(part);
      std::vector<int>().swap(offsets);
    }
  }
  std::vector<Index>().swap(cells_of);
  neighbors_.shrink_to_fit();
  row_offset_.shrink_to_fit();
  // Columns: the free dofs in order; the rows of column (m, k) are the free dofs of m's
  // neighbours, already sorted since the neighbours are in the numbering's order and a node's
  // free numbers follow its components. Counted first, so
  // that the row numbers go straight into the matrix (no second copy of them).
  const Index nf = dofs.num_free();
  outer_.assign(static_cast<std::size_t>(nf + 1), 0);
  const auto rows_of = [&](Index m) {
    Index rows = 0;
    for (Index s = neighbor_start_[static_cast<std::size_t>(m)];
         s < neighbor_start_[static_cast<std::size_t>(m + 1)]; ++s)
      for (int k = 0; k < dim; ++k)
        rows += dofs.free_index(neighbors_[static_cast<std::size_t>(s)], k) >= 0 ? 1 : 0;
    return rows;
  };
  // Each column's count in outer_[col + 1], then their running sum in place (the columns are not
  // in node order where the numbering follows a node order).
  for (Index m = 0; m < n; ++m) {
    const Index rows = rows_of(m);
    for (int k = 0; k < dim; ++k) {
      const Index col = dofs.free_index(m, k);
      if (col >= 0) outer_[static_cast<std::size_t>(col + 1)] = static_cast<int>(rows);
    }
  }
  Index nnz = 0;
  for (Index col = 0; col < nf; ++col) {
    nnz += outer_[static_cast<std::size_t>(col + 1)];
    if (nnz > std::numeric_limits<int>::max())
      throw InputError("mesh too large: the stiffness matrix would have more than 2^31 entries");
    outer_[static_cast<std::size_t>(col + 1)] = static_cast<int>(nnz);
  }
  matrix_.resize(nf, nf);
  matrix_.resizeNonZeros(nnz);  // compressed storage, filled directly
  std::copy(outer_.begin(), outer_.end(), matrix_.outerIndexPtr());
  // Filled in parallel over the nodes (each writes its own columns): the first touch of the
  // largest arrays of a model, which on a virtual machine costs more than the writing itself.
  int* inner = matrix_.innerIndexPtr();
  double* values = matrix_.valuePtr();
#pragma omp parallel for schedule(static)
  for (Index m = 0; m < n; ++m)
    for (int k = 0; k < dim; ++k) {
      const Index col = dofs.free_index(m, k);
      if (col < 0) continue;
      const Index first = outer_[static_cast<std::size_t>(col)];
      Index pos = first;
      for (Index s = neighbor_start_[static_cast<std::size_t>(m)];
           s < neighbor_start_[static_cast<std::size_t>(m + 1)]; ++s)
        for (int kk = 0; kk < dim; ++kk) {
          const Index row = dofs.free_index(neighbors_[static_cast<std::size_t>(s)], kk);
          if (row >= 0) inner[pos++] = static_cast<int>(row);
        }
      std::fill(values + first, values + pos, 0.0);
    }
}

SparseMatrix SparsityPattern::take_zero_matrix() {
  if (taken_) throw std::logic_error("SparsityPattern::take_zero_matrix called twice");
  taken_ = true;
  return std::move(matrix_);
}

void SparsityPattern::block_positions(Index node_a, Index node_b, Index* out) const {
  const int dim = dofs_.dim();
  const Index s0 = neighbor_start_[static_cast<std::size_t>(node_b)];
  const Index s1 = neighbor_start_[static_cast<std::size_t>(node_b + 1)];
  if (s0 == s1) {  // a column left empty (the constructor's columns_of)
    std::fill(out, out + dim * dim, Index{-1});
    return;
  }
  const Index place = dofs_.node_place(node_a);
  const auto it =
      std::lower_bound(neighbors_.begin() + s0, neighbors_.begin() + s1, place,
                       [&](int neighbour, Index p) { return dofs_.node_place(neighbour) < p; });
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

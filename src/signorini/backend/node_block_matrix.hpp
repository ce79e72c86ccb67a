#pragma once
// A square sparse matrix stored by node blocks for the CPU's products. Its rows and columns fall
// into groups of consecutive indices with the same pattern (the free dofs of one mesh node:
// supervariables, found from the pattern alone), and every nonzero block is stored dense, row
// by row, with one column-group number for all its entries: 8.4 bytes per entry for 3 x 3
// blocks against 12 in CSR (a value and a column index), and a sparse product is bound by the
// bytes it streams from memory (docs/performance.md, "Node blocks").

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

class NodeBlockMatrix {
 public:
  /// From the CSR arrays of an n x n matrix (sorted column indices), with groups of at most
  /// `max_group` indices. Empty when the pattern does not consist of whole blocks (a row that
  /// holds part of a group), or when the blocks would not save memory (groups of one).
  static std::optional<NodeBlockMatrix> from_csr(Index n, const int* outer, const int* inner,
                                                 const double* values, int max_group = 3);

  [[nodiscard]] Index size() const { return static_cast<Index>(group_start_.back()); }
  [[nodiscard]] Index num_groups() const { return static_cast<Index>(group_start_.size()) - 1; }
  [[nodiscard]] Index num_blocks() const { return static_cast<Index>(block_group_.size()); }
  /// The bytes of its arrays.
  [[nodiscard]] std::size_t bytes() const;

  /// y = alpha A x + beta y (beta = 0 ignores y), in parallel over the row groups where OpenMP
  /// is on and `parallel`.
  void multiply(const double* x, double* y, double alpha, double beta, bool parallel) const;
  /// y = alpha A^T x + beta y, on one thread (no caller needs it fast).
  void multiply_transpose(const double* x, double* y, double alpha, double beta) const;

 private:
  std::vector<int> group_start_;           // group g: indices group_start_[g] .. [g + 1] - 1
  std::vector<int> block_start_;           // row group g: blocks block_start_[g] .. [g + 1] - 1
  std::vector<std::int64_t> value_start_;  // row group g: its values from value_start_[g]
  std::vector<int> block_group_;           // each block's column group
  std::unique_ptr<double[]> values_;       // block after block, each row-major
  std::size_t value_count_ = 0;
};

}  // namespace signorini

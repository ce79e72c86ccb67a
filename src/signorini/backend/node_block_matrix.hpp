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
  /// The same for a symmetric matrix, of which only the blocks on and above the diagonal are
  /// kept (those of a row group with column group >= its own): half the bytes, and a product
  /// that uses each off-diagonal block twice, as B and as B^T. The product is that of the
  /// exactly symmetric matrix formed from A's upper triangle (the diagonal blocks' lower halves
  /// mirrored from their upper ones too), so that a matrix symmetric only up to rounding (a
  /// Galerkin product) is symmetrised at rounding level.
  static std::optional<NodeBlockMatrix> from_symmetric_csr(Index n, const int* outer,
                                                           const int* inner, const double* values,
                                                           int max_group = 3);

  [[nodiscard]] Index size() const { return static_cast<Index>(group_start_.back()); }
  [[nodiscard]] Index num_groups() const { return static_cast<Index>(group_start_.size()) - 1; }
  [[nodiscard]] Index num_blocks() const { return static_cast<Index>(block_group_.size()); }
  /// Whether only the upper blocks are held (from_symmetric_csr).
  [[nodiscard]] bool symmetric() const { return !reach_.empty(); }
  /// The bytes of its arrays.
  [[nodiscard]] std::size_t bytes() const;

  /// y = alpha A x + beta y (beta = 0 ignores y), in parallel over the row groups where OpenMP
  /// is on and `parallel`.
  void multiply(const double* x, double* y, double alpha, double beta, bool parallel) const;
  /// y = alpha A^T x + beta y, on one thread (no caller needs it fast); multiply() where
  /// symmetric().
  void multiply_transpose(const double* x, double* y, double alpha, double beta) const;

 private:
  static std::optional<NodeBlockMatrix> build(Index n, const int* outer, const int* inner,
                                              const double* values, int max_group, bool upper);
  void multiply_full(const double* x, double* y, double alpha, double beta, bool parallel) const;
  void multiply_upper(const double* x, double* y, double alpha, double beta, bool parallel) const;

  std::vector<int> group_start_;           // group g: indices group_start_[g] .. [g + 1] - 1
  std::vector<int> block_start_;           // row group g: blocks block_start_[g] .. [g + 1] - 1
  std::vector<std::int64_t> value_start_;  // row group g: its values from value_start_[g]
  std::vector<int> block_group_;           // each block's column group
  std::unique_ptr<double[]> values_;       // block after block, each row-major
  std::size_t value_count_ = 0;
  // Upper blocks only: reach_[g] is one past the last row that row groups 0..g write to through
  // their transposed blocks (a prefix maximum), which sizes the rows a thread's share of the row
  // groups adds into beyond its own (multiply_upper).
  std::vector<int> reach_;
};

}  // namespace signorini

#pragma once
// Sparse matrix products formed one result column at a time (Gustavson's algorithm), as the
// multigrid set-up does them in parallel over the columns: a dense accumulator that remembers
// which rows it touched, and the assembly of the finished columns into one CSC matrix.

#include <algorithm>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

/// One thread's accumulator for columns of length n.
class ColumnAccumulator {
 public:
  explicit ColumnAccumulator(Index n)
      : values_(static_cast<std::size_t>(n), 0.0), used_(static_cast<std::size_t>(n), 0) {}

  void add(Index i, double v) {
    const auto u = static_cast<std::size_t>(i);
    if (!used_[u]) {
      used_[u] = 1;
      pattern_.push_back(static_cast<int>(i));
    }
    values_[u] += v;
  }

  /// Appends the column's nonzeros (exact zeros dropped) in row order to `rows` and `values`,
  /// and leaves the accumulator empty for the next column.
  void flush(std::vector<int>& rows, std::vector<double>& values) {
    std::sort(pattern_.begin(), pattern_.end());
    rows.reserve(rows.size() + pattern_.size());
    values.reserve(values.size() + pattern_.size());
    for (const int i : pattern_) {
      const auto u = static_cast<std::size_t>(i);
      if (values_[u] != 0.0) {
        rows.push_back(i);
        values.push_back(values_[u]);
      }
      values_[u] = 0.0;
      used_[u] = 0;
    }
    pattern_.clear();
  }

  /// Calls f(row, value) for every row touched, in no particular order (a column that is only
  /// an intermediate needs no sorting), and leaves the accumulator empty.
  template <class F>
  void drain(F&& f) {
    for (const int i : pattern_) {
      const auto u = static_cast<std::size_t>(i);
      f(static_cast<Index>(i), values_[u]);
      values_[u] = 0.0;
      used_[u] = 0;
    }
    pattern_.clear();
  }

 private:
  std::vector<double> values_;
  std::vector<char> used_;
  std::vector<int> pattern_;
};

/// The rows x columns.size() CSC matrix whose column J has the sorted rows column_rows[J] with
/// the values column_values[J].
SparseMatrix assemble_columns(Index rows, const std::vector<std::vector<int>>& column_rows,
                              const std::vector<std::vector<double>>& column_values);

}  // namespace signorini

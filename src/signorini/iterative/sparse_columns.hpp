#pragma once
// Sparse matrix products formed a group of result columns at a time (Gustavson's algorithm, as
// the multigrid set-up does them, in parallel over the groups): the columns of one aggregate
// (the six rigid-body modes on its nodes in 3D) share their rows, so they are formed together,
// each index of the operands read once for the whole group instead of once per column. A group
// accumulator keeps, for each row it touched, one value per column of the group;
// form_column_groups writes the groups straight into one CSC matrix.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

/// The most columns formed together (the callers keep a group's values on the stack).
inline constexpr int kMaxColumnGroup = 8;

/// One thread's accumulator for a group of columns of length n that share their rows: the rows
/// touched get local slots, so its work space grows with the rows touched, not with the group.
class GroupAccumulator {
 public:
  explicit GroupAccumulator(Index n) : slot_(static_cast<std::size_t>(n), -1) {}

  /// Starts an empty group of `width` columns. `counting`: only the rows touched matter (the
  /// first pass of form_column_groups), so a caller may skip the arithmetic.
  void start(int width, bool counting = false) {
    clear();
    width_ = width;
    counting_ = counting;
  }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] bool counting() const { return counting_; }

  /// The group's values in row i (zeros when first touched); valid until the next call.
  double* row(Index i) {
    int s = slot_[static_cast<std::size_t>(i)];
    if (s < 0) [[unlikely]]
      s = add_row(i);
    return values_.data() + static_cast<std::ptrdiff_t>(s) * width_;
  }

  /// Whether row i was touched.
  [[nodiscard]] bool has(Index i) const { return slot_[static_cast<std::size_t>(i)] >= 0; }

  /// The number of rows touched.
  [[nodiscard]] Index touched() const { return static_cast<Index>(rows_.size()); }

  /// Calls f(row, values) for every row touched, in no particular order.
  template <class F>
  void for_each(F&& f) const {
    for (std::size_t s = 0; s < rows_.size(); ++s)
      f(static_cast<Index>(rows_[s]), values_.data() + static_cast<std::ptrdiff_t>(s) * width_);
  }

  /// Writes column c of the group (rows sorted, exact zeros kept) to rows[c] and values[c].
  void write(int* const* rows, double* const* values) {
    order_.resize(rows_.size());
    std::iota(order_.begin(), order_.end(), 0);
    std::sort(order_.begin(), order_.end(), [&](int a, int b) {
      return rows_[static_cast<std::size_t>(a)] < rows_[static_cast<std::size_t>(b)];
    });
    for (std::size_t t = 0; t < order_.size(); ++t) {
      const auto s = static_cast<std::size_t>(order_[t]);
      for (int c = 0; c < width_; ++c) {
        rows[c][t] = rows_[s];
        values[c][t] = values_[s * static_cast<std::size_t>(width_) + static_cast<std::size_t>(c)];
      }
    }
  }

  /// Forgets the group (the work space stays for the next).
  void clear() {
    for (const int i : rows_) slot_[static_cast<std::size_t>(i)] = -1;
    rows_.clear();
  }

 private:
  // A slot for row i, its values zero; the values' storage grows by doubling and is kept.
  int add_row(Index i) {
    const auto s = static_cast<int>(rows_.size());
    slot_[static_cast<std::size_t>(i)] = s;
    rows_.push_back(static_cast<int>(i));
    const auto first = static_cast<std::size_t>(s) * static_cast<std::size_t>(width_);
    const std::size_t need = first + static_cast<std::size_t>(width_);
    if (values_.size() < need) values_.resize(std::max(need, 2 * values_.size()));
    std::fill(values_.begin() + static_cast<std::ptrdiff_t>(first),
              values_.begin() + static_cast<std::ptrdiff_t>(need), 0.0);
    return s;
  }

  std::vector<int> slot_;  // per row: its slot, -1 if untouched
  std::vector<int> rows_;  // per slot: the row
  std::vector<double> values_;
  std::vector<int> order_;
  int width_ = 1;
  bool counting_ = false;
};

/// Calls f(std::integral_constant<int, W>{}) with W = width for the widths of 2D and 3D
/// aggregates (3 and 6 modes), so that the loops over a group's columns unroll, and with W = 0
/// (meaning: any width, `width` at run time) otherwise.
template <class F>
void with_group_width(int width, F&& f) {
  if (width == 6)
    f(std::integral_constant<int, 6>{});
  else if (width == 3)
    f(std::integral_constant<int, 3>{});
  else
    f(std::integral_constant<int, 0>{});
}

/// Per column j of A: whether its rows are those of column j-1 (true of the unknowns of one
/// node in a matrix of node blocks). A pass that only counts the rows a product touches may
/// skip such a column right after column j-1, a third of the reads of A in 3D elasticity.
inline std::vector<char> repeats_previous_column(const SparseView& A) {
  std::vector<char> repeats(static_cast<std::size_t>(A.cols()), 0);
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  const int* lengths = A.innerNonZeroPtr();
  const auto end = [&](std::int64_t j) { return lengths ? outer[j] + lengths[j] : outer[j + 1]; };
#pragma omp parallel for schedule(static)
  for (std::int64_t j = 1; j < A.cols(); ++j)
    repeats[static_cast<std::size_t>(j)] =
        static_cast<char>(end(j) - outer[j] == end(j - 1) - outer[j - 1] &&
                          std::equal(inner + outer[j], inner + end(j), inner + outer[j - 1]));
  return repeats;
}

/// The starts of the runs of consecutive columns of the compressed M with the same rows, each
/// run cut after kMaxColumnGroup columns; the last entry is M.cols().
inline std::vector<Index> same_row_groups(const SparseMatrix& M) {
  const std::vector<char> repeats = repeats_previous_column(view_of(M));
  std::vector<Index> start;
  for (Index J = 0; J < M.cols(); ++J)
    if (start.empty() || J - start.back() >= kMaxColumnGroup ||
        !repeats[static_cast<std::size_t>(J)])
      start.push_back(J);
  start.push_back(M.cols());
  return start;
}

/// The rows of a matrix M by groups of columns with the same rows (same_row_groups): row k of
/// M has entries in the groups group[e] for e in start[k] .. start[k+1]-1, at the place
/// position[e] of the group's rows (so M(k, J) = values[outer[J] + position[e]] for each column
/// J of the group). A product that needs the rows of M (P^T times a column, in the Galerkin
/// product) reads them here instead of in a row-major copy of M: a sixth of its entries where
/// the groups are the six rigid-body modes, and the values stay where they are.
/// repeats[k]: row k lies in the same groups as row k-1 (the unknowns of one node), so a pass
/// that only counts the rows a product touches may skip it once row k-1 is taken.
struct GroupRows {
  std::vector<Index> start;
  std::vector<int> group, position;
  std::vector<char> repeats;
};

inline GroupRows group_rows(const SparseMatrix& M, const std::vector<Index>& groups) {
  const int* outer = M.outerIndexPtr();
  const int* inner = M.innerIndexPtr();
  GroupRows r;
  r.start.assign(static_cast<std::size_t>(M.rows()) + 1, 0);
  const auto count_of_groups = static_cast<std::int64_t>(groups.size()) - 1;
  for (std::int64_t G = 0; G < count_of_groups; ++G) {
    const Index J = groups[static_cast<std::size_t>(G)];
    for (int k = outer[J]; k < outer[J + 1]; ++k) ++r.start[static_cast<std::size_t>(inner[k]) + 1];
  }
  std::partial_sum(r.start.begin(), r.start.end(), r.start.begin());
  r.group.resize(static_cast<std::size_t>(r.start.back()));
  r.position.resize(r.group.size());
  std::vector<Index> next(r.start.begin(), r.start.end() - 1);
  for (std::int64_t G = 0; G < count_of_groups; ++G) {
    const Index J = groups[static_cast<std::size_t>(G)];
    for (int k = outer[J]; k < outer[J + 1]; ++k) {
      const auto e = static_cast<std::size_t>(next[static_cast<std::size_t>(inner[k])]++);
      r.group[e] = static_cast<int>(G);
      r.position[e] = k - outer[J];
    }
  }
  r.repeats.assign(static_cast<std::size_t>(M.rows()), 0);
  for (std::size_t k = 1; k < r.repeats.size(); ++k)
    r.repeats[k] =
        static_cast<char>(r.start[k + 1] - r.start[k] == r.start[k] - r.start[k - 1] &&
                          std::equal(r.group.begin() + r.start[k], r.group.begin() + r.start[k + 1],
                                     r.group.begin() + r.start[k - 1]));
  return r;
}

/// How many of the columns list[k], list[k+1], ... (at most three) of A are the consecutive
/// unknowns i, i+1, ... of one node with the same rows in A (repeats: repeats_previous_column),
/// all below `limit`: where three, a product reads the node's three columns together
/// (ColumnsOfNode), one look-up of each row for three entries.
inline int node_columns(const int* list, int k, int length, Index limit,
                        const std::vector<char>& repeats) {
  const Index i = list[k];
  int run = 1;
  while (run < 3 && k + run < length && list[k + run] == i + run && i + run < limit &&
         repeats[static_cast<std::size_t>(i + run)])
    ++run;
  return run;
}

/// Columns i, i+1, i+2 of A with the same rows (node_columns() == 3): the rows once, and the
/// three columns' values against them.
struct ColumnsOfNode {
  ColumnsOfNode(const SparseView& A, Index i) {
    const int* outer = A.outerIndexPtr();
    const int* lengths = A.innerNonZeroPtr();
    rows = A.innerIndexPtr() + outer[i];
    length = lengths ? lengths[i] : outer[i + 1] - outer[i];
    for (int r = 0; r < 3; ++r) values[r] = A.valuePtr() + outer[i + r];
  }
  const int* rows;
  int length;
  const double* values[3];
};

/// The rows x cols matrix whose columns J0 .. J0 + g - 1 (a group: `groups` holds their starts,
/// then cols) are what group(J0, g, accumulator) adds to an accumulator started with width g,
/// where `group = make_group()` is made once per thread (so that it may keep work space of its
/// own). Formed in parallel over the groups in two passes: the first counts each group's rows
/// (the accumulator is then counting(), and `group` may leave out the arithmetic), the second
/// writes them straight into the result, so that no column is ever held twice (the
/// peak memory of a multigrid set-up is the result, not twice it). Exact zeros are kept.
template <class MakeGroup>
SparseMatrix form_column_groups(Index rows, Index cols, const std::vector<Index>& groups,
                                const MakeGroup& make_group) {
  if (groups.empty() || groups.back() != cols)
    throw std::logic_error("form_column_groups: the groups must end at the last column");
  const auto count_of_groups = static_cast<std::int64_t>(groups.size()) - 1;
  std::vector<Index> count(static_cast<std::size_t>(count_of_groups), 0);
  const auto width_of = [&](std::int64_t G) {
    return static_cast<int>(groups[static_cast<std::size_t>(G) + 1] -
                            groups[static_cast<std::size_t>(G)]);
  };
#pragma omp parallel
  {
    GroupAccumulator accumulator(rows);
    auto group = make_group();
#pragma omp for schedule(dynamic, 64)
    for (std::int64_t G = 0; G < count_of_groups; ++G) {
      accumulator.start(width_of(G), true);
      group(groups[static_cast<std::size_t>(G)], width_of(G), accumulator);
      count[static_cast<std::size_t>(G)] = accumulator.touched();
    }
  }
  SparseMatrix M(rows, cols);
  int* outer = M.outerIndexPtr();
  Index nonzeros = 0;
  for (std::int64_t G = 0; G < count_of_groups; ++G)
    for (Index J = groups[static_cast<std::size_t>(G)]; J < groups[static_cast<std::size_t>(G) + 1];
         ++J) {
      outer[J] = static_cast<int>(nonzeros);
      nonzeros += count[static_cast<std::size_t>(G)];
      if (nonzeros > std::numeric_limits<int>::max())
        throw NumericalError("a multigrid operator would have more than 2^31 entries");
    }
  outer[cols] = static_cast<int>(nonzeros);
  M.resizeNonZeros(nonzeros);
  int* inner = M.innerIndexPtr();
  double* values = M.valuePtr();
  bool mismatch = false;
#pragma omp parallel
  {
    GroupAccumulator accumulator(rows);
    auto group = make_group();
    int* row_out[kMaxColumnGroup];
    double* value_out[kMaxColumnGroup];
#pragma omp for schedule(dynamic, 64) reduction(|| : mismatch)
    for (std::int64_t G = 0; G < count_of_groups; ++G) {
      const Index J0 = groups[static_cast<std::size_t>(G)];
      const int width = width_of(G);
      accumulator.start(width);
      group(J0, width, accumulator);
      if (accumulator.touched() != count[static_cast<std::size_t>(G)]) {
        mismatch = true;  // the room counted for it is not its size: written nowhere
        continue;
      }
      for (int c = 0; c < width; ++c) {
        row_out[c] = inner + outer[J0 + c];
        value_out[c] = values + outer[J0 + c];
      }
      accumulator.write(row_out, value_out);
    }
  }
  if (mismatch)
    throw std::logic_error("form_column_groups: a group touched other rows in its second pass");
  return M;
}

}  // namespace signorini

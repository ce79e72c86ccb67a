#include "signorini/backend/node_block_matrix.hpp"

#include <algorithm>

namespace signorini {

std::optional<NodeBlockMatrix> NodeBlockMatrix::from_csr(Index n, const int* outer,
                                                         const int* inner, const double* values,
                                                         int max_group) {
  const auto same_pattern = [&](Index a, Index b) {
    return outer[a + 1] - outer[a] == outer[b + 1] - outer[b] &&
           std::equal(inner + outer[a], inner + outer[a + 1], inner + outer[b]);
  };
  max_group = std::clamp(max_group, 1, 8);  // multiply() keeps a group's sums on the stack
  NodeBlockMatrix m;
  // Groups: runs of consecutive rows with the same pattern (by symmetry of the pattern, of
  // columns too; checked below, block by block).
  std::vector<int> group_of(static_cast<std::size_t>(n));
  m.group_start_.push_back(0);
  for (Index i = 0; i < n; ++i) {
    const Index first = m.group_start_.back();
    if (i > first && (i - first >= max_group || !same_pattern(first, i)))
      m.group_start_.push_back(static_cast<int>(i));
    group_of[static_cast<std::size_t>(i)] = static_cast<int>(m.group_start_.size()) - 1;
  }
  m.group_start_.push_back(static_cast<int>(n));
  const Index groups = m.num_groups();
  if (groups == n) return std::nullopt;  // groups of one: CSR is smaller

  // Blocks: each row group's pattern (that of its first row) cut into whole column groups.
  m.block_start_.assign(static_cast<std::size_t>(groups + 1), 0);
  m.value_start_.assign(static_cast<std::size_t>(groups + 1), 0);
  for (Index g = 0; g < groups; ++g) {
    const int r0 = m.group_start_[static_cast<std::size_t>(g)];
    const int height = m.group_start_[static_cast<std::size_t>(g) + 1] - r0;
    std::int64_t entries = 0;
    for (int k = outer[r0]; k < outer[r0 + 1];) {
      const int c = inner[k];
      const int cg = group_of[static_cast<std::size_t>(c)];
      const int c0 = m.group_start_[static_cast<std::size_t>(cg)];
      const int width = m.group_start_[static_cast<std::size_t>(cg) + 1] - c0;
      // The whole column group must follow, in order.
      if (c != c0 || k + width > outer[r0 + 1]) return std::nullopt;
      for (int w = 0; w < width; ++w)
        if (inner[k + w] != c0 + w) return std::nullopt;
      m.block_group_.push_back(cg);
      entries += static_cast<std::int64_t>(height) * width;
      k += width;
    }
    m.block_start_[static_cast<std::size_t>(g) + 1] = static_cast<int>(m.block_group_.size());
    m.value_start_[static_cast<std::size_t>(g) + 1] =
        m.value_start_[static_cast<std::size_t>(g)] + entries;
  }
  // Values: block by block, row-major; the rows of a group share the pattern, so entry k of a
  // row's pattern is at the same place in each. In parallel over the groups: the first touch of
  // the copy's memory, which costs more than the copying on a virtual machine.
  m.value_count_ = static_cast<std::size_t>(m.value_start_.back());
  m.values_.reset(new double[m.value_count_]);  // not zeroed here: each thread writes its part
#pragma omp parallel for schedule(static)
  for (Index g = 0; g < groups; ++g) {
    const int r0 = m.group_start_[static_cast<std::size_t>(g)];
    const int height = m.group_start_[static_cast<std::size_t>(g) + 1] - r0;
    std::int64_t v = m.value_start_[static_cast<std::size_t>(g)];
    int position = 0;  // of the block's first entry within the row
    for (int b = m.block_start_[static_cast<std::size_t>(g)];
         b < m.block_start_[static_cast<std::size_t>(g) + 1]; ++b) {
      const int cg = m.block_group_[static_cast<std::size_t>(b)];
      const int width = m.group_start_[static_cast<std::size_t>(cg) + 1] -
                        m.group_start_[static_cast<std::size_t>(cg)];
      for (int r = 0; r < height; ++r)
        for (int w = 0; w < width; ++w)
          m.values_[static_cast<std::size_t>(v++)] = values[outer[r0 + r] + position + w];
      position += width;
    }
  }
  return m;
}

std::size_t NodeBlockMatrix::bytes() const {
  return group_start_.size() * sizeof(int) + block_start_.size() * sizeof(int) +
         value_start_.size() * sizeof(std::int64_t) + block_group_.size() * sizeof(int) +
         value_count_ * sizeof(double);
}

void NodeBlockMatrix::multiply(const double* x, double* y, double alpha, double beta,
                               bool parallel) const {
  const int* gs = group_start_.data();
  const int* bs = block_start_.data();
  const int* bg = block_group_.data();
  const std::int64_t* vs = value_start_.data();
  const double* values = values_.get();
  const auto row_group = [&](std::int64_t g) {
    const int r0 = gs[g];
    const int height = gs[g + 1] - r0;
    const double* v = values + vs[g];
    double s0 = 0.0, s1 = 0.0, s2 = 0.0;
    if (height == 3) {
      // The common case in 3D, unrolled: a node's three rows against each neighbour's block.
      for (int b = bs[g]; b < bs[g + 1]; ++b) {
        const int c0 = gs[bg[b]];
        const int width = gs[bg[b] + 1] - c0;
        if (width == 3) {
          const double x0 = x[c0], x1 = x[c0 + 1], x2 = x[c0 + 2];
          s0 += v[0] * x0 + v[1] * x1 + v[2] * x2;
          s1 += v[3] * x0 + v[4] * x1 + v[5] * x2;
          s2 += v[6] * x0 + v[7] * x1 + v[8] * x2;
          v += 9;
        } else {
          for (int w = 0; w < width; ++w) {
            s0 += v[w] * x[c0 + w];
            s1 += v[width + w] * x[c0 + w];
            s2 += v[2 * width + w] * x[c0 + w];
          }
          v += 3 * width;
        }
      }
      const double sums[3] = {s0, s1, s2};
      for (int r = 0; r < 3; ++r)
        y[r0 + r] = alpha * sums[r] + (beta == 0.0 ? 0.0 : beta * y[r0 + r]);
      return;
    }
    double sums[8] = {};  // groups are at most max_group (<= 8) rows
    for (int b = bs[g]; b < bs[g + 1]; ++b) {
      const int c0 = gs[bg[b]];
      const int width = gs[bg[b] + 1] - c0;
      for (int r = 0; r < height; ++r)
        for (int w = 0; w < width; ++w) sums[r] += v[r * width + w] * x[c0 + w];
      v += height * width;
    }
    for (int r = 0; r < height; ++r)
      y[r0 + r] = alpha * sums[r] + (beta == 0.0 ? 0.0 : beta * y[r0 + r]);
  };
  const auto groups = static_cast<std::int64_t>(num_groups());
  if (parallel) {
#pragma omp parallel for schedule(static)
    for (std::int64_t g = 0; g < groups; ++g) row_group(g);
  } else {
    for (std::int64_t g = 0; g < groups; ++g) row_group(g);
  }
}

void NodeBlockMatrix::multiply_transpose(const double* x, double* y, double alpha,
                                         double beta) const {
  const Index n = size();
  for (Index j = 0; j < n; ++j) y[j] = beta == 0.0 ? 0.0 : beta * y[j];
  for (Index g = 0; g < num_groups(); ++g) {
    const int r0 = group_start_[static_cast<std::size_t>(g)];
    const int height = group_start_[static_cast<std::size_t>(g) + 1] - r0;
    const double* v = values_.get() + value_start_[static_cast<std::size_t>(g)];
    for (int b = block_start_[static_cast<std::size_t>(g)];
         b < block_start_[static_cast<std::size_t>(g) + 1]; ++b) {
      const int cg = block_group_[static_cast<std::size_t>(b)];
      const int c0 = group_start_[static_cast<std::size_t>(cg)];
      const int width = group_start_[static_cast<std::size_t>(cg) + 1] - c0;
      for (int r = 0; r < height; ++r)
        for (int w = 0; w < width; ++w) y[c0 + w] += alpha * v[r * width + w] * x[r0 + r];
      v += height * width;
    }
  }
}

}  // namespace signorini

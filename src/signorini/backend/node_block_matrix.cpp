#include "signorini/backend/node_block_matrix.hpp"

#include <algorithm>
#include <cstring>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace signorini {

namespace {

// Two doubles as one SIMD operand (GCC's and Clang's vector extension: SSE2 on x86-64, NEON on
// ARM), loaded and stored unaligned.
using Pair = double __attribute__((vector_size(16)));
inline Pair load_pair(const double* p) {
  Pair r;
  std::memcpy(&r, p, sizeof r);
  return r;
}
inline void store_pair(double* p, Pair v) {
  std::memcpy(p, &v, sizeof v);
}

// The arrays of a NodeBlockMatrix, for upper_rows.
struct UpperArrays {
  const int* gs;           // group_start_
  const int* bs;           // block_start_
  const int* bg;           // block_group_
  const std::int64_t* vs;  // value_start_
  const double* values;    // values_
};

// Row groups g0 .. g1 - 1 of the upper blocks (multiply_upper): y += alpha A x for their rows,
// with the transposed blocks' sums into y where their rows are below the run's end, and into
// `beyond` (from the run's end on) where not.
void upper_rows(const UpperArrays a, int g0, int g1, const double* x, double* y, double* beyond,
                double alpha) {
  const int* gs = a.gs;
  const int* bs = a.bs;
  const int* bg = a.bg;
  const std::int64_t* vs = a.vs;
  const double* values = a.values;
  const int row1 = gs[g1];
  for (int g = g0; g < g1; ++g) {
    const int r0 = gs[g];
    const int height = gs[g + 1] - r0;
    const double* v = values + vs[g];
    int b = bs[g];
    const int b1 = bs[g + 1];
    if (height == 3) {
      // The common case in 3D: a node's three rows.
      // Twice the arithmetic of multiply_full per byte: in pairs (the first two columns of
      // a block's rows, two lanes of every x86-64 and ARM core) where the full product's
      // scalar code would leave this one bound by the arithmetic, not the memory.
      const double a0 = alpha * x[r0], a1 = alpha * x[r0 + 1], a2 = alpha * x[r0 + 2];
      const Pair a0p = {a0, a0}, a1p = {a1, a1}, a2p = {a2, a2};
      Pair p0 = {0.0, 0.0}, p1 = p0, p2 = p0;  // rows' sums over the blocks' first two columns
      double s0 = 0.0, s1 = 0.0, s2 = 0.0;     // and over their third
      const auto add_block = [&](const double* u, const double* xc) {
        const Pair xp = load_pair(xc);
        const double x2 = xc[2];
        p0 += load_pair(u) * xp;
        p1 += load_pair(u + 3) * xp;
        p2 += load_pair(u + 6) * xp;
        s0 += u[2] * x2;
        s1 += u[5] * x2;
        s2 += u[8] * x2;
      };
      if (b < b1 && bg[b] == g) {  // the diagonal block (the first: columns sorted), once
        add_block(v, x + r0);
        v += 9;
        ++b;
      }
      for (; b < b1; ++b) {
        const int c0 = gs[bg[b]];
        const int width = gs[bg[b] + 1] - c0;
        double* target = c0 < row1 ? y + c0 : beyond + (c0 - row1);
        if (width == 3) {
          add_block(v, x + c0);
          // The transposed block, into the rows of column group c.
          store_pair(target, load_pair(target) + (load_pair(v) * a0p + load_pair(v + 3) * a1p +
                                                  load_pair(v + 6) * a2p));
          target[2] += v[2] * a0 + v[5] * a1 + v[8] * a2;
        } else {
          for (int w = 0; w < width; ++w) {
            s0 += v[w] * x[c0 + w];
            s1 += v[width + w] * x[c0 + w];
            s2 += v[2 * width + w] * x[c0 + w];
            target[w] += v[w] * a0 + v[width + w] * a1 + v[2 * width + w] * a2;
          }
        }
        v += 3 * width;
      }
      y[r0] += alpha * (p0[0] + p0[1] + s0);
      y[r0 + 1] += alpha * (p1[0] + p1[1] + s1);
      y[r0 + 2] += alpha * (p2[0] + p2[1] + s2);
      continue;
    }
    double sums[8] = {};  // groups are at most max_group (<= 8) rows
    for (; b < b1; ++b) {
      const int c = bg[b];
      const int c0 = gs[c];
      const int width = gs[c + 1] - c0;
      double* target = c0 < row1 ? y + c0 : beyond + (c0 - row1);
      for (int r = 0; r < height; ++r)
        for (int w = 0; w < width; ++w) sums[r] += v[r * width + w] * x[c0 + w];
      if (c != g)
        for (int w = 0; w < width; ++w) {
          double s = 0.0;
          for (int r = 0; r < height; ++r) s += v[r * width + w] * x[r0 + r];
          target[w] += alpha * s;
        }
      v += height * width;
    }
    for (int r = 0; r < height; ++r) y[r0 + r] += alpha * sums[r];
  }
}

}  // namespace

std::optional<NodeBlockMatrix> NodeBlockMatrix::from_csr(Index n, const int* outer,
                                                         const int* inner, const double* values,
                                                         int max_group) {
  return build(n, outer, inner, values, max_group, false);
}

std::optional<NodeBlockMatrix> NodeBlockMatrix::from_symmetric_csr(Index n, const int* outer,
                                                                   const int* inner,
                                                                   const double* values,
                                                                   int max_group) {
  return build(n, outer, inner, values, max_group, true);
}

std::optional<NodeBlockMatrix> NodeBlockMatrix::build(Index n, const int* outer, const int* inner,
                                                      const double* values, int max_group,
                                                      bool upper) {
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

  // Blocks: each row group's pattern (that of its first row) cut into whole column groups; with
  // `upper`, those of column group >= the row group only.
  // reach_ (multiply_upper): the end of the last column group of each row group's blocks, at
  // least the row group's own end, as a running maximum.
  m.block_start_.assign(static_cast<std::size_t>(groups + 1), 0);
  m.value_start_.assign(static_cast<std::size_t>(groups + 1), 0);
  if (upper) m.reach_.reserve(static_cast<std::size_t>(groups));
  int reach = 0;
  for (Index g = 0; g < groups; ++g) {
    const int r0 = m.group_start_[static_cast<std::size_t>(g)];
    const int height = m.group_start_[static_cast<std::size_t>(g) + 1] - r0;
    reach = std::max(reach, r0 + height);
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
      if (!upper || cg >= g) {
        m.block_group_.push_back(cg);
        entries += static_cast<std::int64_t>(height) * width;
        reach = std::max(reach, c0 + width);
      }
      k += width;
    }
    if (upper) m.reach_.push_back(reach);
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
    for (int k = outer[r0]; k < outer[r0 + 1];) {
      const int cg = group_of[static_cast<std::size_t>(inner[k])];
      const int width = m.group_start_[static_cast<std::size_t>(cg) + 1] -
                        m.group_start_[static_cast<std::size_t>(cg)];
      const int position = k - outer[r0];  // of the block's first entry within the row
      if (!upper || cg > g) {
        for (int r = 0; r < height; ++r)
          for (int w = 0; w < width; ++w)
            m.values_[static_cast<std::size_t>(v++)] = values[outer[r0 + r] + position + w];
      } else if (cg == g) {
        // The diagonal block of a symmetric matrix from its upper triangle, mirrored: the
        // operator is then exactly symmetric, whatever the rounding of A's lower entries.
        for (int r = 0; r < height; ++r)
          for (int w = 0; w < width; ++w)
            m.values_[static_cast<std::size_t>(v++)] =
                values[outer[r0 + std::min(r, w)] + position + std::max(r, w)];
      }
      k += width;
    }
  }
  return m;
}

std::size_t NodeBlockMatrix::bytes() const {
  return group_start_.size() * sizeof(int) + block_start_.size() * sizeof(int) +
         value_start_.size() * sizeof(std::int64_t) + block_group_.size() * sizeof(int) +
         value_count_ * sizeof(double) + reach_.size() * sizeof(int);
}

void NodeBlockMatrix::multiply(const double* x, double* y, double alpha, double beta,
                               bool parallel) const {
  if (symmetric())
    multiply_upper(x, y, alpha, beta, parallel);
  else
    multiply_full(x, y, alpha, beta, parallel);
}

void NodeBlockMatrix::multiply_full(const double* x, double* y, double alpha, double beta,
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

// Upper blocks: row group g adds B x_c into its own rows and B^T x_g into the rows of column
// group c > g. Each thread takes a run of row groups (as many blocks each), starts by scaling its
// own rows of y by beta, and adds into its own rows directly: only it writes there, and the
// transposed blocks of a run reach forward only (c >= g). What a run adds beyond its last row
// goes into a buffer of its own (reach_: as far as the band of the ordering, some 190 kB for a
// brick of 88 x 88 x 44 nodes), which the threads owning those rows add after a barrier.
void NodeBlockMatrix::multiply_upper(const double* x, double* y, double alpha, double beta,
                                     bool parallel) const {
  const UpperArrays arrays{group_start_.data(), block_start_.data(), block_group_.data(),
                           value_start_.data(), values_.get()};
  const int* gs = arrays.gs;
  const int* bs = arrays.bs;
  const int groups = static_cast<int>(num_groups());
  int threads = 1;
#ifdef _OPENMP
  if (parallel) threads = std::max(1, omp_get_max_threads());
#endif
  threads = std::min(threads, std::max(1, groups));
  // Runs of row groups with as many blocks each: first[t] .. first[t + 1] - 1.
  std::vector<int> first(static_cast<std::size_t>(threads) + 1, groups);
  const std::int64_t blocks = bs[groups];
  for (int t = 0; t < threads; ++t)
    first[static_cast<std::size_t>(t)] =
        static_cast<int>(std::lower_bound(bs, bs + groups, blocks * t / threads) - bs);
  first[0] = 0;
  std::vector<std::vector<double>> spill(static_cast<std::size_t>(threads));

  const auto run = [&](int t) {
    const int g0 = first[static_cast<std::size_t>(t)];
    const int g1 = first[static_cast<std::size_t>(t) + 1];
    const int row0 = gs[g0];
    const int row1 = gs[g1];
    for (int i = row0; i < row1; ++i) y[i] = beta == 0.0 ? 0.0 : beta * y[i];
    auto& own_spill = spill[static_cast<std::size_t>(t)];
    if (g1 > g0)
      own_spill.assign(static_cast<std::size_t>(std::max(0, reach_[g1 - 1] - row1)), 0.0);
    upper_rows(arrays, g0, g1, x, y, own_spill.data(), alpha);
  };
  // Adds the buffers of the runs before t that reach into t's rows.
  const auto gather = [&](int t) {
    const int row0 = gs[first[static_cast<std::size_t>(t)]];
    const int row1 = gs[first[static_cast<std::size_t>(t) + 1]];
    for (int s = 0; s < t; ++s) {
      const auto& buffer = spill[static_cast<std::size_t>(s)];
      const int start = gs[first[static_cast<std::size_t>(s) + 1]];  // its first row
      const int lo = std::max(row0, start);
      const int hi = std::min(row1, start + static_cast<int>(buffer.size()));
      for (int i = lo; i < hi; ++i) y[i] += buffer[static_cast<std::size_t>(i - start)];
    }
  };
  if (threads == 1) {
    run(0);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    run(t);
#pragma omp barrier
    gather(t);
  }
}

void NodeBlockMatrix::multiply_transpose(const double* x, double* y, double alpha,
                                         double beta) const {
  if (symmetric()) {
    multiply_upper(x, y, alpha, beta, false);
    return;
  }
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

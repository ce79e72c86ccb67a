#include "signorini/iterative/smoothed_aggregation.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/chebyshev_smoother.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/sparse_columns.hpp"

namespace signorini {

namespace {

// The unknowns of each node: node a owns unknowns start[a] .. start[a+1]; nodes renumbered
// 0 .. m-1 in order of appearance.
std::vector<Index> node_starts(const std::vector<Index>& node_of_unknown) {
  std::vector<Index> start;
  Index previous = -1;
  for (std::size_t i = 0; i < node_of_unknown.size(); ++i) {
    if (i == 0 || node_of_unknown[i] != previous) start.push_back(static_cast<Index>(i));
    previous = node_of_unknown[i];
  }
  start.push_back(static_cast<Index>(node_of_unknown.size()));
  return start;
}

// The strong couplings between nodes (the node graph of A, self excluded), from the Frobenius
// norms of A's node blocks.
void strength_graph(const SparseView& A, const std::vector<Index>& start,
                    const std::vector<Index>& node_of, double theta, std::vector<Index>& offsets,
                    std::vector<Index>& adjacency) {
  const auto m = static_cast<Index>(start.size()) - 1;
  // Rows past the numbered unknowns (another rank's, aggregate_level) are not nodes of the graph.
  const auto n = static_cast<Index>(node_of.size());
  std::vector<double> diagonal(static_cast<std::size_t>(m), 0.0);
  for (Index a = 0; a < m; ++a)
    for (Index j = start[static_cast<std::size_t>(a)]; j < start[static_cast<std::size_t>(a) + 1];
         ++j)
      for (SparseView::InnerIterator it(A, j); it; ++it)
        if (it.row() < n && node_of[static_cast<std::size_t>(it.row())] == a)
          diagonal[static_cast<std::size_t>(a)] += it.value() * it.value();
  for (double& d : diagonal) d = std::sqrt(d);

  offsets.assign(1, 0);
  adjacency.clear();
  std::vector<double> block(static_cast<std::size_t>(m), 0.0);
  std::vector<char> seen(static_cast<std::size_t>(m), 0);
  std::vector<Index> touched;
  for (Index a = 0; a < m; ++a) {
    touched.clear();
    for (Index j = start[static_cast<std::size_t>(a)]; j < start[static_cast<std::size_t>(a) + 1];
         ++j)
      for (SparseView::InnerIterator it(A, j); it; ++it) {
        if (it.row() >= n) continue;
        const Index b = node_of[static_cast<std::size_t>(it.row())];
        if (b == a) continue;
        if (!seen[static_cast<std::size_t>(b)]) {
          seen[static_cast<std::size_t>(b)] = 1;
          touched.push_back(b);
        }
        block[static_cast<std::size_t>(b)] += it.value() * it.value();
      }
    for (const Index b : touched) {
      const auto u = static_cast<std::size_t>(b);
      // ||A_ab||_F >= theta sqrt(||A_aa|| ||A_bb||), squared.
      if (block[u] > 0.0 &&
          block[u] >= theta * theta * diagonal[static_cast<std::size_t>(a)] * diagonal[u])
        adjacency.push_back(b);
      block[u] = 0.0;
      seen[u] = 0;
    }
    offsets.push_back(static_cast<Index>(adjacency.size()));
  }
}

struct Tentative {
  SparseMatrix P;
  Matrix coarse_null_space;
  std::vector<Index> coarse_node;
};

// P_tent: on every aggregate, the orthonormal basis Q_a of the near-null space's rows there
// (B_a = Q_a R_a, column-pivoted to drop the modes an aggregate cannot carry, e.g. rotations on
// an aggregate of one node).
Tentative tentative_prolongation(const Matrix& B, const std::vector<Index>& start,
                                 const std::vector<Index>& aggregate, Index aggregates) {
  const Index n = B.rows();
  const Index k = B.cols();
  std::vector<std::vector<Index>> rows(static_cast<std::size_t>(aggregates));
  for (std::size_t a = 0; a + 1 < start.size(); ++a)
    for (Index i = start[a]; i < start[a + 1]; ++i)
      rows[static_cast<std::size_t>(aggregate[a])].push_back(i);

  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(static_cast<std::size_t>(n * k));
  std::vector<Matrix> blocks;
  blocks.reserve(rows.size());
  Tentative t;
  Index coarse = 0;
  for (std::size_t a = 0; a < rows.size(); ++a) {
    const auto s = static_cast<Index>(rows[a].size());
    Matrix Ba(s, k);
    for (Index r = 0; r < s; ++r) Ba.row(r) = B.row(rows[a][static_cast<std::size_t>(r)]);
    Eigen::ColPivHouseholderQR<Matrix> qr(Ba);
    qr.setThreshold(1e-10);
    const Index rank = qr.rank();
    const Matrix Q = qr.householderQ() * Matrix::Identity(s, rank);
    // B_a P = Q R, so B_a = Q (R P^T): the coarse rows of the near-null space.
    Matrix R = Matrix(qr.matrixR().topRows(rank).triangularView<Eigen::Upper>());
    blocks.push_back(R * qr.colsPermutation().transpose());
    for (Index r = 0; r < s; ++r)
      for (Index c = 0; c < rank; ++c)
        if (Q(r, c) != 0.0)
          entries.emplace_back(static_cast<int>(rows[a][static_cast<std::size_t>(r)]),
                               static_cast<int>(coarse + c), Q(r, c));
    for (Index c = 0; c < rank; ++c) t.coarse_node.push_back(static_cast<Index>(a));
    coarse += rank;
  }
  t.P.resize(n, coarse);
  t.P.setFromTriplets(entries.begin(), entries.end());
  t.coarse_null_space.resize(coarse, k);
  Index row = 0;
  for (const Matrix& b : blocks) {
    t.coarse_null_space.middleRows(row, b.rows()) = b;
    row += b.rows();
  }
  return t;
}

}  // namespace

// A dozen Lanczos steps give the prolongation smoother's damping to well under a per cent, more
// than it needs.
double jacobi_spectral_radius(const SparseMatrix& A) {
  HostBackend host;
  SymmetricMatrixOperator op(A);
  const DeviceVector dinv = to_device(host, Vector(A.diagonal().cwiseInverse()));
  DiagonalPreconditioner jacobi(dinv);
  const DeviceVector start = to_device(host, eigenvalue_estimate_start(A.rows()));
  return estimate_largest_eigenvalue(op, jacobi, start, ChebyshevOptions{}.lanczos_steps);
}

std::vector<Index> aggregate_nodes(const std::vector<Index>& offsets,
                                   const std::vector<Index>& adjacency, std::vector<Index> order) {
  const auto m = static_cast<Index>(offsets.size()) - 1;
  if (!order.empty() && static_cast<Index>(order.size()) != m)
    throw NumericalError(fmt::format("aggregation: an order of {} nodes for {}", order.size(), m));
  std::vector<Index> visit = std::move(order);
  if (visit.empty()) {
    visit.resize(static_cast<std::size_t>(m));
    std::iota(visit.begin(), visit.end(), Index{0});
  }
  std::vector<Index> agg(static_cast<std::size_t>(m), -1);
  auto neighbours = [&](Index a) {
    return std::pair{adjacency.begin() + offsets[static_cast<std::size_t>(a)],
                     adjacency.begin() + offsets[static_cast<std::size_t>(a) + 1]};
  };
  Index count = 0;
  // 1: a node whose neighbours are all free starts an aggregate with them (a 3 x 3 patch of
  // nodes on a quadrilateral mesh).
  for (const Index a : visit) {
    if (agg[static_cast<std::size_t>(a)] >= 0) continue;
    auto [first, last] = neighbours(a);
    bool free = true;
    for (auto it = first; it != last && free; ++it) free = agg[static_cast<std::size_t>(*it)] < 0;
    if (!free) continue;
    agg[static_cast<std::size_t>(a)] = count;
    for (auto it = first; it != last; ++it) agg[static_cast<std::size_t>(*it)] = count;
    ++count;
  }
  // 2: a left-over node joins the aggregate of a neighbour from step 1.
  const std::vector<Index> first_pass = agg;
  for (const Index a : visit) {
    if (agg[static_cast<std::size_t>(a)] >= 0) continue;
    auto [first, last] = neighbours(a);
    for (auto it = first; it != last; ++it)
      if (first_pass[static_cast<std::size_t>(*it)] >= 0) {
        agg[static_cast<std::size_t>(a)] = first_pass[static_cast<std::size_t>(*it)];
        break;
      }
  }
  // 3: what is still left (no strong neighbour aggregated) forms aggregates of its own.
  for (const Index a : visit) {
    if (agg[static_cast<std::size_t>(a)] >= 0) continue;
    agg[static_cast<std::size_t>(a)] = count;
    auto [first, last] = neighbours(a);
    for (auto it = first; it != last; ++it)
      if (agg[static_cast<std::size_t>(*it)] < 0) agg[static_cast<std::size_t>(*it)] = count;
    ++count;
  }
  return agg;
}

namespace {

// -omega / a_jj for the columns j of A (with A's columns of the first unknowns only, their
// diagonal): the smoothing step's row scaling. (An SPD matrix has a positive diagonal; a zero
// one leaves its row unsmoothed.)
Vector smoothing_scale(const SparseView& A, double omega) {
  Vector scale = Vector::Zero(A.cols());
#pragma omp parallel for schedule(static)
  for (Index j = 0; j < A.cols(); ++j)
    for (SparseView::InnerIterator a(A, j); a; ++a)
      if (a.row() == j) {
        if (a.value() != 0.0) scale(j) = -omega / a.value();
        break;
      }
  return scale;
}

}  // namespace

// P = (I - omega D^{-1} A) T, in parallel over groups of columns (Eigen's general sparse product
// takes ten times longer, on one thread): the columns of one aggregate have the same rows in T,
// so they are formed together, each entry of A read once for all of them.
SparseMatrix smoothed_prolongation(const SparseView& A, const SparseMatrix& T, double omega) {
  const Vector scale = smoothing_scale(A, omega);
  const std::vector<char> repeats = repeats_previous_column(A);
  const int* t_outer = T.outerIndexPtr();
  const int* t_inner = T.innerIndexPtr();
  const double* t_values = T.valuePtr();
  const auto make_group = [&] {
    return [&](Index J0, int width, GroupAccumulator& out) {
      const bool counting = out.counting();
      with_group_width(width, [&](auto fixed) {
        constexpr int W = decltype(fixed)::value;
        const int w = W > 0 ? W : width;
        double t[kMaxColumnGroup];
        const int length = t_outer[J0 + 1] - t_outer[J0];
        const int* rows = t_inner + t_outer[J0];
        for (int k = 0; k < length;) {
          const Index i = rows[k];
          if (counting) {
            out.row(i);
            // The rows of A(:, i) are those of A(:, i-1), taken just before: nothing new.
            if (!(k > 0 && rows[k - 1] == i - 1 && repeats[static_cast<std::size_t>(i)]))
              for (SparseView::InnerIterator a(A, i); a; ++a) out.row(a.row());
            ++k;
            continue;
          }
          if (node_columns(rows, k, length, A.cols(), repeats) == 3) {
            // A node's three columns of A at once: one look-up of each row they share.
            double t3[3][kMaxColumnGroup];
            for (int r = 0; r < 3; ++r) {
              for (int c = 0; c < w; ++c) t3[r][c] = t_values[t_outer[J0 + c] + k + r];
              double* own = out.row(i + r);
              for (int c = 0; c < w; ++c) own[c] += t3[r][c];
            }
            const ColumnsOfNode a(A, i);
            for (int e = 0; e < a.length; ++e) {
              const double s = scale[a.rows[e]];
              const double a0 = s * a.values[0][e], a1 = s * a.values[1][e],
                           a2 = s * a.values[2][e];
              double* v = out.row(a.rows[e]);
              for (int c = 0; c < w; ++c) v[c] += a0 * t3[0][c] + a1 * t3[1][c] + a2 * t3[2][c];
            }
            k += 3;
            continue;
          }
          for (int c = 0; c < w; ++c) t[c] = t_values[t_outer[J0 + c] + k];
          double* own = out.row(i);
          for (int c = 0; c < w; ++c) own[c] += t[c];
          for (SparseView::InnerIterator a(A, i); a; ++a) {
            const double s = scale[a.row()] * a.value();
            double* v = out.row(a.row());
            for (int c = 0; c < w; ++c) v[c] += s * t[c];
          }
          ++k;
        }
      });
    };
  };
  return form_column_groups(A.rows(), T.cols(), same_row_groups(T), make_group);
}

SparseMatrix smoothed_prolongation_rows(const SparseView& A, const SparseMatrix& T, double omega) {
  const Index k = A.cols();
  const Index m = T.cols();
  if (k > A.rows() || T.rows() != A.rows())
    throw NumericalError(fmt::format("smoothed prolongation: A is {}x{}, T {}x{}", A.rows(),
                                     A.cols(), T.rows(), T.cols()));
  using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  const RowMatrix Tr(T);
  const Vector scale = smoothing_scale(A, omega);
  int threads = 1;
#ifdef _OPENMP
  if (k >= 20000) threads = omp_get_max_threads();
#endif
  // Each thread a contiguous block of rows, into a CSR fragment of its own (Gustavson's row
  // product with a dense accumulator); the fragments are then laid end to end.
  struct Fragment {
    std::vector<int> lengths, columns;
    std::vector<double> values;
  };
  std::vector<Fragment> fragments(static_cast<std::size_t>(threads));
#pragma omp parallel num_threads(threads)
  {
    int t = 0;
#ifdef _OPENMP
    t = omp_get_thread_num();
#endif
    Fragment& out = fragments[static_cast<std::size_t>(t)];
    const Index first = k * t / threads;
    const Index last = k * (t + 1) / threads;
    std::vector<double> sum(static_cast<std::size_t>(m), 0.0);
    std::vector<Index> mark(static_cast<std::size_t>(m), -1);
    std::vector<int> touched;
    for (Index i = first; i < last; ++i) {
      touched.clear();
      const auto add = [&](int c, double v) {
        const auto u = static_cast<std::size_t>(c);
        if (mark[u] != i) {
          mark[u] = i;
          sum[u] = 0.0;
          touched.push_back(c);
        }
        sum[u] += v;
      };
      for (RowMatrix::InnerIterator ti(Tr, i); ti; ++ti)
        add(static_cast<int>(ti.col()), ti.value());
      for (SparseView::InnerIterator a(A, i); a; ++a) {
        const double s = scale(i) * a.value();
        for (RowMatrix::InnerIterator tj(Tr, a.row()); tj; ++tj)
          add(static_cast<int>(tj.col()), s * tj.value());
      }
      // Exact zeros kept, as smoothed_prolongation keeps them: the columns of one aggregate
      // then share their rows, which the Galerkin product forms together (sparse_columns.hpp).
      std::sort(touched.begin(), touched.end());
      for (const int c : touched) {
        out.columns.push_back(c);
        out.values.push_back(sum[static_cast<std::size_t>(c)]);
      }
      out.lengths.push_back(static_cast<int>(touched.size()));
    }
  }
  std::size_t nonzeros = 0;
  for (const Fragment& f : fragments) nonzeros += f.columns.size();
  RowMatrix P(k, m);
  P.resizeNonZeros(static_cast<Index>(nonzeros));
  int* outer = P.outerIndexPtr();
  outer[0] = 0;
  Index row = 0;
  std::size_t at = 0;
  for (const Fragment& f : fragments) {
    for (const int length : f.lengths) {
      outer[row + 1] = outer[row] + length;
      ++row;
    }
    std::copy(f.columns.begin(), f.columns.end(), P.innerIndexPtr() + at);
    std::copy(f.values.begin(), f.values.end(), P.valuePtr() + at);
    at += f.columns.size();
  }
  return SparseMatrix(P);
}

AggregationLevel aggregate_level(const SparseView& A, const Matrix& near_null_space,
                                 const std::vector<Index>& node_of_unknown,
                                 const std::vector<Index>& place_of, double strength_threshold) {
  const auto n = static_cast<Index>(node_of_unknown.size());
  if (A.cols() != n || A.rows() < n || near_null_space.rows() != n)
    throw NumericalError(
        fmt::format("aggregation: A is {}x{}, the near-null space has {} rows, {} node numbers",
                    A.rows(), A.cols(), near_null_space.rows(), n));
  const std::vector<Index>& node_of = node_of_unknown;
  const std::vector<Index> start = node_starts(node_of);
  const auto m = static_cast<Index>(start.size()) - 1;
  // Compact node numbers 0 .. m-1 (a node whose unknowns were not consecutive would count as
  // several: a coarser aggregation, nothing worse).
  std::vector<Index> compact(node_of.size());
  for (Index a = 0; a < m; ++a)
    for (Index i = start[static_cast<std::size_t>(a)]; i < start[static_cast<std::size_t>(a) + 1];
         ++i)
      compact[static_cast<std::size_t>(i)] = a;
  std::vector<Index> offsets, adjacency;
  strength_graph(A, start, compact, strength_threshold, offsets, adjacency);
  std::vector<Index> order(static_cast<std::size_t>(m));
  std::iota(order.begin(), order.end(), Index{0});
  const auto place = [&](Index a) {
    const Index id = node_of[static_cast<std::size_t>(start[static_cast<std::size_t>(a)])];
    return place_of.empty() ? id : place_of[static_cast<std::size_t>(id)];
  };
  const auto before = [&](Index a, Index b) { return place(a) < place(b); };
  if (!std::is_sorted(order.begin(), order.end(), before)) {
    std::stable_sort(order.begin(), order.end(), before);
    // Each node's neighbours in that order too: a left-over node joins the aggregate of its
    // first aggregated neighbour.
    for (Index a = 0; a < m; ++a)
      std::sort(adjacency.begin() + offsets[static_cast<std::size_t>(a)],
                adjacency.begin() + offsets[static_cast<std::size_t>(a) + 1], before);
  }
  std::vector<Index> aggregate = aggregate_nodes(offsets, adjacency, std::move(order));
  // The aggregates numbered by their first node in the level's own order, so that the coarse
  // unknowns keep the fine ones' locality; their formation order becomes the next level's.
  std::vector<Index> number(aggregate.size(), -1);
  std::vector<Index> formed;
  for (Index& a : aggregate) {
    Index& k = number[static_cast<std::size_t>(a)];
    if (k < 0) {
      k = static_cast<Index>(formed.size());
      formed.push_back(a);
    }
    a = k;
  }
  const auto aggregates = static_cast<Index>(formed.size());
  Tentative t = tentative_prolongation(near_null_space, start, aggregate, aggregates);
  return {std::move(t.P), std::move(t.coarse_null_space), std::move(t.coarse_node),
          std::move(formed)};
}

MultigridHierarchy smoothed_aggregation_hierarchy(const SparseMatrix& A, Matrix near_null_space,
                                                  std::vector<Index> node_of_unknown,
                                                  const SmoothedAggregationOptions& options) {
  if (A.rows() != A.cols() || near_null_space.rows() != A.rows() ||
      static_cast<Index>(node_of_unknown.size()) != A.rows() || near_null_space.cols() < 1)
    throw NumericalError(fmt::format(
        "smoothed aggregation: A is {}x{}, the near-null space {}x{}, {} node numbers", A.rows(),
        A.cols(), near_null_space.rows(), near_null_space.cols(), node_of_unknown.size()));
  MultigridHierarchy h;
  // Reserved: `current` points into coarse_operators, which must not move.
  h.coarse_operators.reserve(static_cast<std::size_t>(options.max_levels));
  const SparseMatrix* current = &A;
  Matrix B = std::move(near_null_space);
  std::vector<Index> node_of = std::move(node_of_unknown);
  // Per node number of the current level, its place in the aggregation's order (empty: the
  // number itself). The fine level's numbers are the mesh's nodes; a coarse node's place is when
  // its aggregate was formed, so that each level is aggregated as if no unknown had been
  // renumbered (the greedy aggregation depends on the order: in the order of a mesh generator
  // it made fewer, fuller aggregates than in a locality order, 67 CG iterations against 87 on
  // Hertz's ball at 940,094 unknowns).
  std::vector<Index> place_of;
  while (current->rows() > options.max_coarse_unknowns &&
         static_cast<int>(h.prolongations.size()) + 1 < options.max_levels) {
    const SparseMatrix& Al = *current;
    AggregationLevel t = aggregate_level(Al, B, node_of, place_of, options.strength_threshold);
    place_of = std::move(t.place_of);
    if (static_cast<double>(t.tentative.cols()) >
        (1.0 - options.min_reduction) * static_cast<double>(Al.rows()))
      break;  // no real coarsening left (e.g. a level of isolated nodes)
    // P = (I - omega D^{-1} A) P_tent, omega = 4 / (3 rho(D^{-1} A)) (Vanek et al., eq. 4.4).
    const double radius = jacobi_spectral_radius(Al);
    h.jacobi_radii.push_back(radius);
    const double omega = 4.0 / (3.0 * radius);
    SparseMatrix P = smoothed_prolongation(Al, t.tentative, omega);
    h.tentatives.push_back(std::move(t.tentative));  // (for contact_prolongation.hpp)
    h.omegas.push_back(omega);
    h.coarse_operators.push_back(galerkin_product(Al, P));
    h.prolongations.push_back(std::move(P));
    current = &h.coarse_operators.back();
    B = std::move(t.coarse_null_space);
    node_of = std::move(t.coarse_node);
  }
  if (!h.prolongations.empty()) h.kind = HierarchyKind::Aggregation;
  return h;
}

}  // namespace signorini

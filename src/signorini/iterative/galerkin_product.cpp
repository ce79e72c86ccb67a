#include "signorini/iterative/galerkin_product.hpp"

#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/iterative/sparse_columns.hpp"

namespace signorini {

SparseMatrix galerkin_product(const SparseView& A, const SparseMatrix& P) {
  if (A.cols() > A.rows() || P.rows() != A.rows())
    throw NumericalError("galerkin_product: A must have as many rows as P and no more columns");
  // Columns of A past k (another rank's unknowns) are rows of E that this rank does not hold:
  // (E^T P)(:, J) = sum over i < k of p_iJ A(:, i), and P^T (E^T P) = (P^T E P)^T.
  const Index k_columns = A.cols();
  const int* p_outer = P.outerIndexPtr();
  const int* p_inner = P.innerIndexPtr();
  const double* p_values = P.valuePtr();
  const std::vector<Index> groups = same_row_groups(P);
  const GroupRows rows_of_P = group_rows(P, groups);
  const std::vector<char> repeats = repeats_previous_column(A);
  // A group of columns J of P with the same rows (an aggregate's) in two steps: (A P)(:, J) =
  // sum over the fine i in the group's rows of p_iJ A(:, i), gathered first in a fine
  // accumulator of the thread's own, then P^T times it, by the rows of P (group_rows). Done at
  // once, as a triple loop, the rows of P would be walked again for every pair (i, k): in 3D, with
  // the six rigid-body modes in P, some twenty times the work (docs/performance.md). Each index of
  // A and of P is read once for the whole group.
  const auto make_group = [&] {
    return [&, fine = GroupAccumulator(A.rows())](Index J0, int width,
                                                  GroupAccumulator& coarse) mutable {
      const bool counting = coarse.counting();
      fine.start(width, counting);
      with_group_width(width, [&](auto fixed) {
        constexpr int W = decltype(fixed)::value;
        const int w = W > 0 ? W : width;
        double p[kMaxColumnGroup];
        const int length = p_outer[J0 + 1] - p_outer[J0];
        const int* rows = p_inner + p_outer[J0];
        for (int k = 0; k < length;) {
          const Index i = rows[k];
          if (i >= k_columns) {
            ++k;
            continue;
          }
          if (counting) {
            // The rows of A(:, i) are those of A(:, i-1), taken just before: nothing new.
            if (!(k > 0 && rows[k - 1] == i - 1 && repeats[static_cast<std::size_t>(i)]))
              for (SparseView::InnerIterator a(A, i); a; ++a) fine.row(a.row());
            ++k;
            continue;
          }
          if (node_columns(rows, k, length, k_columns, repeats) == 3) {
            // A node's three columns of A at once: one look-up of each row they share.
            double p3[3][kMaxColumnGroup];
            for (int r = 0; r < 3; ++r)
              for (int c = 0; c < w; ++c) p3[r][c] = p_values[p_outer[J0 + c] + k + r];
            const ColumnsOfNode a(A, i);
            for (int e = 0; e < a.length; ++e) {
              double* f = fine.row(a.rows[e]);
              const double a0 = a.values[0][e], a1 = a.values[1][e], a2 = a.values[2][e];
              for (int c = 0; c < w; ++c) f[c] += a0 * p3[0][c] + a1 * p3[1][c] + a2 * p3[2][c];
            }
            k += 3;
            continue;
          }
          for (int c = 0; c < w; ++c) p[c] = p_values[p_outer[J0 + c] + k];
          for (SparseView::InnerIterator a(A, i); a; ++a) {
            double* f = fine.row(a.row());
            const double value = a.value();
            for (int c = 0; c < w; ++c) f[c] += value * p[c];
          }
          ++k;
        }
        fine.for_each([&](Index k, const double* f) {
          // Counting: row k of P lies in the groups of row k-1, which is (or will be) taken.
          if (counting && k > 0 && rows_of_P.repeats[static_cast<std::size_t>(k)] &&
              fine.has(k - 1))
            return;
          const auto first = static_cast<std::size_t>(rows_of_P.start[static_cast<std::size_t>(k)]);
          const auto last =
              static_cast<std::size_t>(rows_of_P.start[static_cast<std::size_t>(k) + 1]);
          double fk[kMaxColumnGroup];
          for (int c = 0; c < w; ++c) fk[c] = f[c];
          for (std::size_t e = first; e < last; ++e) {
            const auto G = static_cast<std::size_t>(rows_of_P.group[e]);
            const Index J = groups[G];
            const auto width_J = static_cast<int>(groups[G + 1] - J);
            const int at = rows_of_P.position[e];
            for (int d = 0; d < width_J; ++d) {
              double* v = coarse.row(J + d);
              if (counting) continue;
              const double value = p_values[p_outer[J + d] + at];
              for (int c = 0; c < w; ++c) v[c] += value * fk[c];
            }
          }
        });
      });
    };
  };
  return form_column_groups(P.cols(), P.cols(), groups, make_group);
}

}  // namespace signorini

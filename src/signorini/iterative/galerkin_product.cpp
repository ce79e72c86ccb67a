#include "signorini/iterative/galerkin_product.hpp"

#include <algorithm>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {

SparseMatrix galerkin_product(const SparseMatrix& A, const SparseMatrix& P) {
  if (A.rows() != A.cols() || P.rows() != A.rows())
    throw NumericalError("galerkin_product: A must be square with as many rows as P");
  const Index m = P.cols();
  // Rows of P (its columns are P's CSC storage).
  const Eigen::SparseMatrix<double, Eigen::RowMajor, int> Pr(P);
  std::vector<std::vector<int>> col_rows(static_cast<std::size_t>(m));
  std::vector<std::vector<double>> col_values(static_cast<std::size_t>(m));
  const std::int64_t columns = m;

#pragma omp parallel
  {
    std::vector<double> accumulator(static_cast<std::size_t>(m), 0.0);
    std::vector<char> used(static_cast<std::size_t>(m), 0);
    std::vector<int> pattern;
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t J = 0; J < columns; ++J) {
      // Column J of P^T A P = sum over fine i in column J of P: p_iJ (P^T A)(:, i), and by the
      // symmetry of A, column i of A is its row i.
      pattern.clear();
      for (SparseMatrix::InnerIterator pi(P, static_cast<Index>(J)); pi; ++pi) {
        const auto i = static_cast<Index>(pi.row());
        for (SparseMatrix::InnerIterator ak(A, i); ak; ++ak) {
          const double w = pi.value() * ak.value();
          for (decltype(Pr)::InnerIterator pk(Pr, ak.row()); pk; ++pk) {
            const auto I = static_cast<std::size_t>(pk.col());
            if (!used[I]) {
              used[I] = 1;
              pattern.push_back(static_cast<int>(I));
            }
            accumulator[I] += w * pk.value();
          }
        }
      }
      std::sort(pattern.begin(), pattern.end());
      auto& rows = col_rows[static_cast<std::size_t>(J)];
      auto& values = col_values[static_cast<std::size_t>(J)];
      rows.reserve(pattern.size());
      values.reserve(pattern.size());
      for (const int I : pattern) {
        const auto u = static_cast<std::size_t>(I);
        if (accumulator[u] != 0.0) {
          rows.push_back(I);
          values.push_back(accumulator[u]);
        }
        accumulator[u] = 0.0;
        used[u] = 0;
      }
    }
  }

  Index nonzeros = 0;
  for (const auto& r : col_rows) nonzeros += static_cast<Index>(r.size());
  SparseMatrix C(m, m);
  C.resizeNonZeros(nonzeros);
  int* outer = C.outerIndexPtr();
  Index k = 0;
  for (Index J = 0; J < m; ++J) {
    outer[J] = static_cast<int>(k);
    const auto& rows = col_rows[static_cast<std::size_t>(J)];
    const auto& values = col_values[static_cast<std::size_t>(J)];
    std::copy(rows.begin(), rows.end(), C.innerIndexPtr() + k);
    std::copy(values.begin(), values.end(), C.valuePtr() + k);
    k += static_cast<Index>(rows.size());
  }
  outer[m] = static_cast<int>(k);
  return C;
}

}  // namespace signorini

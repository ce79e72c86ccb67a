#include "signorini/iterative/galerkin_product.hpp"

#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/iterative/sparse_columns.hpp"

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
    // Column J in two steps: (A P)(:, J) = sum over fine i in column J of P of p_iJ A(:, i),
    // gathered first, then P^T times it, by the rows of P. Done at once, as a triple loop, the
    // rows of P would be walked again for every pair (i, k): in 3D, with the six rigid-body
    // modes in P, some twenty times the work (docs/performance.md).
    ColumnAccumulator fine(A.rows());
    ColumnAccumulator coarse(m);
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t J = 0; J < columns; ++J) {
      for (SparseMatrix::InnerIterator pi(P, static_cast<Index>(J)); pi; ++pi)
        for (SparseMatrix::InnerIterator ak(A, pi.row()); ak; ++ak)
          fine.add(ak.row(), pi.value() * ak.value());
      fine.drain([&](Index k, double w) {
        for (decltype(Pr)::InnerIterator pk(Pr, k); pk; ++pk) coarse.add(pk.col(), w * pk.value());
      });
      coarse.flush(col_rows[static_cast<std::size_t>(J)], col_values[static_cast<std::size_t>(J)]);
    }
  }
  return assemble_columns(m, col_rows, col_values);
}

}  // namespace signorini

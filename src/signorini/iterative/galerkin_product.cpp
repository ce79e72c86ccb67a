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
    ColumnAccumulator accumulator(m);
#pragma omp for schedule(dynamic, 256)
    for (std::int64_t J = 0; J < columns; ++J) {
      // Column J of P^T A P = sum over fine i in column J of P: p_iJ (P^T A)(:, i), and by the
      // symmetry of A, column i of A is its row i.
      for (SparseMatrix::InnerIterator pi(P, static_cast<Index>(J)); pi; ++pi) {
        const auto i = static_cast<Index>(pi.row());
        for (SparseMatrix::InnerIterator ak(A, i); ak; ++ak) {
          const double w = pi.value() * ak.value();
          for (decltype(Pr)::InnerIterator pk(Pr, ak.row()); pk; ++pk)
            accumulator.add(pk.col(), w * pk.value());
        }
      }
      accumulator.flush(col_rows[static_cast<std::size_t>(J)],
                        col_values[static_cast<std::size_t>(J)]);
    }
  }
  return assemble_columns(m, col_rows, col_values);
}

}  // namespace signorini

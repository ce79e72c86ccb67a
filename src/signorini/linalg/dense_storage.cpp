#include "signorini/linalg/dense_storage.hpp"

#include <algorithm>

namespace signorini {

SparseMatrix dense_stored_matrix(Index n) {
  SparseMatrix A(n, n);
  A.resizeNonZeros(n * n);  // compressed, filled directly
  for (Index col = 0; col <= n; ++col) A.outerIndexPtr()[col] = static_cast<int>(col * n);
  for (Index col = 0; col < n; ++col)
    for (Index row = 0; row < n; ++row) A.innerIndexPtr()[col * n + row] = static_cast<int>(row);
  std::fill(A.valuePtr(), A.valuePtr() + n * n, 0.0);
  return A;
}

bool is_dense_stored(const SparseMatrix& A) {
  const Index n = A.rows();
  if (A.cols() != n || !A.isCompressed() || A.nonZeros() != n * n) return false;
  for (Index col = 0; col < n; ++col) {
    if (A.outerIndexPtr()[col] != col * n) return false;
    const int* rows = A.innerIndexPtr() + col * n;
    for (Index row = 0; row < n; ++row)
      if (rows[row] != row) return false;
  }
  return true;
}

std::optional<Eigen::Map<const Eigen::MatrixXd>> dense_view(const SparseMatrix& A) {
  if (!is_dense_stored(A)) return std::nullopt;
  return Eigen::Map<const Eigen::MatrixXd>(A.valuePtr(), A.rows(), A.cols());
}

}  // namespace signorini

#include "signorini/iterative/linear_operator.hpp"

namespace signorini {

void SymmetricMatrixOperator::apply(const DeviceVector& x, DeviceVector& y) {
  // Host memory (a host backend's vectors): A is column-major, so row i of A x is column i of A
  // against x by symmetry, and the rows are independent.
  const double* xs = x.data();
  double* ys = y.data();
  const Index n = A_.rows();
#pragma omp parallel for schedule(static) if (n > 20000)
  for (Index i = 0; i < n; ++i) {
    double sum = 0.0;
    for (SparseMatrix::InnerIterator it(A_, i); it; ++it) sum += it.value() * xs[it.row()];
    ys[i] = sum;
  }
}

}  // namespace signorini

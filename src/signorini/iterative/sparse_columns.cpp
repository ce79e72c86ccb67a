#include "signorini/iterative/sparse_columns.hpp"

namespace signorini {

SparseMatrix assemble_columns(Index rows, const std::vector<std::vector<int>>& column_rows,
                              const std::vector<std::vector<double>>& column_values) {
  const auto m = static_cast<Index>(column_rows.size());
  Index nonzeros = 0;
  for (const auto& r : column_rows) nonzeros += static_cast<Index>(r.size());
  SparseMatrix C(rows, m);
  C.resizeNonZeros(nonzeros);
  int* outer = C.outerIndexPtr();
  Index k = 0;
  for (Index J = 0; J < m; ++J) {
    outer[J] = static_cast<int>(k);
    const auto& r = column_rows[static_cast<std::size_t>(J)];
    const auto& v = column_values[static_cast<std::size_t>(J)];
    std::copy(r.begin(), r.end(), C.innerIndexPtr() + k);
    std::copy(v.begin(), v.end(), C.valuePtr() + k);
    k += static_cast<Index>(r.size());
  }
  outer[m] = static_cast<int>(k);
  return C;
}

}  // namespace signorini

#include "signorini/petsc/level_numbering.hpp"

#include <type_traits>
#include <utility>

#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

namespace {

// Fills M (type AIJ, sized) with this rank's rows in CSR (global column numbers, each row's
// ascending); PETSc copies them. (Each call is a no-op on the other type.)
template <class O, class C>
void set_rows(Mat M, Index rows, const O* outer, const C* columns, const double* values) {
  if constexpr (std::is_same_v<O, PetscInt> && std::is_same_v<C, PetscInt>) {
    // (Whole rows, sorted, the preallocation exact: PETSc copies each row in one go.)
    check(MatSetOption(M, MAT_SORTED_FULL, PETSC_TRUE), "a multigrid level");
    check(MatSeqAIJSetPreallocationCSR(M, outer, columns, values), "a multigrid level");
    check(MatMPIAIJSetPreallocationCSR(M, outer, columns, values), "a multigrid level");
  } else {
    const std::vector<PetscInt> o(outer, outer + rows + 1);
    const std::vector<PetscInt> c(columns, columns + outer[rows]);
    set_rows(M, rows, o.data(), c.data(), values);
  }
}

}  // namespace

Mat distributed_matrix(MPI_Comm comm, const RowMatrix& R, const ExtNumbering& numbering,
                       PetscInt local_columns) {
  const auto rows = static_cast<PetscInt>(R.rows());
  Mat M = nullptr;
  check(MatCreate(comm, &M), "a prolongation");
  check(MatSetSizes(M, rows, local_columns, PETSC_DETERMINE, PETSC_DETERMINE), "a prolongation");
  check(MatSetType(M, MATAIJ), "a prolongation");
  if (numbering.first == 0 && numbering.foreign.empty()) {  // (no ghosts: local is global)
    set_rows(M, rows, R.outerIndexPtr(), R.innerIndexPtr(), R.valuePtr());
    return M;
  }
  std::vector<PetscInt> columns(static_cast<std::size_t>(R.nonZeros()));
  std::vector<double> values(R.valuePtr(), R.valuePtr() + R.nonZeros());
  std::vector<std::pair<PetscInt, double>> row;
  for (PetscInt r = 0; r < rows; ++r) {
    const auto b = static_cast<std::size_t>(R.outerIndexPtr()[r]);
    const auto e = static_cast<std::size_t>(R.outerIndexPtr()[r + 1]);
    bool sorted = true;
    for (std::size_t k = b; k < e; ++k) {
      columns[k] = numbering.global(R.innerIndexPtr()[k]);
      sorted = sorted && (k == b || columns[k - 1] < columns[k]);
    }
    if (sorted) continue;  // (only rows that reach a neighbour's columns need it)
    row.clear();
    for (std::size_t k = b; k < e; ++k) row.emplace_back(columns[k], values[k]);
    std::sort(row.begin(), row.end());
    for (std::size_t k = b; k < e; ++k) {
      columns[k] = row[k - b].first;
      values[k] = row[k - b].second;
    }
  }
  set_rows(M, rows, R.outerIndexPtr(), columns.data(), values.data());
  return M;
}

}  // namespace signorini::petsc

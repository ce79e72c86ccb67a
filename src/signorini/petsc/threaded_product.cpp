#include "signorini/petsc/threaded_product.hpp"

#include <omp.h>

#include <exception>
#include <tuple>

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/shell_call.hpp"

namespace signorini::petsc {

namespace {

PetscErrorCode shell_multiply(Mat shell, Vec x, Vec y) {
  return shell_call<ThreadedProduct>(
      shell, [&](const ThreadedProduct& product) { product.multiply(x, y, false); });
}

// z = y + M x
PetscErrorCode shell_multiply_add(Mat shell, Vec x, Vec y, Vec z) {
  if (z != y) PetscCall(VecCopy(y, z));
  return shell_call<ThreadedProduct>(
      shell, [&](const ThreadedProduct& product) { product.multiply(x, z, true); });
}

PetscErrorCode shell_diagonal(Mat shell, Vec d) {
  ThreadedProduct* product = nullptr;
  PetscCall(MatShellGetContext(shell, &product));
  PetscCall(MatGetDiagonal(product->matrix(), d));
  return 0;
}

// y(block row) (+)= sum over its blocks of the bs x bs block (column-major) times x there.
template <int BS>
void multiply_rows(PetscInt rows, const PetscInt* ia, const PetscInt* ja, const PetscScalar* a,
                   const PetscScalar* x, PetscScalar* y, bool add) {
#pragma omp parallel for schedule(static)
  for (PetscInt i = 0; i < rows; ++i) {
    PetscScalar s[BS] = {};
    for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) {
      const PetscScalar* v = a + static_cast<std::ptrdiff_t>(k) * BS * BS;
      const PetscScalar* xb = x + static_cast<std::ptrdiff_t>(ja[k]) * BS;
      for (int c = 0; c < BS; ++c)
        for (int r = 0; r < BS; ++r) s[r] += v[c * BS + r] * xb[c];
    }
    PetscScalar* yb = y + static_cast<std::ptrdiff_t>(i) * BS;
    for (int r = 0; r < BS; ++r) yb[r] = add ? yb[r] + s[r] : s[r];
  }
}

void multiply_rows_generic(PetscInt bs, PetscInt rows, const PetscInt* ia, const PetscInt* ja,
                           const PetscScalar* a, const PetscScalar* x, PetscScalar* y, bool add) {
#pragma omp parallel for schedule(static)
  for (PetscInt i = 0; i < rows; ++i) {
    PetscScalar* yb = y + static_cast<std::ptrdiff_t>(i) * bs;
    if (!add)
      for (PetscInt r = 0; r < bs; ++r) yb[r] = 0.0;
    for (PetscInt k = ia[i]; k < ia[i + 1]; ++k) {
      const PetscScalar* v = a + static_cast<std::ptrdiff_t>(k) * bs * bs;
      const PetscScalar* xb = x + static_cast<std::ptrdiff_t>(ja[k]) * bs;
      for (PetscInt c = 0; c < bs; ++c)
        for (PetscInt r = 0; r < bs; ++r) yb[r] += v[c * bs + r] * xb[c];
    }
  }
}

// What a matrix is to the product: rows of scalars or node blocks, on one process or several.
struct Layout {
  bool known = false, blocks = false, distributed = false;
};
Layout layout_of(Mat M) {
  for (const auto& [type, blocks, distributed] :
       {std::tuple{MATSEQAIJ, false, false}, std::tuple{MATMPIAIJ, false, true},
        std::tuple{MATSEQBAIJ, true, false}, std::tuple{MATMPIBAIJ, true, true}}) {
    PetscBool same = PETSC_FALSE;
    check(PetscObjectTypeCompare(reinterpret_cast<PetscObject>(M), type, &same),
          "a threaded product");
    if (same) return {true, blocks, distributed};
  }
  return {};
}

}  // namespace

ThreadedProduct::ThreadedProduct(Mat M) : M_(M) {
  const Layout layout = layout_of(M);
  if (!layout.known)
    throw NumericalError("a threaded product needs a SeqAIJ, MPIAIJ, SeqBAIJ or MPIBAIJ matrix");
  blocks_ = layout.blocks;
  if (blocks_) check(MatGetBlockSize(M, &bs_), "a threaded product");
  if (!layout.distributed) {
    own_.M = M;
  } else {
    const PetscInt* columns = nullptr;  // the neighbours' (block) columns, global numbers
    if (blocks_)
      check(MatMPIBAIJGetSeqBAIJ(M, &own_.M, &others_.M, &columns), "a threaded product");
    else
      check(MatMPIAIJGetSeqAIJ(M, &own_.M, &others_.M, &columns), "a threaded product");
    PetscInt ghost_columns = 0;
    check(MatGetSize(others_.M, nullptr, &ghost_columns), "a threaded product");
    const PetscInt ghost_blocks = ghost_columns / bs_;
    IS from = nullptr;
    check(ISCreateBlock(PETSC_COMM_SELF, bs_, ghost_blocks, columns, PETSC_COPY_VALUES, &from),
          "a threaded product");
    check(VecCreateSeq(PETSC_COMM_SELF, ghost_blocks * bs_, &ghosts_), "a threaded product");
    Vec columns_like = nullptr;  // (a vector of M's columns, for the scatter's layout)
    check(MatCreateVecs(M, &columns_like, nullptr), "a threaded product");
    check(VecScatterCreate(columns_like, from, ghosts_, nullptr, &scatter_), "a threaded product");
    check(VecDestroy(&columns_like), "a threaded product");
    check(ISDestroy(&from), "a threaded product");
  }
  PetscInt m = 0, n = 0, rows = 0, columns = 0;
  check(MatGetLocalSize(M, &m, &n), "a threaded product");
  check(MatGetSize(M, &rows, &columns), "a threaded product");
  check(MatCreateShell(PetscObjectComm(reinterpret_cast<PetscObject>(M)), m, n, rows, columns, this,
                       &shell_),
        "a threaded product");
  check(MatShellSetOperation(shell_, MATOP_MULT, reinterpret_cast<void (*)(void)>(&shell_multiply)),
        "a threaded product");
  check(MatShellSetOperation(shell_, MATOP_MULT_ADD,
                             reinterpret_cast<void (*)(void)>(&shell_multiply_add)),
        "a threaded product");
  check(MatShellSetOperation(shell_, MATOP_GET_DIAGONAL,
                             reinterpret_cast<void (*)(void)>(&shell_diagonal)),
        "a threaded product");
}

ThreadedProduct::~ThreadedProduct() {
  MatDestroy(&shell_);
  VecScatterDestroy(&scatter_);
  VecDestroy(&ghosts_);
}

void ThreadedProduct::refresh() {
  // (An assembly raises a matrix's state, by which a PC knows that its operator changed.)
  check(MatAssemblyBegin(shell_, MAT_FINAL_ASSEMBLY), "a threaded product");
  check(MatAssemblyEnd(shell_, MAT_FINAL_ASSEMBLY), "a threaded product");
}

bool ThreadedProduct::worthwhile(Mat M) {
  return layout_of(M).known && omp_get_max_threads() > 1;
}

void ThreadedProduct::take_arrays(Part& part) const {
  PetscBool done = PETSC_FALSE;
  // Block-compressed rows for BAIJ (the fourth argument): PETSc's own arrays, no copy.
  check(MatGetRowIJ(part.M, 0, PETSC_FALSE, blocks_ ? PETSC_TRUE : PETSC_FALSE, &part.rows,
                    &part.ia, &part.ja, &done),
        "a threaded product");
  if (!done) throw NumericalError("PETSc: a matrix's rows are not available");
  if (blocks_) {
    PetscScalar* values = nullptr;
    check(MatSeqBAIJGetArray(part.M, &values), "a threaded product");
    part.values = values;
  } else {
    check(MatSeqAIJGetArrayRead(part.M, &part.values), "a threaded product");
  }
}

void ThreadedProduct::release_arrays(Part& part) const {
  if (blocks_) {
    auto* values = const_cast<PetscScalar*>(part.values);
    check(MatSeqBAIJRestoreArray(part.M, &values), "a threaded product");
  } else {
    check(MatSeqAIJRestoreArrayRead(part.M, &part.values), "a threaded product");
  }
  PetscBool done = PETSC_FALSE;
  check(MatRestoreRowIJ(part.M, 0, PETSC_FALSE, blocks_ ? PETSC_TRUE : PETSC_FALSE, &part.rows,
                        &part.ia, &part.ja, &done),
        "a threaded product");
  part.values = nullptr;
}

void ThreadedProduct::multiply_part(const Part& part, const PetscScalar* x, PetscScalar* y,
                                    bool add) const {
  switch (bs_) {
    case 1:
      multiply_rows<1>(part.rows, part.ia, part.ja, part.values, x, y, add);
      break;
    case 2:
      multiply_rows<2>(part.rows, part.ia, part.ja, part.values, x, y, add);
      break;
    case 3:
      multiply_rows<3>(part.rows, part.ia, part.ja, part.values, x, y, add);
      break;
    default:
      multiply_rows_generic(bs_, part.rows, part.ia, part.ja, part.values, x, y, add);
  }
}

void ThreadedProduct::multiply(Vec x, Vec y, bool add) const {
  // The neighbours' values travel while the rank's own columns are multiplied.
  if (scatter_ != nullptr)
    check(VecScatterBegin(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD),
          "a threaded product");
  PetscScalar* ya = nullptr;
  check(VecGetArray(y, &ya), "a threaded product");
  // y (+)= part x, the part's arrays held for the product only.
  const auto product_with = [&](const Part& of, Vec v, bool adding) {
    const PetscScalar* va = nullptr;
    check(VecGetArrayRead(v, &va), "a threaded product");
    Part part = of;
    take_arrays(part);
    multiply_part(part, va, ya, adding);
    release_arrays(part);
    check(VecRestoreArrayRead(v, &va), "a threaded product");
  };
  product_with(own_, x, add);
  if (scatter_ != nullptr) {
    check(VecScatterEnd(scatter_, x, ghosts_, INSERT_VALUES, SCATTER_FORWARD),
          "a threaded product");
    product_with(others_, ghosts_, true);
  }
  check(VecRestoreArray(y, &ya), "a threaded product");
}

}  // namespace signorini::petsc

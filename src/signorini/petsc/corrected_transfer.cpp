#include "signorini/petsc/corrected_transfer.hpp"

#include <exception>
#include <utility>

#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {

namespace {

template <bool Interpolation, bool Add>
PetscErrorCode shell_product(Mat shell, Vec x, Vec y, Vec w) {
  CorrectedTransfer* transfer = nullptr;
  PetscCall(MatShellGetContext(shell, &transfer));
  try {
    if constexpr (Interpolation)
      transfer->interpolate(x, y, w, Add);
    else
      transfer->restrict_residual(x, y, w, Add);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  return 0;
}

template <bool Interpolation>
PetscErrorCode shell_multiply(Mat shell, Vec x, Vec y) {
  return shell_product<Interpolation, false>(shell, x, y, y);
}

template <bool Interpolation>
PetscErrorCode shell_multiply_add(Mat shell, Vec x, Vec y, Vec w) {
  return shell_product<Interpolation, true>(shell, x, y, w);
}

Mat make_shell(Mat like, bool transposed, CorrectedTransfer* context) {
  PetscInt m = 0, n = 0, rows = 0, columns = 0;
  check(MatGetLocalSize(like, &m, &n), "a multigrid transfer");
  check(MatGetSize(like, &rows, &columns), "a multigrid transfer");
  if (transposed) {
    std::swap(m, n);
    std::swap(rows, columns);
  }
  Mat shell = nullptr;
  check(MatCreateShell(PetscObjectComm(reinterpret_cast<PetscObject>(like)), m, n, rows, columns,
                       context, &shell),
        "a multigrid transfer");
  const auto multiply = transposed ? &shell_multiply<false> : &shell_multiply<true>;
  const auto multiply_add = transposed ? &shell_multiply_add<false> : &shell_multiply_add<true>;
  check(MatShellSetOperation(shell, MATOP_MULT, reinterpret_cast<void (*)(void)>(multiply)),
        "a multigrid transfer");
  check(MatShellSetOperation(shell, MATOP_MULT_ADD, reinterpret_cast<void (*)(void)>(multiply_add)),
        "a multigrid transfer");
  return shell;
}

}  // namespace

CorrectedTransfer::CorrectedTransfer(Mat P, Mat R) : P_(P), R_(R) {
  interpolation_ = make_shell(P_, false, this);
  restriction_ = make_shell(P_, true, this);
}

CorrectedTransfer::~CorrectedTransfer() {
  MatDestroy(&interpolation_);
  MatDestroy(&restriction_);
}

void CorrectedTransfer::interpolate(Vec x, Vec y, Vec w, bool add) const {
  if (add)
    check(MatMultAdd(P_, x, y, w), "a multigrid interpolation");
  else
    check(MatMult(P_, x, w), "a multigrid interpolation");
  if (dP_ != nullptr) check(MatMultAdd(dP_, x, w, w), "a multigrid interpolation");
}

void CorrectedTransfer::restrict_residual(Vec x, Vec y, Vec w, bool add) const {
  if (R_ != nullptr)
    check(add ? MatMultAdd(R_, x, y, w) : MatMult(R_, x, w), "a multigrid restriction");
  else
    check(add ? MatMultTransposeAdd(P_, x, y, w) : MatMultTranspose(P_, x, w),
          "a multigrid restriction");
  if (dP_ != nullptr) check(MatMultTransposeAdd(dP_, x, w, w), "a multigrid restriction");
}

}  // namespace signorini::petsc

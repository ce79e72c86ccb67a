#include "signorini/petsc/corrected_transfer.hpp"

#include <utility>

#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/shell_call.hpp"

namespace signorini::petsc {

namespace {

void interpolate(const CorrectedTransfer& t, Vec x, Vec y, Vec w, bool add) {
  t.interpolate(x, y, w, add);
}

void restrict_residual(const CorrectedTransfer& t, Vec x, Vec y, Vec w, bool add) {
  t.restrict_residual(x, y, w, add);
}

using Interpolation = ShellProducts<CorrectedTransfer, &interpolate>;
using Restriction = ShellProducts<CorrectedTransfer, &restrict_residual>;

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
  const auto multiply = transposed ? &Restriction::multiply : &Interpolation::multiply;
  const auto multiply_add = transposed ? &Restriction::multiply_add : &Interpolation::multiply_add;
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

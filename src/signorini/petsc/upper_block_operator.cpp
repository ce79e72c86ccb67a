#include "signorini/petsc/upper_block_operator.hpp"

#include <utility>

#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/shell_call.hpp"

namespace signorini::petsc {

namespace {

template <bool Newton>
void apply(const UpperBlockOperator& op, Vec x, Vec y, Vec w, bool add) {
  op.multiply(x, y, w, add, Newton);
}

template <bool Newton>
PetscErrorCode shell_diagonal(Mat shell, Vec d) {
  return shell_call<UpperBlockOperator>(
      shell, [&](const UpperBlockOperator& op) { op.diagonal(d, Newton); });
}

template <bool Newton>
Mat make_shell(MPI_Comm comm, PetscInt n, UpperBlockOperator* op) {
  const char* what = "the one-rank products";
  Mat shell = nullptr;
  check(MatCreateShell(comm, n, n, n, n, op, &shell), what);
  using Products = ShellProducts<UpperBlockOperator, &apply<Newton>>;
  check(MatShellSetOperation(shell, MATOP_MULT,
                             reinterpret_cast<void (*)(void)>(&Products::multiply)),
        what);
  check(MatShellSetOperation(shell, MATOP_MULT_ADD,
                             reinterpret_cast<void (*)(void)>(&Products::multiply_add)),
        what);
  check(MatShellSetOperation(shell, MATOP_GET_DIAGONAL,
                             reinterpret_cast<void (*)(void)>(&shell_diagonal<Newton>)),
        what);
  check(MatSetOption(shell, MAT_SYMMETRIC, PETSC_TRUE), what);
  check(MatSetOption(shell, MAT_SPD, PETSC_TRUE), what);
  return shell;
}

}  // namespace

std::unique_ptr<UpperBlockOperator> UpperBlockOperator::make(const SparseMatrix& A, MPI_Comm comm) {
  if (!A.isCompressed() || A.rows() != A.cols()) return nullptr;
  std::optional<NodeBlockMatrix> upper = NodeBlockMatrix::from_symmetric_csr(
      A.rows(), A.outerIndexPtr(), A.innerIndexPtr(), A.valuePtr());
  if (!upper) return nullptr;
  return std::make_unique<UpperBlockOperator>(std::move(*upper), A.diagonal(), comm);
}

UpperBlockOperator::UpperBlockOperator(NodeBlockMatrix upper, Vector diagonal, MPI_Comm comm)
    : upper_(std::move(upper)), diagonal_(std::move(diagonal)), comm_(comm) {
  const auto n = static_cast<PetscInt>(diagonal_.size());
  A_ = make_shell<false>(comm_, n, this);
  H_ = make_shell<true>(comm_, n, this);
}

UpperBlockOperator::~UpperBlockOperator() {
  MatDestroy(&A_);
  MatDestroy(&H_);
}

void UpperBlockOperator::set_contact_blocks(std::vector<std::vector<PetscInt>> dofs,
                                            std::vector<std::vector<double>> values) {
  dofs_ = std::move(dofs);
  values_ = std::move(values);
  // (An assembly raises a matrix's state, by which a PC knows that its operator changed.)
  check(MatAssemblyBegin(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
  check(MatAssemblyEnd(H_, MAT_FINAL_ASSEMBLY), "the Newton matrix");
}

void UpperBlockOperator::multiply(Vec x, Vec y, Vec w, bool add, bool newton) const {
  const char* what = "the one-rank products";
  if (add && w != y) check(VecCopy(y, w), what);
  const PetscScalar* xa = nullptr;
  PetscScalar* wa = nullptr;
  check(VecGetArrayRead(x, &xa), what);
  check(VecGetArray(w, &wa), what);
  upper_.multiply(xa, wa, 1.0, add ? 1.0 : 0.0, true);
  if (newton)
    for (std::size_t b = 0; b < dofs_.size(); ++b) {
      const std::vector<PetscInt>& d = dofs_[b];
      const std::vector<double>& v = values_[b];
      const std::size_t k = d.size();
      for (std::size_t p = 0; p < k; ++p) {
        double s = 0.0;
        for (std::size_t q = 0; q < k; ++q) s += v[p * k + q] * xa[d[q]];
        wa[d[p]] += s;
      }
    }
  check(VecRestoreArray(w, &wa), what);
  check(VecRestoreArrayRead(x, &xa), what);
}

void UpperBlockOperator::diagonal(Vec d, bool newton) const {
  const char* what = "the one-rank products";
  PetscScalar* a = nullptr;
  check(VecGetArray(d, &a), what);
  for (Index i = 0; i < diagonal_.size(); ++i) a[i] = diagonal_(i);
  if (newton)
    for (std::size_t b = 0; b < dofs_.size(); ++b) {
      const std::size_t k = dofs_[b].size();
      for (std::size_t p = 0; p < k; ++p) a[dofs_[b][p]] += values_[b][p * k + p];
    }
  check(VecRestoreArray(d, &a), what);
}

}  // namespace signorini::petsc

#include "signorini/linalg/dense_cholesky_solver.hpp"

#include "signorini/core/error.hpp"

namespace signorini {

void DenseCholeskySolver::factorize(const SparseMatrix& H) {
  workspace(H.rows()) = Eigen::MatrixXd(H);
  factorize_in_place();
}

void DenseCholeskySolver::factorize_dense(const Eigen::MatrixXd& H) {
  workspace(H.rows()) = H;
  factorize_in_place();
}

Eigen::MatrixXd& DenseCholeskySolver::workspace(Index n) {
  factorized_ = false;
  if (storage_.rows() != n) storage_.resize(n, n);
  return storage_;
}

void DenseCholeskySolver::factorize_in_place() {
  ScopedTimer timer(timings_, "linear factorization");
  // Eigen's in-place decomposition: an LLT over a Ref factorises the referenced array itself.
  llt_.emplace(storage_);
  factorized_ = llt_->info() == Eigen::Success;
  if (!factorized_) throw NumericalError("dense Cholesky: matrix is not positive definite");
}

bool DenseCholeskySolver::rank_update(const Vector& v, double sigma) {
  ScopedTimer timer(timings_, "linear factor update");
  if (!factorized_) return false;
  llt_->rankUpdate(v, sigma);
  factorized_ = llt_->info() == Eigen::Success;
  return factorized_;
}

LinearSolveStats DenseCholeskySolver::solve(const Vector& rhs, Vector& x) {
  ScopedTimer timer(timings_, "linear solve");
  if (!factorized_) throw NumericalError("dense Cholesky: solve() before factorize()");
  x = llt_->solve(rhs);
  return {};
}

}  // namespace signorini

#include "signorini/linalg/cg_solver.hpp"

#include "signorini/core/error.hpp"
#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

void CgSolver::factorize(const SparseMatrix& H) {
  ScopedTimer timer(timings_, "linear factorization");  // here: Jacobi preconditioner setup
  const Index n = H.rows();
  // The preconditioner refers to the operator: it goes first. The iteration's work vectors and b
  // and x stay from one Newton matrix to the next of the same size.
  jacobi_.reset();
  operator_ = std::make_unique<PenalizedOperator>(backend_, H, SparseMatrix(0, n));
  jacobi_ = std::make_unique<JacobiPreconditioner>(*operator_);
  if (!pcg_ || b_.size() != n) {
    pcg_ = std::make_unique<Pcg>(backend_, n);
    b_ = DeviceVector(backend_, n);
    x_ = DeviceVector(backend_, n);
  }
}

LinearSolveStats CgSolver::solve(const Vector& rhs, Vector& x) {
  ScopedTimer timer(timings_, "linear solve");
  if (!pcg_) throw NumericalError("CG: solve() before factorize()");
  const Index n = operator_->size();
  if (rhs.size() != n) throw NumericalError("CG: the right-hand side has the wrong size");
  if (x.size() != n) x = Vector::Zero(n);
  backend_.upload(rhs.data(), n, b_.data());
  backend_.upload(x.data(), n, x_.data());
  const PcgResult r = pcg_->solve(*operator_, *jacobi_, b_, x_, pcg_options(options_, n));
  backend_.download(x_.data(), n, x.data());
  LinearSolveStats stats;
  stats.iterations = r.iterations;
  stats.residual = r.residual;
  stats.converged = r.converged;
  return stats;
}

}  // namespace signorini

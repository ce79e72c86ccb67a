#include "signorini/linalg/cg_solver.hpp"

#include "signorini/core/error.hpp"

namespace signorini {

void CgSolver::factorize(const SparseMatrix& H) {
  ScopedTimer timer(timings_, "linear factorization");  // here: Jacobi preconditioner setup
  matrix_ = H;
  cg_.setTolerance(options_.cg_tolerance);
  const Index limit = options_.cg_max_iterations > 0 ? options_.cg_max_iterations : 10 * H.rows();
  cg_.setMaxIterations(limit);
  cg_.compute(matrix_);
}

LinearSolveStats CgSolver::solve(const Vector& rhs, Vector& x) {
  ScopedTimer timer(timings_, "linear solve");
  if (x.size() != rhs.size()) x = Vector::Zero(rhs.size());
  x = cg_.solveWithGuess(rhs, x);
  LinearSolveStats stats;
  stats.iterations = static_cast<int>(cg_.iterations());
  stats.residual = cg_.error();
  stats.converged = cg_.info() == Eigen::Success;
  return stats;
}

}  // namespace signorini

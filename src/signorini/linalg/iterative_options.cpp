#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

PcgOptions pcg_options(const LinearSolverOptions& options, Index n) {
  PcgOptions o;
  o.tolerance = options.cg_tolerance;
  o.max_iterations = options.cg_iteration_limit(n);
  return o;
}

MultigridOptions multigrid_options(const LinearSolverOptions& options) {
  MultigridOptions o;
  o.smoother.degree = options.chebyshev_degree;
  return o;
}

std::unique_ptr<Preconditioner> make_preconditioner(PenalizedOperator& H, const SparseMatrix& A,
                                                    const SparseMatrix& N,
                                                    const MultigridHierarchy* levels,
                                                    const LinearSolverOptions& options) {
  if (options.preconditioner != PreconditionerType::Multigrid)
    return std::make_unique<JacobiPreconditioner>(H);
  static const MultigridHierarchy kSingleLevel;  // no hierarchy: smoothing alone
  const MultigridHierarchy& l = levels != nullptr ? *levels : kSingleLevel;
  MultigridOptions o = multigrid_options(options);
  o.lambda_max = l.jacobi_radii;  // the hierarchy's estimates for the same A_l and D_l
  if (!l.tentatives.empty()) {
    o.tentatives = &l.tentatives;
    o.omegas = l.omegas;
  }
  return std::make_unique<MultigridPreconditioner>(H, A, N, l.prolongations, o, l.coarse_operators);
}

}  // namespace signorini

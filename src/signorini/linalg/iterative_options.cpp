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

}  // namespace signorini

#include "signorini/linalg/linear_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/linalg/cg_solver.hpp"
#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/linalg/dense_cholesky_solver.hpp"

namespace signorini {

void validate(const LinearSolverOptions& o) {
  if (!(o.cg_tolerance > 0.0) || !std::isfinite(o.cg_tolerance) || o.cg_tolerance >= 1.0)
    throw InputError("solver.linear.cg_tolerance = " + std::to_string(o.cg_tolerance) +
                     ": expected a number in (0, 1)");
  if (o.cg_max_iterations < 0)
    throw InputError("solver.linear.cg_max_iterations = " + std::to_string(o.cg_max_iterations) +
                     ": expected >= 0 (0: automatic)");
  if (o.chebyshev_degree < 1 || o.chebyshev_degree > 50)
    throw InputError("solver.linear.chebyshev_degree = " + std::to_string(o.chebyshev_degree) +
                     ": expected an integer in [1, 50]");
}

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options) {
  validate(options);
  switch (options.type) {
    case LinearSolverType::Cholmod:
      return std::make_unique<CholmodSolver>();
    case LinearSolverType::ConjugateGradient:
      return std::make_unique<CgSolver>(options);
    case LinearSolverType::Dense:
      return std::make_unique<DenseCholeskySolver>();
  }
  throw InputError("unknown linear solver type");
}

int LinearSolverOptions::cg_iteration_limit(Index n) const {
  if (cg_max_iterations > 0) return cg_max_iterations;
  return static_cast<int>(std::min<Index>(10 * n, std::numeric_limits<int>::max()));
}

}  // namespace signorini

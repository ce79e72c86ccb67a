#pragma once
// The options of the iterative algorithms (PCG, the multigrid V-cycle and its Chebyshev
// smoother) as the user's LinearSolverOptions set them: the one place where the keys of
// [solver.linear] reach those structs, for the host CG solver and the backend Newton space alike.
// Everything not set by a key keeps the default of its struct.

#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

/// cg_tolerance and the iteration limit for n unknowns (cg_max_iterations, 0: 10 n).
PcgOptions pcg_options(const LinearSolverOptions& options, Index n);

/// chebyshev_degree; the coarsest dense size is kDenseCoarsestUnknowns.
MultigridOptions multigrid_options(const LinearSolverOptions& options);

}  // namespace signorini

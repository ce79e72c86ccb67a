#pragma once
// The options of the iterative algorithms (PCG, the multigrid V-cycle and its Chebyshev
// smoother) as the user's LinearSolverOptions set them: the one place where the keys of
// [solver.linear] reach those structs, for the host CG solver and the backend Newton space alike.
// Everything not set by a key keeps the default of its struct.

#include <memory>

#include "signorini/iterative/jacobi_preconditioner.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

/// cg_tolerance and the iteration limit for n unknowns (cg_max_iterations, 0: 10 n).
PcgOptions pcg_options(const LinearSolverOptions& options, Index n);

/// chebyshev_degree; the coarsest dense size is kDenseCoarsestUnknowns.
MultigridOptions multigrid_options(const LinearSolverOptions& options);

/// The preconditioner that `options` ask for on H (A and N its stiffness and contact rows, which
/// must outlive it): a multigrid V-cycle on `levels` (null: smoothing alone), or Jacobi.
std::unique_ptr<Preconditioner> make_preconditioner(PenalizedOperator& H, const SparseMatrix& A,
                                                    const SparseMatrix& N,
                                                    const MultigridHierarchy* levels,
                                                    const LinearSolverOptions& options);

}  // namespace signorini

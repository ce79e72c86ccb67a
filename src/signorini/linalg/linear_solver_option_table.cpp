#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {

const OptionTable<LinearSolverOptions>& linear_solver_option_table() {
  using O = LinearSolverOptions;
  static const OptionTable<O> table = [] {
    OptionTable<O> t("solver.linear");
    t.choice("type", &O::type, kLinearSolverTypeNames,
             "`cholmod`: sparse Cholesky (SuiteSparse); `cg`: Jacobi-preconditioned conjugate "
             "gradients (the paper's choice; less memory); `dense`: dense Cholesky of the whole "
             "system (small problems only: memory grows as the square of the unknowns)");
    t.number("cg_tolerance", &O::cg_tolerance, open_interval(0.0, 1.0),
             "CG stops when ||H x - rhs|| <= cg_tolerance ||rhs||");
    t.integer("cg_max_iterations", &O::cg_max_iterations, at_least(0),
              "CG iteration limit; 0 means 10 times the number of unknowns")
        .range_note("(0: automatic)");
    t.choice("preconditioner", &O::preconditioner, kPreconditionerTypeNames,
             "preconditioner of `cg`: `jacobi` is the paper's diag(H)^-1; `multigrid` is one "
             "multigrid V-cycle (geometric or smoothed-aggregation levels: `coarsening`) with "
             "Chebyshev–Jacobi smoothing, whose iteration count hardly grows with the mesh (about "
             "8 CG iterations per Newton system at 1e-13 on every Table 1 mesh). `multigrid` runs "
             "on the backend path ([gpu.md](gpu.md)), on the CPU or the GPU, with "
             "`method = \"uzawa_gnm\"` or `\"semismooth_newton\"`");
    t.choice("coarsening", &O::coarsening, kMultigridCoarseningNames,
             "how `multigrid` builds its coarse levels: `geometric` halves the rectangle mesh "
             "down to at most 2,000 unknowns (nx and ny must stay even until then; an error "
             "otherwise); `aggregation` is smoothed aggregation from the matrix and the "
             "rigid-body modes, for any mesh; `auto` takes the geometric levels while the mesh "
             "halves and continues by aggregation where they stop above 2,000 unknowns "
             "([gpu.md](gpu.md))");
    t.integer("chebyshev_degree", &O::chebyshev_degree, closed_interval(1.0, 50.0),
              "products with H per smoothing sweep of the `multigrid` preconditioner (2 balances "
              "CG iterations, each with its host synchronisations, against products with the "
              "fine matrix: docs/gpu.md)");
    t.choice("factor_updates", &O::factor_updates, kFactorUpdatesNames,
             "`cholmod` on the sparse direct path (`schur_complement = false`), when the active "
             "set changes: `auto` updates and downdates the factor of the Newton matrix "
             "(CHOLMOD's `cholmod_updown`, one rank-one term per node that enters or leaves the "
             "active set; for `semismooth_newton`, CHOLMOD's row deletions and additions, two per "
             "node) instead of refactorising where that is expected to take less time, from "
             "the measured times of the last factorisation and update; `always` updates on every "
             "change (a factorisation after 2,000 updates, or where a downdate fails); `never` "
             "refactorises. Updating needs the simplicial L D L^T form of the factor, about 1.5 "
             "times the memory of the supernodal one (docs/solvers.md)");
    return t;
  }();
  return table;
}

}  // namespace signorini

#pragma once
// One interface for the linear solvers of the Newton steps (method.md section 4): a direct sparse
// Cholesky (CHOLMOD, the default), a dense Cholesky (condensed problems) and Jacobi-preconditioned
// conjugate gradients (the paper's choice).
// analyze() does the symbolic work once per sparsity pattern; factorize() the numeric work for
// each new matrix of that pattern; solve() can then be called any number of times.

#include <memory>
#include <string_view>

#include "signorini/core/enum_names.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

enum class LinearSolverType { Cholmod, ConjugateGradient, Dense };

inline constexpr EnumNames<LinearSolverType, 3> kLinearSolverTypeNames{{
    {LinearSolverType::Cholmod, "cholmod"},
    {LinearSolverType::ConjugateGradient, "cg"},
    {LinearSolverType::Dense, "dense"},
}};

/// Preconditioner of the conjugate gradients of the iterative path (docs/gpu.md).
enum class PreconditionerType { Jacobi, Multigrid };

/// When the sparse direct path updates its CHOLMOD factor instead of refactorising.
enum class FactorUpdates { Auto, Always, Never };

inline constexpr EnumNames<FactorUpdates, 3> kFactorUpdatesNames{{
    {FactorUpdates::Auto, "auto"},
    {FactorUpdates::Always, "always"},
    {FactorUpdates::Never, "never"},
}};

inline constexpr EnumNames<PreconditionerType, 2> kPreconditionerTypeNames{{
    {PreconditionerType::Jacobi, "jacobi"},
    {PreconditionerType::Multigrid, "multigrid"},
}};

/// How the multigrid preconditioner builds its coarse levels (docs/gpu.md).
enum class MultigridCoarsening { Auto, Geometric, Aggregation };

inline constexpr EnumNames<MultigridCoarsening, 3> kMultigridCoarseningNames{{
    {MultigridCoarsening::Auto, "auto"},
    {MultigridCoarsening::Geometric, "geometric"},
    {MultigridCoarsening::Aggregation, "aggregation"},
}};

struct LinearSolverOptions {
  /// "cholmod": supernodal sparse Cholesky; "cg": Jacobi-preconditioned conjugate gradients;
  /// "dense": dense Cholesky (small problems, and the condensed contact problems).
  LinearSolverType type = LinearSolverType::Cholmod;
  /// CG stops when ||H x - rhs||_2 <= cg_tolerance ||rhs||_2.
  double cg_tolerance = 1e-13;
  /// CG iteration limit; 0 means 10 times the number of unknowns.
  int cg_max_iterations = 0;
  /// "jacobi": diag(H)^{-1}, the paper's; "multigrid": one multigrid V-cycle with
  /// Chebyshev-Jacobi smoothing, whose iteration count hardly grows with the mesh (docs/gpu.md).
  /// Multigrid runs on the backend path (any device).
  PreconditionerType preconditioner = PreconditionerType::Jacobi;
  /// Coarse levels of "multigrid" (problem/model_hierarchy.hpp): "geometric" halves the
  /// rectangle mesh; "aggregation" is smoothed aggregation from the matrix and the rigid-body
  /// modes (any mesh); "auto" takes the geometric levels while the mesh halves, then aggregation.
  MultigridCoarsening coarsening = MultigridCoarsening::Auto;
  /// Degree of the Chebyshev smoother of the multigrid preconditioner (products with H per sweep).
  int chebyshev_degree = 2;
  /// "cholmod" on the sparse direct path, when the active set changes: update the factor of the
  /// Newton matrix by CHOLMOD's rank-k update/downdate instead of refactorising, where that is
  /// expected to be faster ("auto"), whenever the active set changes ("always"), or never.
  FactorUpdates factor_updates = FactorUpdates::Auto;

  /// The CG iteration limit for n unknowns: cg_max_iterations, or 10 n when that is 0.
  [[nodiscard]] int cg_iteration_limit(Index n) const;
};

/// Throws InputError naming the bad field.
void validate(const LinearSolverOptions& options);

struct LinearSolveStats {
  int iterations = 0;     ///< CG iterations (0 for a direct solve)
  double residual = 0.0;  ///< relative residual reached (CG); 0 for a direct solve
  bool converged = true;  ///< false: CG hit its iteration limit
};

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// Symbolic work for the pattern of `pattern` (values are ignored). Matrices passed to
  /// factorize() later must have exactly this pattern (same outer/inner index arrays).
  virtual void analyze(const SparseMatrix& pattern) = 0;
  /// Numeric work for an SPD matrix (both triangles stored). Throws NumericalError if the matrix
  /// is not positive definite.
  virtual void factorize(const SparseMatrix& H) = 0;
  /// Solves H x = rhs with the last factorised H; x holds the initial guess on entry (used by
  /// iterative solvers).
  virtual LinearSolveStats solve(const Vector& rhs, Vector& x) = 0;
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// Seconds spent in "linear analysis", "linear factorization" and "linear solve".
  [[nodiscard]] const TimingTable& timings() const { return timings_; }

 protected:
  TimingTable timings_;
};

std::unique_ptr<LinearSolver> make_linear_solver(const LinearSolverOptions& options);

}  // namespace signorini

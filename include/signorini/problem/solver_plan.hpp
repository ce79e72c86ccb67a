#pragma once
// The solver path of a problem chosen from its size and the machine's memory (docs/solvers.md,
// "Which path runs"): the condensed direct path while its dense matrix is small, the sparse
// direct path when that matrix would not fit, and CG with multigrid where a sparse factor costs
// more than it (3D beyond some tens of thousands of unknowns) or would not fit. build_model()
// applies it when ContactSolverOptions::automatic_path is set; the summary names the path and
// says why.

#include <string>

#include "signorini/contact/contact_solver_options.hpp"

namespace signorini {

/// What the choice looks at.
struct ProblemSize {
  int dimension = 2;
  Index nodes = 0;
  Index free_unknowns = 0;
  Index contact_nodes = 0;
  double memory_bytes = 0.0;  ///< the machine's physical memory; 0: unknown (no memory rule)
  /// A contact boundary with friction: the condensed and multigrid paths are frictionless, so
  /// the sparse direct path runs.
  bool friction = false;
};

/// In 3D a sparse Cholesky factor costs more than CG with smoothed-aggregation multigrid from
/// about this many free unknowns on (hex8 blocks on the 2-core development machine, model and
/// solve: at 6,900 unknowns 0.32 s against 0.51 s, at 22,500 1.6 s against 0.9 s, at 52,000
/// 6.5 s against 2.1 s; the factor's memory grows faster still: 0.94 GB against 0.19 GB;
/// docs/solvers.md).
inline constexpr Index kIterativeFromUnknowns3D = 15000;

/// Bytes per entry of the condensed path's dense matrices (the Schur complement stored with its
/// indices, and the Cholesky factor's array).
inline constexpr double kCondensedBytesPerEntry = 32.0;

struct SolverPlan {
  ContactSolverOptions options;  ///< the options to solve with
  std::string reason;            ///< one line: the path and why (summary.json's path_reason)
};

/// The plan for `given`. The options change only when given.automatic_path is set, the solve
/// runs on the CPU and the linear solver is the default "cholmod" (a user who chose "cg" or
/// "dense", a device or automatic_path = false gets exactly what was asked for):
///   - 3D with more than kIterativeFromUnknowns3D free unknowns, or a sparse factor estimated
///     above half of memory_bytes: "cg" with the "multigrid" preconditioner (the hierarchy from
///     the mesh: geometric where it halves, else aggregation);
///   - else, with schur_complement, a condensed matrix above a quarter of memory_bytes: the
///     sparse direct path (schur_complement = false);
///   - else as given.
SolverPlan plan_solver(const ContactSolverOptions& given, const ProblemSize& size);

/// The rough peak memory of a sparse Cholesky factor of the problem: 4 KB per node in 2D, as
/// measured on the paper's meshes (memory_estimate.hpp), and 25 KB per free unknown in 3D
/// (hex8 blocks: 12 KB at 22,500 unknowns, 17 KB at 52,000, 22 KB at 100,000, growing).
double estimated_factor_bytes(const ProblemSize& size);

}  // namespace signorini

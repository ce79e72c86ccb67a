#pragma once
// The Newton matrix of a contact problem on a backend, H = A + N^T diag(c) N
// (penalized_operator.hpp), with its preconditioner (Jacobi, or the multigrid V-cycle of the
// problem's hierarchy): what Uzawa-GNM's Newton systems (backend_newton_space.hpp) and semismooth
// Newton's projected steps (projected_active_set_solver.hpp) both solve with. The upload and the
// set-ups are timed ("device upload", "multigrid setup" or "preconditioner setup").

#include <memory>
#include <vector>

#include "signorini/backend/backend.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/iterative/linear_operator.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"
#include "signorini/iterative/penalized_operator.hpp"

namespace signorini {

struct BackendNewtonMatrix {
  /// Uploads A and N (the stiffness in place where a copy would not fit: stiffness_arrays; the
  /// problem must outlive this) and sets up the preconditioner for c = 0.
  BackendNewtonMatrix(const ContactProblem& problem, const ContactSolverOptions& options,
                      const MultigridHierarchy* multigrid, Backend& backend, TimingTable& timings);
  /// c_j = r h_j on the active nodes, 0 elsewhere; refreshes the preconditioner.
  void set_active(const ActiveSet& active, double r, const Vector& weights, TimingTable& timings);
  /// Friction (docs/method.md, "Friction"): H = A + N^T diag(c) N with c per row of N (2D, the
  /// blocks diag(0/1)), or A + N^T W N with W block diagonal (3D); refreshes the preconditioner.
  void set_row_weights(const Vector& c, TimingTable& timings);
  void set_block_weights(const SparseMatrix& W, Index block_size, TimingTable& timings);

  std::unique_ptr<PenalizedOperator> H;
  std::unique_ptr<Preconditioner> preconditioner;
  std::vector<Index> levels;  ///< unknowns per multigrid level (empty with Jacobi)
};

/// The backend that options.device asks for, its creation timed ("device setup").
[[nodiscard]] std::unique_ptr<Backend> make_timed_backend(const ContactSolverOptions& options,
                                                          TimingTable& timings);
/// Where a backend solve ran: device, its peak memory, the multigrid levels and hierarchy.
void record_backend(SolveSummary& summary, const Backend& backend, const std::vector<Index>& levels,
                    const MultigridHierarchy* multigrid);

}  // namespace signorini

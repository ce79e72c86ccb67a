#include "signorini/contact/backend_newton_matrix.hpp"

#include "signorini/backend/make_backend.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/linalg/iterative_options.hpp"

namespace signorini {

BackendNewtonMatrix::BackendNewtonMatrix(const ContactProblem& problem,
                                         const ContactSolverOptions& options,
                                         const MultigridHierarchy* multigrid, Backend& backend,
                                         TimingTable& timings) {
  {
    ScopedTimer t(timings, "device upload");
    // The problem outlives this matrix, so the stiffness (the largest matrix of the solve) may
    // be multiplied in place where a faster copy would not fit (stiffness_arrays).
    H = std::make_unique<PenalizedOperator>(backend, problem.A, problem.contact.N,
                                            stiffness_arrays(problem.A));
    backend.synchronize();
  }
  // The multigrid set-up (Galerkin coarse operators on the host, their upload) is timed apart
  // from the set-ups per active set ("preconditioner setup").
  ScopedTimer t(timings, options.linear.preconditioner == PreconditionerType::Multigrid
                             ? "multigrid setup"
                             : "preconditioner setup");
  preconditioner = make_preconditioner(*H, problem.A, problem.contact.N, multigrid, options.linear);
  if (const auto* mg = dynamic_cast<const MultigridPreconditioner*>(preconditioner.get())) {
    levels = mg->level_sizes();
    timings.merge(mg->setup_timings());
  }
  backend.synchronize();
}

void BackendNewtonMatrix::set_active(const ActiveSet& active, double r, const Vector& weights,
                                     TimingTable& timings) {
  Vector c = Vector::Zero(weights.size());
  for (Index j = 0; j < c.size(); ++j)
    if (active[static_cast<std::size_t>(j)]) c(j) = r * weights(j);
  ScopedTimer timer(timings, "preconditioner setup");
  H->set_weights(c);
  preconditioner->refresh();
  H->backend().synchronize();
}

void BackendNewtonMatrix::set_row_weights(const Vector& c, TimingTable& timings) {
  ScopedTimer timer(timings, "preconditioner setup");
  H->set_weights(c);
  preconditioner->refresh();
  H->backend().synchronize();
}

void BackendNewtonMatrix::set_block_weights(const SparseMatrix& W, Index block_size,
                                            TimingTable& timings) {
  ScopedTimer timer(timings, "preconditioner setup");
  H->set_block_weights(W, block_size);
  preconditioner->refresh();
  H->backend().synchronize();
}

std::unique_ptr<Backend> make_timed_backend(const ContactSolverOptions& options,
                                            TimingTable& timings) {
  ScopedTimer t(timings, "device setup");
  return make_backend(options.device);
}

void record_backend(SolveSummary& summary, const Backend& backend, const std::vector<Index>& levels,
                    const MultigridHierarchy* multigrid) {
  summary.device = backend.description();
  summary.device_peak_bytes = backend.peak_bytes();
  summary.multigrid_levels = levels;
  summary.multigrid_hierarchy = multigrid != nullptr ? multigrid->kind : HierarchyKind::None;
}

}  // namespace signorini

#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/uzawa_iteration.hpp"

#include <fmt/format.h>

namespace signorini {

void run_uzawa_iteration(const ContactProblem& problem, const ContactSolverOptions& options,
                         ModifiedLagrangian& phi, const UzawaInnerStep& inner, ContactResult& out) {
  SolveSummary& s = out.summary;
  Vector l = Vector::Zero(problem.contact.size());  // l^0 = 0 (method.md "Conventions")
  Vector Nx;
  s.termination = Termination::IterationLimit;
  bool stopped = false;  // by convergence or by a failure of step (i)
  for (int k = 1; k <= options.max_uzawa_iterations; ++k) {
    phi.set_multipliers(l);
    const GnmResult g = inner(phi, k, Nx);  // step (i): x = argmin Phi
    OuterStepRecord rec;
    rec.inner_iterations = g.iterations;
    rec.armijo_reductions = g.armijo_reductions;
    rec.linear_iterations = g.linear_iterations;
    rec.factorizations = g.factorizations;
    rec.factor_updates = g.factor_updates;
    rec.inner_residual = g.residual;
    if (g.termination != Termination::Converged) {
      rec.active_set_size = (l.array() > 0.0).count();
      s.steps.push_back(rec);
      s.termination = g.termination;
      s.message = g.message;
      stopped = true;
      break;
    }
    // Step (ii): l^{k+1} = (l^k + r ((N x)_j - g_j))_+, non-movable nodes stay at 0.
    const Vector l_new = phi.shifted_multipliers(Nx).cwiseMax(0.0);
    rec.dual_change = relative_change(l_new, l);
    rec.active_set_size = (l_new.array() > 0.0).count();
    l = l_new;
    s.steps.push_back(rec);
    if (options.observer)
      options.observer({IterationEvent::Kind::Outer, k, g.iterations, rec.active_set_size,
                        rec.dual_change, rec.armijo_reductions, rec.linear_iterations});
    if (rec.dual_change < options.uzawa_tolerance) {
      s.termination = Termination::Converged;
      s.message = fmt::format("||l^k - l^(k-1)|| / ||l^k|| = {:.3e} < {:.1e} after {} Uzawa steps",
                              rec.dual_change, options.uzawa_tolerance, k);
      stopped = true;
      break;
    }
  }
  if (!stopped)
    s.message = fmt::format(
        "Uzawa did not converge in {} steps: ||l^k - l^(k-1)|| / ||l^k|| = {:.3e} (tolerance "
        "{:.1e})",
        options.max_uzawa_iterations, s.steps.empty() ? 0.0 : s.steps.back().dual_change,
        options.uzawa_tolerance);
  out.l = std::move(l);
}

}  // namespace signorini

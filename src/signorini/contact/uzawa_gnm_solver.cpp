// The paper's method: Uzawa iterations (13) on the modified Lagrangian (10), each step (i)
// minimised by the generalised Newton method (17) (method.md sections 2-4).

#include <fmt/format.h>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/newton_system.hpp"

namespace signorini {

ContactResult solve_uzawa_gnm(const ContactProblem& problem, const ContactSolverOptions& options) {
  ContactResult out;
  SolveSummary& s = out.summary;
  ModifiedLagrangian phi(problem, options.r);
  const auto system = make_newton_system(problem, phi, options.linear);
  GeneralizedNewton gnm(problem, options, *system);
  Vector x = Vector::Zero(problem.A.rows());
  Vector l = Vector::Zero(problem.contact.size());  // l^0 = 0 (method.md "Conventions")
  s.termination = Termination::IterationLimit;
  bool stopped = false;  // by convergence or by a failure of step (i)

  for (int k = 1; k <= options.max_uzawa_iterations; ++k) {
    phi.set_multipliers(l);
    const GnmResult g = gnm.minimize(phi, x, k);  // step (i): x = argmin Phi
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
    const Vector l_new = phi.shifted_multipliers(problem.contact.N * x).cwiseMax(0.0);
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
  s.timings.merge(system->timings());
  out.u = std::move(x);
  out.l = std::move(l);
  return out;
}

}  // namespace signorini

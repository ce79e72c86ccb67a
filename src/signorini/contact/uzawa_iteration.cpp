#include "signorini/contact/uzawa_iteration.hpp"

#include <fmt/format.h>

#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/outer_iteration.hpp"

namespace signorini {

void run_uzawa_iteration(const ContactProblem& problem, const ContactSolverOptions& options,
                         ModifiedLagrangian& phi, NewtonSpace& space, Vector l0,
                         ContactResult& out) {
  const GeneralizedNewton gnm(options, problem.b.norm(), problem.contact.weights);
  OuterLoop loop;
  loop.max_steps = options.max_uzawa_iterations;
  loop.step = [&](int k, const Vector& l) {
    OuterStepOutcome o;
    phi.set_multipliers(l);
    const GnmResult g = gnm.minimize(phi, space, k);  // step (i): x = argmin Phi
    OuterStepRecord& rec = o.record;
    rec.inner_iterations = g.iterations;
    rec.armijo_reductions = g.armijo_reductions;
    rec.linear_iterations = g.linear_iterations;
    rec.factorizations = g.factorizations;
    rec.factor_updates = g.factor_updates;
    rec.inner_residual = g.residual;
    if (g.termination != Termination::Converged) {
      rec.active_set_size = (l.array() > 0.0).count();
      o.stop = g.termination;
      o.message = g.message;
      return o;
    }
    // Step (ii): l^{k+1} = P(l^k + r ((N x)_j - g_j)), P(z) = z_+ for the paper's law;
    // non-movable nodes stay at 0.
    o.l = phi.updated_multipliers(space.contact_values());
    rec.dual_change = relative_change(o.l, l);
    rec.active_set_size = (o.l.array() > 0.0).count();
    if (rec.dual_change < options.uzawa_tolerance) {
      o.stop = Termination::Converged;
      o.message = dual_change_message(rec, options.uzawa_tolerance, k, "Uzawa steps");
    }
    return o;
  };
  loop.limit_message = [&](const OuterStepRecord& last) {
    return fmt::format(
        "Uzawa did not converge in {} steps: ||l^k - l^(k-1)|| / ||l^k|| = {:.3e} (tolerance "
        "{:.1e})",
        options.max_uzawa_iterations, last.dual_change, options.uzawa_tolerance);
  };
  run_outer_loop(loop, std::move(l0), options, out);
}

}  // namespace signorini

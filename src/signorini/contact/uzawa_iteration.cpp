#include "signorini/contact/uzawa_iteration.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "signorini/contact/active_set_update.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/outer_iteration.hpp"

namespace signorini {

bool contact_conditions_hold(const ContactSet& contact, const ActiveSet& S,
                             const ActiveSetSolve& solve, double tolerance) {
  // (kkt_residuals.cpp's measures, with the contact nodes' normal displacements for lengths.)
  const double l_max = solve.l.size() > 0 ? solve.l.lpNorm<Eigen::Infinity>() : 0.0;
  double length = contact.gaps.size() > 0 ? contact.gaps.lpNorm<Eigen::Infinity>() : 0.0;
  double sign = 0.0, penetration = 0.0;
  for (Index j = 0; j < contact.size(); ++j) {
    if (!contact.movable[static_cast<std::size_t>(j)]) continue;
    length = std::max(length, std::abs(solve.gap_residual(j) + contact.gaps(j)));
    if (S[static_cast<std::size_t>(j)])
      sign = std::max(sign, -solve.l(j));
    else
      penetration = std::max(penetration, solve.gap_residual(j));
  }
  return sign <= tolerance * l_max && penetration <= tolerance * length;
}

void run_uzawa_iteration(const ContactProblem& problem, const ContactSolverOptions& options,
                         ModifiedLagrangian& phi, NewtonSpace& space, Vector l0,
                         ContactResult& out) {
  const GeneralizedNewton gnm(options, load_norm(problem), problem.contact.size());
  OuterLoop loop;
  loop.max_steps = options.max_uzawa_iterations;
  double previous_change = 1.0;     // ||l^k - l^(k-1)|| / ||l^k|| of the previous step
  double previous_tolerance = 1.0;  // step (i)'s tolerance at the previous step
  // The active-set finish (docs/solvers.md): once the multipliers change by less than
  // kFinishDualChange, the nodes where l^k > 0 are close to the solution's contact set, and the
  // solution is that of a linear problem once the set is right: the energy minimised under
  // (N x)_j = g_j on the set alone. The space solves it (projected CG), and the set is corrected
  // by semismooth Newton's primal-dual rule (pressing nodes stay, penetrating ones join), solved
  // to kLooseNewtonTolerance while it moves, then more tightly, then exactly (below); where an
  // exact solve repeats its set, its multipliers are nonnegative and no node off it penetrates,
  // it is the answer (the KKT conditions hold, to the Uzawa tolerance), and the Uzawa steps that
  // would have approached it one contraction at a time are saved. Else (kFinishSolves solves
  // without that) Uzawa goes on from there; each starting set is tried once.
  const bool finishes =
      options.active_set_finish && options.adaptive_inner_tolerance() && phi.components() == 1;
  ActiveSet tried;
  const auto try_active_set_finish = [&](int k, OuterStepOutcome& o) {
    OuterStepRecord& rec = o.record;
    if (k < 2 || !(rec.dual_change < kFinishDualChange)) return;
    const Index nc = o.l.size();
    ActiveSet S(static_cast<std::size_t>(nc));
    for (Index j = 0; j < nc; ++j) S[static_cast<std::size_t>(j)] = o.l(j) > 0.0;
    if (S == tried) return;
    tried = S;
    const int refreshes = space.factorizations();
    std::optional<ActiveSetSolve> f;
    // The tolerances of the solves: loose while the set moves, then, once a set repeats, a
    // middle one (the geometric mean), then exact. A node on the border of the contact area
    // has a multiplier or a gap near zero, whose sign a loose solve may not resolve: the middle
    // solve finds it before a whole exact solve is spent on the wrong set. On Hertz's ball such
    // a node cost a second exact solve (107,586 unknowns: 28 projected CG iterations without
    // the middle step, 21 with it; 1,016,227 on the PETSc path: 47 and 37); where no node is
    // left, the middle step costs a restart of CG (one iteration more at 434,235 unknowns and
    // at a million, serially).
    const double exact = 10.0 * options.linear.cg_tolerance;
    const double middle =
        exact < kLooseNewtonTolerance ? std::sqrt(kLooseNewtonTolerance * exact) : exact;
    const std::array<double, 3> tolerances = {kLooseNewtonTolerance, middle, exact};
    std::size_t stage = 0;
    bool repeated = false;
    int solves = 0, iterations = 0;
    while (solves < kFinishSolves && !repeated) {
      const double tolerance = tolerances[stage];
      f = space.solve_on_active_set(S, phi.r(), tolerance);
      if (!f) return;
      ++solves;
      iterations += f->stats.iterations;
      rec.linear_iterations += f->stats.iterations;
      if (!f->stats.converged) break;
      ActiveSet next = next_active_set(problem.contact, S, f->l, f->gap_residual);
      if (next == S) {
        repeated = stage + 1 == tolerances.size();
        if (!repeated) ++stage;  // (the same set again, now solved more tightly)
      }
      S = std::move(next);
    }
    rec.factorizations += space.factorizations() - refreshes;
    if (!repeated || !contact_conditions_hold(problem.contact, S, *f, options.uzawa_tolerance))
      return;
    rec.dual_change = relative_change(f->l, o.l);
    rec.active_set_size = count_in_contact(f->l, phi.components());
    o.l = f->l;
    o.stop = Termination::Converged;
    out.summary.active_set_finish = true;
    o.message = fmt::format(
        "the {} nodes in contact solved for exactly after Uzawa step {} ({} active-set solves, "
        "{} projected CG iterations): multipliers nonnegative and no penetration elsewhere, to "
        "{:.0e}",
        rec.active_set_size, k, solves, iterations, options.uzawa_tolerance);
  };
  loop.step = [&](int k, const Vector& l) {
    OuterStepOutcome o;
    phi.set_multipliers(l);
    // Inexact Uzawa (inner_tolerance = adaptive): step (i) only as accurate as the multipliers
    // it starts from, a thousandth of their last change. Near the end that is tighter than
    // gnm_tolerance, so that the error of step (i) stays below the dual change that Uzawa's
    // stopping rule measures (a floor at gnm_tolerance stalled Uzawa at a dual change of
    // 1.6e-10 under a tolerance of 1e-10); never below 10 cg_tolerance, what a Newton system
    // solved to cg_tolerance can reach. At least ten times tighter at each step: where the
    // dual change does not fall (Uzawa not yet contracting, or contracting slowly), the steps
    // become exact within a few steps, and the method is the exact one from there on.
    const double tolerance = options.adaptive_inner_tolerance()
                                 ? std::max(std::min(kInnerForcing * std::min(previous_change, 1.0),
                                                     0.1 * previous_tolerance),
                                            10.0 * options.linear.cg_tolerance)
                                 : options.gnm_tolerance;
    previous_tolerance = tolerance;
    const GnmResult g = gnm.minimize(phi, space, k, tolerance);  // step (i): x = argmin Phi
    OuterStepRecord& rec = o.record;
    rec.inner_iterations = g.iterations;
    rec.armijo_reductions = g.armijo_reductions;
    rec.linear_iterations = g.linear_iterations;
    rec.factorizations = g.factorizations;
    rec.factor_updates = g.factor_updates;
    rec.inner_residual = g.residual;
    if (g.termination != Termination::Converged) {
      rec.active_set_size = count_in_contact(l, phi.components());
      o.stop = g.termination;
      o.message = g.message;
      return o;
    }
    // Step (ii): l^{k+1} = P(l^k + r ((N x)_j - g_j)), P(z) = z_+ for the paper's law (with
    // friction P projects each node's d values, with the slip bound of step (i): Coulomb's
    // mu (l_n^k)_+, method.md "Friction"); non-movable nodes stay at 0.
    o.l = phi.updated_multipliers(space.contact_values());
    rec.dual_change = relative_change(o.l, l);
    previous_change = rec.dual_change;
    rec.active_set_size = count_in_contact(o.l, phi.components());
    // With inexact steps the rule also asks that step (i) was solved to a tenth of the KKT
    // tolerance: where no node ever touches, l stays 0 and the dual change is 0 after the
    // first step, solved to 1e-3 only (the equilibrium residual then failed the KKT check). The
    // next step's tolerance, from this dual change, is tighter.
    const bool step_tight_enough =
        !options.adaptive_inner_tolerance() || tolerance <= 0.1 * options.kkt_tolerance;
    if (rec.dual_change < options.uzawa_tolerance && step_tight_enough) {
      o.stop = Termination::Converged;
      o.message = dual_change_message(rec, options.uzawa_tolerance, k, "Uzawa steps");
      return o;
    }
    if (finishes) try_active_set_finish(k, o);
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

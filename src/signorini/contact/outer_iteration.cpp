#include "signorini/contact/outer_iteration.hpp"

#include <fmt/format.h>

namespace signorini {

void run_outer_loop(const OuterLoop& loop, Vector l0, const ContactSolverOptions& options,
                    ContactResult& out) {
  SolveSummary& s = out.summary;
  Vector l = std::move(l0);
  const Index num_contact = l.size();
  s.termination = Termination::IterationLimit;
  bool stopped = false;  // by convergence or by the method (a failure of its step)
  for (int k = 1; k <= loop.max_steps; ++k) {
    OuterStepOutcome o = loop.step(k, l);
    s.steps.push_back(o.record);
    // A step that produced multipliers is reported, whether the method goes on, converged or
    // stops on what they show (active-set cycling); a failed step leaves l^(k-1).
    if (o.l.size() == num_contact) {
      l = std::move(o.l);
      const bool report = !loop.report || loop.report(k);
      const IterationEvent event{.kind = IterationEvent::Kind::Outer,
                                 .outer = k,
                                 .inner = o.record.inner_iterations,
                                 .active = o.record.active_set_size,
                                 .residual = o.record.dual_change,
                                 .armijo = o.record.armijo_reductions,
                                 .linear_iterations = o.record.linear_iterations};
      // The callback sees every step (it may enforce a time limit); the observer the reported.
      if (report && options.observer) options.observer(event);
      if (!o.stop && options.callback && options.callback(event) == CallbackAction::Stop) {
        o.stop = Termination::StoppedByCallback;
        o.message = fmt::format("stopped by the callback after outer step {}", k);
      }
    }
    if (o.stop) {
      s.termination = *o.stop;
      s.message = std::move(o.message);
      stopped = true;
      break;
    }
  }
  if (!stopped)
    s.message = loop.limit_message(s.steps.empty() ? OuterStepRecord{} : s.steps.back());
  out.l = std::move(l);
}

std::string dual_change_message(const OuterStepRecord& rec, double tolerance, int k,
                                const std::string& steps_name) {
  return fmt::format("||l^k - l^(k-1)|| / ||l^k|| = {:.3e} < {:.1e} after {} {}", rec.dual_change,
                     tolerance, k, steps_name);
}

}  // namespace signorini

#include "signorini/problem/load_stepping.hpp"

#include <fmt/format.h>

#include <chrono>
#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {

ContactResult solve_load_steps(const Model& model, const ContactSolverOptions& options,
                               const std::vector<double>& factors, const LoadStepSink& each_step) {
  if (factors.empty()) throw InputError("loading: no load factors");
  for (const double f : factors)
    if (!std::isfinite(f) || f < 0.0)
      throw InputError("loading: the load factors must be finite and >= 0");
  for (const LoadGroup& g : model.load_groups)
    if (g.factors.size() != factors.size())
      throw InputError(fmt::format("{}.factors: expected {} load factors, one per step, got {}",
                                   g.entry, factors.size(), g.factors.size()));
  const ContactProblem& p = model.problem;
  const ContactSet& c = p.contact;
  ContactSolver solver(p, options, &model.multigrid);
  std::vector<LoadStepRecord> history;
  Vector slip = Vector::Zero(c.size());
  ContactResult previous;
  for (std::size_t k = 0; k < factors.size(); ++k) {
    const double t = factors[k];
    const int step = static_cast<int>(k) + 1;
    // b is linear in the loads and u_D together (b = f - K u_D on the free dofs); the gaps move
    // with u_D's normal component (Model::contact_gaps).
    solver.set_loads(model.free_loads(t, step));
    if (model.contact_gap_shift.size() != 0) solver.set_gaps(model.contact_gaps(t, step));
    if (k > 0) {
      solver.warm_start(previous);
      solver.set_slip_origin(previous.u);  // each step's slip is its increment
    }
    const auto start = std::chrono::steady_clock::now();
    ContactResult r = solver.solve();
    r.load_factor = t;
    r.load_step = step;
    if (r.slip.size() == c.size()) {
      slip += r.slip;
      r.slip = slip;
    }
    const SolveSummary& s = r.summary;
    history.push_back(
        {t, s.converged(), s.outer_iterations, s.num_active, s.contact_force,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    r.summary.load_steps = history;
    if (each_step) each_step(step, r);
    if (!s.converged() || k + 1 == factors.size()) return r;
    previous = std::move(r);
  }
  return previous;  // not reached
}

ContactResult solve_model(const Model& model, const ContactSolverOptions& options,
                          const std::vector<double>& factors, const LoadStepSink& each_step) {
  ContactResult r = factors.empty() ? solve_contact(model.problem, options, &model.multigrid)
                                    : solve_load_steps(model, options, factors, each_step);
  r.summary.path_reason = model.solver_reason;
  return r;
}

}  // namespace signorini

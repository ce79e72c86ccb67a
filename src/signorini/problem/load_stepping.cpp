#include "signorini/problem/load_stepping.hpp"

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
  const ContactProblem& p = model.problem;
  const ContactSet& c = p.contact;
  // The contact set's gaps are g - nu . u_D at each node (fem/contact_boundary.cpp): at factor
  // t the prescribed part is t u_D, so g_t = gaps + (1 - t) nu . u_D.
  Vector prescribed_normal = Vector::Zero(c.size());
  if (model.dofs.has_prescribed_values())
    for (Index j = 0; j < c.size(); ++j)
      prescribed_normal(j) =
          c.normals.col(j).dot(model.dofs.prescribed_at(c.nodes[static_cast<std::size_t>(j)]));
  ContactSolver solver(p, options, &model.multigrid);
  std::vector<LoadStepRecord> history;
  Vector slip = Vector::Zero(c.size());
  ContactResult previous;
  for (std::size_t k = 0; k < factors.size(); ++k) {
    const double t = factors[k];
    // b is linear in the loads and u_D together (b = f - K u_D on the free dofs).
    solver.set_loads(t * p.b);
    if (model.dofs.has_prescribed_values()) solver.set_gaps(c.gaps + (1.0 - t) * prescribed_normal);
    if (k > 0) {
      solver.warm_start(previous);
      solver.set_slip_origin(previous.u);  // each step's slip is its increment
    }
    const auto start = std::chrono::steady_clock::now();
    ContactResult r = solver.solve();
    r.load_factor = t;
    if (r.slip.size() == c.size()) {
      slip += r.slip;
      r.slip = slip;
    }
    const SolveSummary& s = r.summary;
    history.push_back(
        {t, s.converged(), s.outer_iterations, s.num_active, s.contact_force,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()});
    r.summary.load_steps = history;
    if (each_step) each_step(static_cast<int>(k) + 1, r);
    if (!s.converged() || k + 1 == factors.size()) return r;
    previous = std::move(r);
  }
  return previous;  // not reached
}

}  // namespace signorini

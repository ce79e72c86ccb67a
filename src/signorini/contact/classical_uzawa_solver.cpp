// The classical Uzawa method on the ordinary Lagrangian L(v, l) = J(v) + sum_j h_j l_j ((N v)_j -
// g_j) (method.md section 2, last paragraph): the baseline the paper improves on. Step (i) is a
// linear solve with l^k as a load, step (ii) a projected gradient step of length rho.

#include <fmt/format.h>

#include <cmath>

#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/outer_iteration.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// Largest eigenvalue of the dual operator T = H^(1/2) N A^-1 N^T H^(1/2) (H = diag(h)) by power
// iteration; the projected gradient step converges for rho < 2 / lambda_max(T).
double dual_operator_norm(const ContactProblem& p, LinearSolver& solver) {
  const ContactSet& c = p.contact;
  const Vector sqrt_h = c.weights.cwiseSqrt();
  Vector v(c.size());
  for (Index j = 0; j < c.size(); ++j)
    v(j) =
        c.movable[static_cast<std::size_t>(j)] ? 1.0 + 0.1 * std::sin(static_cast<double>(j)) : 0.0;
  v.normalize();
  double lambda = 0.0;
  Vector x = Vector::Zero(p.A.rows());
  for (int it = 0; it < 200; ++it) {
    solver.solve(c.N.transpose() * sqrt_h.cwiseProduct(v), x);
    const Vector w = sqrt_h.cwiseProduct(c.N * x);
    const double next = v.dot(w);
    const double wn = w.norm();
    if (!(wn > 0.0)) break;
    v = w / wn;
    const bool settled = std::abs(next - lambda) <= 1e-6 * std::abs(next);
    lambda = next;
    if (settled) break;
  }
  if (!(lambda > 0.0)) throw NumericalError("classical Uzawa: the dual operator is zero");
  return lambda;
}

}  // namespace

ContactResult solve_classical_uzawa(const ContactProblem& problem,
                                    const ContactSolverOptions& options, const MethodStart& start) {
  ContactResult out;
  SolveSummary& s = out.summary;
  const ContactSet& c = problem.contact;
  auto solver = make_linear_solver(options.linear);
  solver->analyze(problem.A);
  solver->factorize(problem.A);  // A never changes: one factorisation for the whole run

  const double rho = options.classical_step > 0.0 ? options.classical_step
                                                  : 1.5 / dual_operator_norm(problem, *solver);
  s.classical_step = rho;

  Vector x = start.displacement(problem.A.rows());
  OuterLoop loop;
  loop.max_steps = options.max_classical_iterations;
  loop.step = [&](int k, const Vector& l) {
    OuterStepOutcome o;
    OuterStepRecord& rec = o.record;
    // (i) A u = b - N^T H l: the contact pressure acts as a load.
    const LinearSolveStats st =
        solver->solve(problem.b - c.N.transpose() * c.weights.cwiseProduct(l), x);
    rec.inner_iterations = 1;
    rec.linear_iterations = st.iterations;
    rec.factorizations = k == 1 ? 1 : 0;
    if (!st.converged) {
      o.stop = Termination::LinearSolverFailure;
      o.message = fmt::format("linear solver did not converge at Uzawa step {} (residual {:.3e})",
                              k, st.residual);
      return o;
    }
    // (ii) l^{k+1} = P(l^k + rho ((N u)_j - g_j)), P(z) = z_+ for the paper's law
    o.l = contact_law(options).project(l + rho * (c.N * x - c.gaps));
    for (Index j = 0; j < c.size(); ++j)
      if (!c.movable[static_cast<std::size_t>(j)]) o.l(j) = 0.0;
    rec.dual_change = relative_change(o.l, l);
    rec.active_set_size = (o.l.array() > 0.0).count();
    if (rec.dual_change < options.uzawa_tolerance) {
      o.stop = Termination::Converged;
      o.message = dual_change_message(rec, options.uzawa_tolerance, k,
                                      fmt::format("classical Uzawa steps (rho = {:.4e})", rho));
    }
    return o;
  };
  loop.limit_message = [&](const OuterStepRecord& last) {
    return fmt::format(
        "classical Uzawa did not converge in {} steps: ||l^k - l^(k-1)|| / ||l^k|| = {:.3e} "
        "(tolerance {:.1e}, rho = {:.4e})",
        options.max_classical_iterations, last.dual_change, options.uzawa_tolerance, rho);
  };
  // Thousands of cheap steps: the first ten and every hundredth go to the observer.
  loop.report = [](int k) { return k <= 10 || k % 100 == 0; };
  run_outer_loop(loop, start.multipliers(c.size()), options, out);
  s.timings.merge(solver->timings());
  out.u = std::move(x);
  return out;
}

}  // namespace signorini

// The classical Uzawa method on the ordinary Lagrangian L(v, l) = J(v) + sum_j h_j l_j ((N v)_j -
// g_j) (method.md section 2, last paragraph): the baseline the paper improves on. Step (i) is a
// linear solve with l^k as a load, step (ii) a projected gradient step of length rho. With
// friction the same on every row of N (normal and tangential), the law projecting each node's
// d values (friction_law.hpp).

#include <fmt/format.h>

#include <cmath>

#include "signorini/backend/host_backend.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/outer_iteration.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"

namespace signorini {

namespace {

// The dual operator T = H^(1/2) N A^-1 N^T H^(1/2) (H = diag(h)) on a host backend's vectors: a
// solve with A's factor per product. Its largest eigenvalue bounds the projected gradient step:
// step (ii) converges for rho < 2 / lambda_max(T).
class DualOperator final : public LinearOperator {
 public:
  DualOperator(const ContactProblem& p, LinearSolver& solver)
      : contact_(p.contact),
        solver_(solver),
        sqrt_h_(row_weights(p.contact).cwiseSqrt()),
        u_(Vector::Zero(p.A.rows())) {}
  [[nodiscard]] Index size() const override { return contact_.N.rows(); }
  void apply(const DeviceVector& x, DeviceVector& y) override {
    const Eigen::Map<const Vector> v(x.data(), x.size());
    solver_.solve(contact_.N.transpose() * sqrt_h_.cwiseProduct(v), u_);  // u_: the last guess
    Eigen::Map<Vector>(y.data(), y.size()) = sqrt_h_.cwiseProduct(contact_.N * u_);
  }

 private:
  const ContactSet& contact_;
  LinearSolver& solver_;
  Vector sqrt_h_, u_;
};

// lambda_max(T) by Lanczos steps (eigenvalue_estimate.hpp) from a smooth start on the movable
// nodes. T's spectrum falls off quickly (it is a discrete inverse of a Dirichlet-to-Neumann map),
// so its top is found in a few steps; 30 give it to many digits.
double dual_operator_norm(const ContactProblem& p, LinearSolver& solver) {
  const ContactSet& c = p.contact;
  Vector v(c.N.rows());
  for (Index i = 0; i < v.size(); ++i)
    v(i) = c.movable[static_cast<std::size_t>(i / c.components)]
               ? 1.0 + 0.1 * std::sin(static_cast<double>(i))
               : 0.0;
  HostBackend host;
  DualOperator T(p, solver);
  IdentityPreconditioner identity;
  const DeviceVector start = to_device(host, v);
  const auto zero = [] { return NumericalError("classical Uzawa: the dual operator is zero"); };
  double lambda = 0.0;
  try {
    lambda = estimate_largest_eigenvalue(T, identity, start, 30);
  } catch (const NumericalError&) {
    throw zero();  // not one step: T vanishes on the start vector
  }
  if (!(lambda > 0.0)) throw zero();
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
  const Vector h = row_weights(c), g_hat = row_offsets(c);
  const Index m = c.components;
  OuterLoop loop;
  loop.max_steps = options.max_classical_iterations;
  loop.step = [&](int k, const Vector& l) {
    OuterStepOutcome o;
    OuterStepRecord& rec = o.record;
    // (i) A u = b - N^T H l: the contact pressure acts as a load.
    const LinearSolveStats st = solver->solve(problem.b - c.N.transpose() * h.cwiseProduct(l), x);
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
    o.l = contact_law(options).project(l + rho * (c.N * x - g_hat));
    for (Index j = 0; j < c.size(); ++j)
      if (!c.movable[static_cast<std::size_t>(j)]) o.l.segment(m * j, m).setZero();
    rec.dual_change = relative_change(o.l, l);
    rec.active_set_size = count_in_contact(o.l, m);
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
  run_outer_loop(loop, start.multipliers(c.N.rows()), options, out);
  s.timings.merge(solver->timings());
  out.u = std::move(x);
  return out;
}

}  // namespace signorini

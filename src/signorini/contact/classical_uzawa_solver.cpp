// The classical Uzawa method on the ordinary Lagrangian L(v, l) = J(v) + sum_j h_j l_j ((N v)_j -
// g_j) (method.md section 2, last paragraph): the baseline the paper improves on. Step (i) is a
// linear solve with l^k as a load, step (ii) a projected gradient step of length rho. With
// friction the same on every row of N (normal and tangential), the law projecting each node's
// d values (friction_law.hpp). In one process on a linear solver (a factor, or CG); on the
// distributed path on the engine's Newton space with no node active, whose matrix is A.

#include <fmt/format.h>

#include <cmath>
#include <functional>
#include <memory>

#include "signorini/backend/host_backend.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/outer_iteration.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/eigenvalue_estimate.hpp"

namespace signorini {

namespace {

// Step (i)'s linear algebra, wherever it runs: one process's factor or CG (LinearSolver), or the
// distributed engine's Newton space with no node active (H = A).
struct LoadSolves {
  /// u <- A^-1 (b - N^T w), from the last u; w holds d values per contact node (N's rows).
  std::function<LinearSolveStats(const Vector& w)> solve;
  /// N u at the last u (every row, on every rank).
  std::function<Vector()> contact_values;
  /// N A^-1 N^T w, for the dual operator (u unchanged).
  std::function<Vector(const Vector& w)> dual_product;
};

// The dual operator T = H^(1/2) N A^-1 N^T H^(1/2) (H = diag(h)) on a host backend's vectors: a
// linear solve per product. Its largest eigenvalue bounds the projected gradient step: step (ii)
// converges for rho < 2 / lambda_max(T).
class DualOperator final : public LinearOperator {
 public:
  DualOperator(const ContactProblem& p, const LoadSolves& solves)
      : nc_(p.contact.N.rows()), solves_(solves), sqrt_h_(row_weights(p.contact).cwiseSqrt()) {}
  [[nodiscard]] Index size() const override { return nc_; }
  void apply(const DeviceVector& x, DeviceVector& y) override {
    const Eigen::Map<const Vector> v(x.data(), x.size());
    Eigen::Map<Vector>(y.data(), y.size()) =
        sqrt_h_.cwiseProduct(solves_.dual_product(sqrt_h_.cwiseProduct(v)));
  }

 private:
  Index nc_;
  const LoadSolves& solves_;
  Vector sqrt_h_;
};

// lambda_max(T) by Lanczos steps (eigenvalue_estimate.hpp) from a smooth start on the movable
// nodes. T's spectrum falls off quickly (it is a discrete inverse of a Dirichlet-to-Neumann map),
// so its top is found in a few steps; 30 give it to many digits.
double dual_operator_norm(const ContactProblem& p, const LoadSolves& solves) {
  const ContactSet& c = p.contact;
  Vector v(c.N.rows());
  for (Index i = 0; i < v.size(); ++i)
    v(i) = c.movable[static_cast<std::size_t>(i / c.components)]
               ? 1.0 + 0.1 * std::sin(static_cast<double>(i))
               : 0.0;
  HostBackend host;
  DualOperator T(p, solves);
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

// The method itself on any LoadSolves: steps (i) and (ii) until the dual change is small.
void run_classical_uzawa(const ContactProblem& problem, const ContactSolverOptions& options,
                         const MethodStart& start, const LoadSolves& solves, bool factorized,
                         ContactResult& out) {
  SolveSummary& s = out.summary;
  const ContactSet& c = problem.contact;
  const double rho = options.classical_step > 0.0 ? options.classical_step
                                                  : 1.5 / dual_operator_norm(problem, solves);
  s.classical_step = rho;
  const Vector h = row_weights(c), g_hat = row_offsets(c);
  const Index m = c.components;
  OuterLoop loop;
  loop.max_steps = options.max_classical_iterations;
  loop.step = [&](int k, const Vector& l) {
    OuterStepOutcome o;
    OuterStepRecord& rec = o.record;
    // (i) A u = b - N^T H l: the contact pressure acts as a load.
    const LinearSolveStats st = solves.solve(h.cwiseProduct(l));
    rec.inner_iterations = 1;
    rec.linear_iterations = st.iterations;
    rec.factorizations = k == 1 && factorized ? 1 : 0;
    if (!st.converged) {
      o.stop = Termination::LinearSolverFailure;
      o.message = fmt::format("linear solver did not converge at Uzawa step {} (residual {:.3e})",
                              k, st.residual);
      return o;
    }
    // (ii) l^{k+1} = P(l^k + rho ((N u)_j - g_j)), P(z) = z_+ for the paper's law
    o.l = contact_law(problem).project(l + rho * (solves.contact_values() - g_hat));
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
}

}  // namespace

ContactResult solve_classical_uzawa(const ContactProblem& problem,
                                    const ContactSolverOptions& options, const MethodStart& start,
                                    const MultigridHierarchy* /*multigrid*/) {
  ContactResult out;
  const ContactSet& c = problem.contact;
  auto solver = make_linear_solver(options.linear);
  solver->analyze(problem.A);
  solver->factorize(problem.A);  // A never changes: one factorisation for the whole run
  Vector x = start.displacement(problem.A.rows());
  Vector dual_u = Vector::Zero(problem.A.rows());  // the dual products' last guess
  LoadSolves solves;
  solves.solve = [&](const Vector& w) { return solver->solve(problem.b - c.N.transpose() * w, x); };
  solves.contact_values = [&] { return Vector(c.N * x); };
  solves.dual_product = [&](const Vector& w) {
    solver->solve(c.N.transpose() * w, dual_u);
    return Vector(c.N * dual_u);
  };
  run_classical_uzawa(problem, options, start, solves, true, out);
  out.summary.timings.merge(solver->timings());
  out.u = std::move(x);
  return out;
}

ContactResult solve_classical_uzawa_distributed(const ContactProblem& problem,
                                                const ContactSolverOptions& options,
                                                const MethodStart& start,
                                                const MultigridHierarchy* /*multigrid*/) {
  return run_on_distributed_space(
      problem, options, start, [&](DistributedNewtonSpace& space, ContactResult& out) {
        // H = A: no row active (a Newton matrix with no contact terms). Each solve starts from
        // the last u and moves there: solve gives u_new, direction() d = u_new - u, step(1)
        // u = u_new.
        space.set_active(ActiveSet(static_cast<std::size_t>(problem.contact.N.rows()), false), 1.0);
        ModifiedLagrangian::Direction dir;
        LoadSolves solves;
        solves.solve = [&](const Vector& w) {
          const NewtonSolveStats st = space.solve(w);
          LinearSolveStats stats;
          stats.converged = st.converged;
          stats.iterations = st.iterations;
          stats.residual = st.residual;
          if (st.converged) {
            space.direction(dir);
            space.step(1.0);
          }
          return stats;
        };
        solves.contact_values = [&] { return space.contact_values(); };
        solves.dual_product = [&](const Vector& w) {
          NewtonSolveStats st;
          Vector y = space.contact_response(w, st);
          if (!st.converged)
            throw NumericalError(fmt::format(
                "classical Uzawa: {} did not converge in the estimate of the step (residual "
                "{:.3e})",
                st.solver, st.residual));
          return y;
        };
        run_classical_uzawa(problem, options, start, solves, false, out);
      });
}

}  // namespace signorini

#include "signorini/contact/contact_solver.hpp"

#include <limits>

#include "signorini/contact/condensed_problem.hpp"
#include "signorini/contact/kkt_residuals.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

double relative_change(const Vector& l_new, const Vector& l_old) {
  const double diff = (l_new - l_old).norm();
  const double norm = l_new.norm();
  if (norm > 0.0) return diff / norm;
  return diff == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
}

namespace {
ContactResult run_method(const ContactProblem& problem, const ContactSolverOptions& options) {
  switch (options.method) {
    case ContactMethod::UzawaGnm:
      return solve_uzawa_gnm(problem, options);
    case ContactMethod::ClassicalUzawa:
      return solve_classical_uzawa(problem, options);
    case ContactMethod::SemismoothNewton:
      return solve_semismooth_newton(problem, options);
  }
  throw InputError("unknown contact method");
}
}  // namespace

ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& options) {
  validate(options);
  const Index n = problem.A.rows();
  if (problem.A.cols() != n || problem.b.size() != n || problem.contact.N.cols() != n)
    throw InputError("contact problem: sizes of A, b and N do not match");

  ContactResult result;
  {
    TimingTable solve_time;
    ScopedTimer timer(solve_time, "contact solve");
    if (uses_backend_path(options)) {
      result = solve_uzawa_gnm_on_backend(problem, options);
    } else if (options.schur_complement && options.linear.type == LinearSolverType::Cholmod) {
      const CondensedProblem condensed(problem);
      ContactSolverOptions reduced_options = options;
      reduced_options.linear.type = LinearSolverType::Dense;
      result = run_method(condensed.reduced(), reduced_options);
      result.u = condensed.expand(result.u);
      TimingTable t = condensed.timings();
      t.merge(result.summary.timings);
      result.summary.timings = std::move(t);
    } else {
      result = run_method(problem, options);
    }
    timer.stop();
    result.summary.timings.merge(solve_time);
  }
  SolveSummary& s = result.summary;
  s.method = options.method;
  s.outer_iterations = static_cast<int>(s.steps.size());
  s.kkt = kkt_residuals(problem, result.u, result.l);
  s.energy = 0.5 * result.u.dot(problem.A * result.u) - problem.b.dot(result.u);
  s.lagrangian = ModifiedLagrangian::value(problem, options.r, result.u, result.l);
  const ContactSet& c = problem.contact;
  s.contact_force = c.weights.dot(result.l);
  s.contact_force_vector = -(c.normals * c.weights.cwiseProduct(result.l));
  s.num_active = (result.l.array() > 0.0).count();
  return result;
}

}  // namespace signorini

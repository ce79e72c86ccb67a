#include "signorini/contact/contact_solver.hpp"

#include <limits>

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

ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& options) {
  validate(options);
  const Index n = problem.A.rows();
  if (problem.A.cols() != n || problem.b.size() != n || problem.contact.N.cols() != n)
    throw InputError("contact problem: sizes of A, b and N do not match");

  ContactResult result;
  {
    TimingTable solve_time;
    ScopedTimer timer(solve_time, "contact solve");
    switch (options.method) {
      case ContactMethod::UzawaGnm: result = solve_uzawa_gnm(problem, options); break;
      case ContactMethod::ClassicalUzawa: result = solve_classical_uzawa(problem, options); break;
      case ContactMethod::SemismoothNewton:
        result = solve_semismooth_newton(problem, options);
        break;
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

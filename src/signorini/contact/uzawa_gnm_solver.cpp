// The paper's method: Uzawa iterations (13) on the modified Lagrangian (10), each step (i)
// minimised by the generalised Newton method (17) (method.md sections 2-4), on the host with a
// sparse or dense Newton system.

#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/newton_system.hpp"
#include "signorini/contact/uzawa_iteration.hpp"

namespace signorini {

ContactResult solve_uzawa_gnm(const ContactProblem& problem, const ContactSolverOptions& options) {
  ContactResult out;
  ModifiedLagrangian phi(problem, augmentation_parameter(problem, options));
  const auto system = make_newton_system(problem, phi, options.linear);
  GeneralizedNewton gnm(problem, options, *system);
  Vector x = Vector::Zero(problem.A.rows());
  run_uzawa_iteration(
      problem, options, phi,
      [&](const ModifiedLagrangian& current, int k, Vector& Nx) {
        const GnmResult g = gnm.minimize(current, x, k);
        Nx = problem.contact.N * x;
        return g;
      },
      out);
  out.summary.timings.merge(system->timings());
  out.u = std::move(x);
  return out;
}

}  // namespace signorini

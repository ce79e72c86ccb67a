// The paper's method: Uzawa iterations (13) on the modified Lagrangian (10), each step (i)
// minimised by the generalised Newton method (17) (method.md sections 2-4). One loop of each
// (uzawa_iteration.cpp, generalized_newton.cpp); what differs between the host and a backend is
// only where the vectors live and how the Newton systems are solved (NewtonSpace).

#include <memory>

#include "signorini/contact/backend_newton_space.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/host_newton_space.hpp"
#include "signorini/contact/newton_system.hpp"
#include "signorini/contact/uzawa_iteration.hpp"

namespace signorini {

ContactResult solve_uzawa_gnm(const ContactProblem& problem, const ContactSolverOptions& options,
                              const MethodStart& start, const MultigridHierarchy* /*multigrid*/) {
  ContactResult out;
  ModifiedLagrangian phi(problem, augmentation_parameter(problem, options));
  const auto system = make_newton_system(problem, phi, options.linear);
  HostNewtonSpace space(problem, *system, start.displacement(problem.A.rows()));
  run_uzawa_iteration(problem, options, phi, space, start.multipliers(problem.contact.N.rows()),
                      out);
  out.summary.timings.merge(system->timings());
  out.u = space.take_x();
  return out;
}

ContactResult solve_uzawa_gnm_on_backend(const ContactProblem& problem,
                                         const ContactSolverOptions& options,
                                         const MethodStart& start,
                                         const MultigridHierarchy* multigrid) {
  ContactResult out;
  SolveSummary& s = out.summary;
  TimingTable timings;
  const std::unique_ptr<Backend> backend = make_timed_backend(options, timings);
  BackendNewtonSpace space(problem, options, multigrid, *backend, timings,
                           start.displacement(problem.A.rows()));
  ModifiedLagrangian phi(problem, augmentation_parameter(problem, options));
  run_uzawa_iteration(problem, options, phi, space, start.multipliers(problem.contact.N.rows()),
                      out);
  {
    ScopedTimer t(timings, "device download");
    out.u = space.solution();
  }
  record_backend(s, *backend, space.levels(), multigrid);
  s.timings = std::move(timings);
  return out;
}

ContactResult run_on_distributed_space(
    const ContactProblem& problem, const ContactSolverOptions& options, const MethodStart& start,
    const std::function<void(DistributedNewtonSpace&, ContactResult&)>& method) {
  DistributedEngine& engine = required_engine(problem);
  ContactResult out;
  TimingTable timings;
  const std::unique_ptr<DistributedNewtonSpace> space =
      engine.newton_space(problem, options, start.held_displacement(problem), timings);
  method(*space, out);
  {
    ScopedTimer t(timings, "gather");
    out.u = space->rank_solution();
  }
  record_distributed(out.summary, engine, space->linear_solver_description());
  out.summary.timings.merge(timings);
  return out;
}

ContactResult solve_uzawa_gnm_distributed(const ContactProblem& problem,
                                          const ContactSolverOptions& options,
                                          const MethodStart& start,
                                          const MultigridHierarchy* /*multigrid: the KSP's*/) {
  return run_on_distributed_space(
      problem, options, start, [&](DistributedNewtonSpace& space, ContactResult& out) {
        ModifiedLagrangian phi(problem, augmentation_parameter(problem, options));
        run_uzawa_iteration(problem, options, phi, space,
                            start.multipliers(problem.contact.N.rows()), out);
      });
}

}  // namespace signorini

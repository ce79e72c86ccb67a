// `signorini check PROBLEM.toml`: everything a solve does before solving, so that a typo is found
// in a second and not after the queue wait of a long run.

#include <fmt/format.h>

#include "commands.hpp"
#include "model_loading.hpp"
#include "signorini/backend/make_backend.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/mesh/mesh_description.hpp"

namespace signorini::app {

int run_check(const CheckArguments& args) {
  const LoadedProblem loaded = read_problem_file(args.problem_file, args.overrides);
  print_warnings(loaded);
  const Model model = build_model_for(loaded, args.engine);
  print_warnings(model_warnings(loaded, model));
  // A solve on the GPU would stop at its first step without one: say so now (docs/gpu.md).
  if (loaded.spec.solver.device == DeviceKind::Cuda) {
    const auto backend = make_backend(DeviceKind::Cuda);  // throws InputError, with the reason
    fmt::print("device: {}\n", backend->description());
  }
  // (Under mpirun each rank holds its part of the mesh: rank 0 says how large the whole is.)
  if (model.is_part())
    fmt::print("mesh: {} nodes, in parts (rank 0's: {})\n", model.whole.nodes,
               mesh_description(model.mesh));
  else
    fmt::print("mesh: {}\n", mesh_description(model.mesh));
  fmt::print("solver path: {}\n", model.solver_reason);
  // Under mpirun the solve is distributed (docs/distributed.md): the plan above then says which
  // Newton-system solver the ranks share.
  if (const DistributedEngine* engine = model.problem.engine;
      engine != nullptr && distributed_path(model.problem, model.solver)) {
    const PetscMultigrid multigrid =
        resolved_petsc_multigrid(model.solver.petsc_multigrid, engine->size());
    fmt::print(
        "distributed: {}, each rank holding its part of the stiffness; the Newton "
        "systems by {}\n",
        engine->description(),
        model.solver.linear.type != LinearSolverType::ConjugateGradient
            ? "MUMPS (the plan's direct solver)"
        : model.solver.linear.preconditioner == PreconditionerType::Jacobi ? "CG with Jacobi"
        : multigrid == PetscMultigrid::Hypre ? "CG with hypre's BoomerAMG"
        : multigrid == PetscMultigrid::Aggregation
            ? "CG with smoothed aggregation on each rank's nodes"
            : "CG with GAMG");
  }
  fmt::print("ok: {} dofs, {} contact nodes\n", model.num_dofs(), model.problem.contact.size());
  return kSuccess;
}

}  // namespace signorini::app

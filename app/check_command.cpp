// `signorini check PROBLEM.toml`: everything a solve does before solving, so that a typo is found
// in a second and not after the queue wait of a long run.

#include <fmt/format.h>

#include "commands.hpp"
#include "model_loading.hpp"
#include "signorini/backend/make_backend.hpp"
#include "signorini/mesh/mesh_description.hpp"

namespace signorini::app {

int run_check(const CheckArguments& args) {
  const LoadedProblem loaded = read_problem_file(args.problem_file, args.overrides);
  print_warnings(loaded);
  const Model model = build_model_for(loaded);
  // A solve on the GPU would stop at its first step without one: say so now (docs/gpu.md).
  if (loaded.spec.solver.device == DeviceKind::Cuda) {
    const auto backend = make_backend(DeviceKind::Cuda);  // throws InputError, with the reason
    fmt::print("device: {}\n", backend->description());
  }
  fmt::print("mesh: {}\n", mesh_description(model.mesh));
  fmt::print("solver path: {}\n", model.solver_reason);
  fmt::print("ok: {} dofs, {} contact nodes\n", model.dofs.num_dofs(),
             model.problem.contact.size());
  return kSuccess;
}

}  // namespace signorini::app

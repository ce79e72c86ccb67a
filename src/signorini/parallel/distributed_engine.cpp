#include "signorini/parallel/distributed_engine.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {
DistributedEngine* registered = nullptr;
}  // namespace

DistributedEngine* distributed_engine() {
  return registered;
}

void set_distributed_engine(DistributedEngine* engine) {
  registered = engine;
}

DistributedEngine& required_distributed_engine() {
  if (registered == nullptr) throw InputError("the distributed path needs a PETSc engine");
  return *registered;
}

void record_distributed(SolveSummary& summary, const DistributedEngine& engine,
                        const std::string& linear_solver) {
  summary.device = engine.description() + ", " + linear_solver;
  summary.ranks = engine.size();
}

void sum_over_ranks(const ContactProblem& problem, double* values, Index count) {
  if (!problem.partitioned()) return;
  if (registered == nullptr)
    throw InputError("a partitioned contact problem needs the distributed engine that made it");
  registered->sum(values, count);
}

Vector stiffness_product(const ContactProblem& problem, const Vector& u) {
  Vector Au = problem.A * u;
  sum_over_ranks(problem, Au.data(), Au.size());
  return Au;
}

bool distributed_path(const ContactSolverOptions& options) {
  const DistributedEngine* engine = registered;
  switch (options.distributed) {
    case DistributedMode::Petsc:
      if (engine == nullptr)
        throw InputError(
            "solver.distributed = \"petsc\": this program has no PETSc engine; run "
            "signorini-mpi (beside signorini in a build with PETSc), or signorini under mpirun, "
            "which becomes it (docs/distributed.md)");
      return true;
    case DistributedMode::Off:
      if (engine != nullptr && engine->size() > 1)
        throw InputError(fmt::format(
            "solver.distributed = \"off\" on {} MPI ranks: each rank would solve the whole "
            "problem alone; run without mpirun, or remove solver.distributed",
            engine->size()));
      return false;
    case DistributedMode::Auto:
      break;
  }
  return engine != nullptr && engine->size() > 1;
}

}  // namespace signorini

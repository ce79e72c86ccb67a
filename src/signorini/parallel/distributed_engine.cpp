#include "signorini/parallel/distributed_engine.hpp"

#include <fmt/format.h>

#include <cmath>

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

Vector held_stiffness_rows(const ContactProblem& problem, const Vector& u) {
  if (!problem.partitioned()) return problem.A * u;
  // Row i of A is its column i, which a partitioned A holds for the rows it owns.
  const Index first = problem.first_row(), end = problem.end_row();
  Vector rows(end - first);
  for (Index i = first; i < end; ++i) {
    double s = 0.0;
    for (SparseMatrix::InnerIterator it(problem.A, problem.column_of(i)); it; ++it)
      s += it.value() * u(it.row());
    rows(i - first) = s;
  }
  return rows;
}

double quadratic_energy(const ContactProblem& problem, const Vector& u) {
  const Vector held = problem.held_rows(u);
  double e = 0.5 * held.dot(held_stiffness_rows(problem, u)) - problem.b.dot(held);
  sum_over_ranks(problem, &e, 1);
  return e;
}

double load_norm(const ContactProblem& problem) {
  double squares = problem.b.squaredNorm();
  sum_over_ranks(problem, &squares, 1);
  return std::sqrt(squares);
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

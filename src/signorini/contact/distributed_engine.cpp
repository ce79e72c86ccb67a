#include "signorini/contact/distributed_engine.hpp"

#include <fmt/format.h>

#include <cmath>

#include "signorini/core/error.hpp"
#include "signorini/parallel/row_partition.hpp"

namespace signorini {

DistributedEngine& required_engine(const ContactProblem& problem) {
  if (problem.engine == nullptr)
    throw InputError(
        "a partitioned problem, or a solve on the distributed path, needs the PETSc engine of "
        "the problem's ranks (build_model(spec, &engine))");
  return *problem.engine;
}

void record_distributed(SolveSummary& summary, const DistributedEngine& engine,
                        const std::string& linear_solver) {
  summary.device = engine.description() + ", " + linear_solver;
  summary.ranks = engine.size();
}

void sum_over_ranks(const ContactProblem& problem, double* values, Index count) {
  if (problem.partitioned()) required_engine(problem).sum(values, count);
}

Vector held_stiffness_rows(const ContactProblem& problem, const Vector& u) {
  if (!problem.partitioned()) return problem.A * u;
  // Row i of A is its column i, which a partitioned A holds for the rows it owns; a part's
  // solution has their own unknowns in one run (from `own`) and the others by their place.
  const Index first = problem.first_row(), end = problem.end_row();
  const bool part = problem.part_solution();
  const Index own = part && end > first ? problem.solution_index(first) : first;
  Vector rows(end - first);
  for (Index i = first; i < end; ++i) {
    double s = 0.0;
    for (SparseMatrix::InnerIterator it(problem.A, problem.column_of(i)); it; ++it) {
      const Index r = it.row();
      const Index at =
          !part ? r : (r >= first && r < end ? own + (r - first) : problem.solution_index(r));
      if (at < 0)
        throw NumericalError(
            fmt::format("A u: unknown {} is neither this rank's nor in its part", r));
      s += it.value() * u(at);
    }
    rows(i - first) = s;
  }
  return rows;
}

Vector contact_rows(const ContactProblem& problem, const Vector& u) {
  const SparseMatrix& N = problem.contact.N;
  if (!problem.part_solution()) return N * u;
  // Each row's unknowns are one node's, on one rank (parallel/row_partition.hpp): that rank
  // computes the row, the others add 0.
  const Index first = problem.first_row();
  const Vector own = problem.held_rows(u);
  Vector rows = Vector::Zero(N.rows());
  for (Index k = 0; k < own.size(); ++k)
    for (SparseMatrix::InnerIterator it(N, first + k); it; ++it)
      rows(it.row()) += it.value() * own(k);
  sum_over_ranks(problem, rows.data(), rows.size());
  return rows;
}

Index solution_size(const ContactProblem& problem) {
  return problem.part_solution() ? static_cast<Index>(problem.solution_unknowns.size())
                                 : problem.A.rows();
}

double largest_displacement(const ContactProblem& problem, const Vector& u) {
  if (!problem.part_solution()) return u.size() > 0 ? u.lpNorm<Eigen::Infinity>() : 0.0;
  // The largest of the ranks' own unknowns (each unknown is one rank's).
  const Vector own = problem.held_rows(u);
  return required_engine(problem).max(own.size() > 0 ? own.lpNorm<Eigen::Infinity>() : 0.0);
}

Vector held_contact_transpose_rows(const ContactProblem& problem, const Vector& v) {
  const SparseMatrix& N = problem.contact.N;
  if (!problem.partitioned()) return N.transpose() * v;
  const Index first = problem.first_row(), end = problem.end_row();
  Vector rows = Vector::Zero(end - first);
  for (Index col = first; col < end; ++col)
    for (SparseMatrix::InnerIterator it(N, col); it; ++it)
      rows(col - first) += it.value() * v(it.row());
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

bool distributed_path(const ContactProblem& problem, const ContactSolverOptions& options) {
  return distributed_path(problem.engine, options);
}

bool distributed_path(const DistributedEngine* engine, const ContactSolverOptions& options) {
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

std::vector<Index> partition_of(const ContactProblem& problem, int ranks) {
  if (problem.partitioned()) {
    if (static_cast<int>(problem.row_starts.size()) != ranks + 1)
      throw InputError(fmt::format("a problem partitioned for {} ranks, solved on {}",
                                   problem.row_starts.size() - 1, ranks));
    return problem.row_starts;
  }
  return row_partition(problem.A.rows(), ranks, problem.node_of_unknown, problem.contact.N);
}

}  // namespace signorini

#include "signorini/petsc/petsc_engine.hpp"

#include <fmt/format.h>
#include <petscsys.h>

#include <cstdlib>

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_active_set_solver.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/petsc_newton_space.hpp"

namespace signorini {

PetscEngine::PetscEngine() {
  petsc::check(PetscInitialize(nullptr, nullptr, nullptr, nullptr), "initialisation");
  // Errors come back as codes that petsc::check turns into one-line exceptions; PETSc's own
  // handler would print a traceback on every rank first.
  petsc::check(PetscPushErrorHandler(PetscIgnoreErrorHandler, nullptr), "error handler");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &size_);
  set_distributed_engine(this);
}

PetscEngine::~PetscEngine() {
  set_distributed_engine(nullptr);
  PetscPopErrorHandler();
  PetscFinalize();
}

std::string PetscEngine::description() const {
  return fmt::format("PETSc {}.{}.{} on {} MPI rank{}", PETSC_VERSION_MAJOR, PETSC_VERSION_MINOR,
                     PETSC_VERSION_SUBMINOR, size_, size_ == 1 ? "" : "s");
}

std::unique_ptr<DistributedNewtonSpace> PetscEngine::newton_space(
    const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
    TimingTable& timings) {
  return std::make_unique<PetscNewtonSpace>(problem, options, x0, timings, PETSC_COMM_WORLD);
}

std::unique_ptr<DistributedActiveSetSolver> PetscEngine::active_set_solver(
    const ContactProblem& problem, const ContactSolverOptions& options, const Vector& x0,
    TimingTable& timings) {
  return std::make_unique<PetscActiveSetSolver>(problem, options, x0, timings, PETSC_COMM_WORLD);
}

void PetscEngine::sum(double* values, Index count) const {
  if (count > 0)
    MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_SUM,
                  PETSC_COMM_WORLD);
}

bool PetscEngine::any(bool flag) const {
  int local = flag ? 1 : 0, global = 0;
  MPI_Allreduce(&local, &global, 1, MPI_INT, MPI_LOR, PETSC_COMM_WORLD);
  return global != 0;
}

void PetscEngine::abort(int status) const {
  MPI_Abort(PETSC_COMM_WORLD, status);
  std::exit(status);  // not reached: MPI_Abort ends the process
}

}  // namespace signorini

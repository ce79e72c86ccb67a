// signorini-mpi: the tool (tool.cpp) with the PETSc engine registered, so that a solve runs
// distributed over the MPI ranks that mpirun started (docs/distributed.md). `mpirun -n 4
// signorini solve ...` re-executes signorini as this program (mpi_handover.hpp); it may also be
// started by name.

#include <fmt/format.h>

#include <cstdio>
#include <exception>

#include "commands.hpp"
#include "process_tuning.hpp"
#include "signorini/petsc/petsc_engine.hpp"

int main(int argc, char** argv) {
  // Before MPI starts: the tuning re-executes the program (process_tuning.hpp).
  signorini::app::tune_process(argc, argv);
  try {
    signorini::PetscEngine engine;
    // Only rank 0 prints and writes; the others' standard output goes nowhere, their errors
    // still reach stderr (tool.cpp).
    if (engine.rank() != 0 && std::freopen("/dev/null", "w", stdout) == nullptr) return 1;
    return signorini::app::run_tool(argc, argv, &engine);
  } catch (const std::exception& e) {
    fmt::print(stderr, "signorini: error: {}\n", e.what());
    return 1;
  }
}

// The main() of signorini_mpi_tests, run by CTest under mpirun on 1, 2 and 4 ranks
// (tests/CMakeLists.txt): MPI and PETSc through the engine, then GoogleTest on every rank. Only
// rank 0 prints; a failure on any rank makes its exit status, and so mpirun's, non-zero.

#include <gtest/gtest.h>

#include <cstdio>

#include "mpi_test_problems.hpp"
#include "signorini/petsc/petsc_engine.hpp"

namespace {
signorini::DistributedEngine* the_engine = nullptr;
}  // namespace

signorini::DistributedEngine& signorini::testing::mpi_engine() {
  return *the_engine;
}

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  signorini::PetscEngine engine;
  the_engine = &engine;
  if (engine.rank() != 0 && std::freopen("/dev/null", "w", stdout) == nullptr) return 1;
  const int status = RUN_ALL_TESTS();
  // Every rank's verdict: a test that failed on one rank fails the run on all.
  return engine.any(status != 0) ? 1 : 0;
}

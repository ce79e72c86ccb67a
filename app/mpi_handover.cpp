#include "mpi_handover.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace signorini::app {

namespace {

// The number of ranks an MPI launcher says it started (0: not started by one).
int launched_ranks() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const char* value = std::getenv(name);
    if (value != nullptr && *value != '\0') return std::max(1, std::atoi(value));
  }
  return std::getenv("PMIX_RANK") != nullptr ? 1 : 0;
}

}  // namespace

void hand_over_to_mpi_tool(char** argv) {
  const int ranks = launched_ranks();
  if (ranks == 0) return;
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error) return;
  if (self.filename() == "signorini-mpi") return;
  const std::filesystem::path mpi_tool = self.parent_path() / "signorini-mpi";
  if (std::filesystem::exists(mpi_tool, error)) {
    argv[0] = const_cast<char*>(mpi_tool.c_str());
    execv(mpi_tool.c_str(), argv);
    // execv returns only on failure: say so below as for a missing program.
  }
  const char* rank = std::getenv("OMPI_COMM_WORLD_RANK");
  if (rank == nullptr) rank = std::getenv("PMIX_RANK");
  if (rank == nullptr) rank = std::getenv("PMI_RANK");
  if (ranks > 1) {
    if (rank != nullptr && std::atoi(rank) != 0) std::exit(2);  // rank 0 says it
    fmt::print(stderr,
               "signorini: error: started by an MPI launcher on {} ranks, but {} has no "
               "signorini-mpi beside it (a build without PETSc: install petsc-dev and build "
               "again; docs/distributed.md)\n",
               ranks, self.string());
    std::exit(2);
  }
}

}  // namespace signorini::app

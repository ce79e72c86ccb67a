// `signorini --version`: what this build contains, so that a bug report says which backends ran.

#include <fmt/format.h>

#include <Eigen/Core>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "commands.hpp"
#include "signorini/backend/cuda_backend.hpp"
#include "signorini/config.hpp"
#include "signorini/linalg/cholmod_solver.hpp"

namespace signorini::app {

std::string version_text() {
  std::string s = fmt::format("signorini {}\n", SIGNORINI_VERSION);
  s += "backends:\n";
  s += fmt::format("  CHOLMOD: {}\n", cholmod_version());
  s += fmt::format("  Eigen: {}.{}.{}\n", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION,
                   EIGEN_MINOR_VERSION);
#ifdef _OPENMP
  s +=
      fmt::format("  OpenMP: yes (version {}, up to {} threads)\n", _OPENMP, omp_get_max_threads());
#else
  s += "  OpenMP: no\n";
#endif
  const CudaReport cuda = cuda_report();
  if (!cuda.built) {
    s += "  CUDA: not built\n";
  } else {
    s += fmt::format("  CUDA: built with toolkit {}, driver {}\n", cuda.toolkit_version,
                     cuda.driver_version.empty() ? "none" : cuda.driver_version);
    for (const GpuInfo& g : cuda.gpus)
      s += fmt::format("    GPU {}: {} (sm_{}{}, {:.1f} GiB, {} multiprocessors)\n", g.ordinal,
                       g.name, g.major, g.minor, static_cast<double>(g.total_memory) / 1073741824.0,
                       g.multiprocessors);
    if (cuda.gpus.empty()) s += fmt::format("    no usable GPU: {}\n", cuda.problem);
  }
  // The distributed engine lives in signorini-mpi (docs/distributed.md); this program says
  // whether the build made it, and which PETSc.
#ifdef SIGNORINI_PETSC_VERSION
  s += fmt::format("  PETSc: {} (signorini-mpi; mpirun -n N signorini solve ...)\n",
                   SIGNORINI_PETSC_VERSION);
#else
  s += "  PETSc: not built\n";
#endif
  return s;
}

}  // namespace signorini::app

// `signorini --version`: what this build contains, so that a bug report says which backends ran.

#include <fmt/format.h>

#include <Eigen/Core>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "commands.hpp"
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
  s += "  CUDA: not built\n";
  s += "  PETSc: not built\n";
  return s;
}

}  // namespace signorini::app

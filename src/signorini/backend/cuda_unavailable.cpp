// The CUDA backend's entry points in a build without CUDA: they say so (the real ones are in
// cuda/cuda_backend.cpp, compiled only when the build has CUDA).

#include "signorini/config.hpp"

#ifndef SIGNORINI_HAVE_CUDA

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

CudaReport cuda_report() {
  CudaReport report;
  report.built = false;
  report.problem =
      "the CUDA backend was not built (no CUDA toolkit found at configure time; see docs/gpu.md)";
  return report;
}

std::unique_ptr<Backend> make_cuda_backend(int /*ordinal*/) {
  throw InputError(
      "solver.device = \"cuda\": this signorini was built without CUDA (reconfigure with the CUDA "
      "toolkit installed; see docs/gpu.md)");
}

std::vector<std::string> load_cuda_libraries() {
  throw InputError("this signorini was built without CUDA: there are no CUDA libraries to load");
}

}  // namespace signorini

#endif  // SIGNORINI_HAVE_CUDA

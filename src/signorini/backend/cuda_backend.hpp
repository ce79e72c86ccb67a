#pragma once
// The CUDA backend: what was built, which GPUs are present, and the factory. These functions
// exist in every build; without CUDA (SIGNORINI_HAVE_CUDA undefined) they report "not built" and
// make_cuda_backend() throws InputError saying so.

#include <memory>
#include <string>
#include <vector>

#include "signorini/backend/backend.hpp"

namespace signorini {

struct GpuInfo {
  int ordinal = 0;
  std::string name;              ///< "NVIDIA H100 80GB HBM3"
  int major = 0, minor = 0;      ///< compute capability
  std::size_t total_memory = 0;  ///< bytes
  int multiprocessors = 0;
};

struct CudaReport {
  bool built = false;           ///< compiled with the CUDA backend
  std::string toolkit_version;  ///< "13.0" (compile time) when built
  std::string driver_version;   ///< "13.0" from the driver, empty if no driver
  std::vector<GpuInfo> gpus;    ///< empty if no usable GPU
  std::string problem;          ///< why no GPU is usable ("no CUDA-capable device is detected")
};

/// Never throws: queries the runtime when built.
CudaReport cuda_report();

/// A backend on GPU `ordinal`. Throws InputError if CUDA was not built or no GPU is usable
/// (the message says which and how to get one), NumericalError on a CUDA failure.
std::unique_ptr<Backend> make_cuda_backend(int ordinal = 0);

/// Opens cuBLAS and cuSPARSE as a GPU solve does when it starts (they are not loaded before:
/// backend/cuda/cuda_libraries.hpp) and returns the files they were loaded from. Throws
/// InputError if CUDA was not built or a library or one of its functions is missing. Needs no
/// GPU: for tests and diagnostics.
std::vector<std::string> load_cuda_libraries();

}  // namespace signorini

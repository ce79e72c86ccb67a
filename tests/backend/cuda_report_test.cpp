// cuda_report() and make_cuda_backend() agree with the build and the machine, with or without
// CUDA and a GPU (the kernels themselves are tested in cuda_backend_gpu_test.cpp).

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/config.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

/// The message of the InputError that make_cuda_backend(ordinal) throws ("" if none).
std::string input_error_of(int ordinal) {
  try {
    (void)make_cuda_backend(ordinal);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CudaReport, AgreesWithTheBuild) {
  const CudaReport report = cuda_report();
#ifdef SIGNORINI_HAVE_CUDA
  EXPECT_TRUE(report.built);
  EXPECT_FALSE(report.toolkit_version.empty());
#else
  EXPECT_FALSE(report.built);
  EXPECT_TRUE(report.gpus.empty());
#endif
  if (report.gpus.empty()) {
    EXPECT_FALSE(report.problem.empty());
  }
  std::set<int> ordinals;
  for (const GpuInfo& gpu : report.gpus) {
    EXPECT_FALSE(gpu.name.empty());
    EXPECT_GE(gpu.major, 1);
    EXPECT_GT(gpu.total_memory, 0U);
    EXPECT_GT(gpu.multiprocessors, 0);
    EXPECT_TRUE(ordinals.insert(gpu.ordinal).second) << "GPU " << gpu.ordinal << " listed twice";
  }
}

TEST(CudaReport, MakeCudaBackendSaysWhyThereIsNoGpu) {
  const CudaReport report = cuda_report();
  if (!report.built) {
    const std::string message = input_error_of(0);
    EXPECT_NE(message.find("built without CUDA"), std::string::npos) << message;
    EXPECT_NE(message.find("solver.device"), std::string::npos) << message;
  } else if (report.gpus.empty()) {
    const std::string message = input_error_of(0);
    EXPECT_NE(message.find("no usable CUDA GPU"), std::string::npos) << message;
    EXPECT_NE(message.find(report.problem), std::string::npos) << message;
  } else {
    // A GPU is there: making a backend on it is for the gpu tests; a GPU that is not there is
    // still an InputError.
    const std::string message = input_error_of(1000);
    EXPECT_NE(message.find("no usable CUDA GPU"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace signorini

// cuBLAS and cuSPARSE are opened when a GPU solve starts, not when the program does: the tool
// does not link them (its start costs no 540 MB of cuBLASLt), and where CUDA was built, both
// load and every function the backend calls resolves, GPU or not.

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <memory>
#include <string>

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

std::string output_of(const std::string& command) {
  std::string out;
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(::popen(command.c_str(), "r"), ::pclose);
  if (!pipe) return out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), static_cast<int>(buffer.size()), pipe.get()) != nullptr)
    out += buffer.data();
  return out;
}

TEST(CudaLibraries, TheToolDoesNotLinkThem) {
  const std::string libraries = output_of(std::string("ldd '") + SIGNORINI_APP_PATH + "' 2>&1");
  ASSERT_NE(libraries.find("libc.so"), std::string::npos) << libraries;  // ldd worked
  EXPECT_EQ(libraries.find("libcublas"), std::string::npos) << libraries;
  EXPECT_EQ(libraries.find("libcusparse"), std::string::npos) << libraries;
}

TEST(CudaLibraries, LoadAndResolveWhereCudaWasBuilt) {
  if (!cuda_report().built) {
    EXPECT_THROW((void)load_cuda_libraries(), InputError);
    GTEST_SKIP() << "built without CUDA";
  }
  const std::vector<std::string> paths = load_cuda_libraries();  // throws if anything is missing
  ASSERT_EQ(paths.size(), 2U);
  EXPECT_NE(paths[0].find("libcublas.so"), std::string::npos) << paths[0];
  EXPECT_NE(paths[1].find("libcusparse.so"), std::string::npos) << paths[1];
  EXPECT_EQ(load_cuda_libraries(), paths);  // loaded once
}

}  // namespace
}  // namespace signorini

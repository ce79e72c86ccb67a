#include "signorini/backend/cuda/cuda_libraries.hpp"

#include <dlfcn.h>
#include <fmt/format.h>
#include <link.h>

#include "signorini/core/error.hpp"

// The sonames and the folder of the toolkit this was built with (src/CMakeLists.txt).
#ifndef SIGNORINI_CUBLAS_SONAME
#define SIGNORINI_CUBLAS_SONAME "libcublas.so"
#endif
#ifndef SIGNORINI_CUSPARSE_SONAME
#define SIGNORINI_CUSPARSE_SONAME "libcusparse.so"
#endif
#ifndef SIGNORINI_CUDA_LIBRARY_DIR
#define SIGNORINI_CUDA_LIBRARY_DIR ""
#endif

// The symbol a name of cublas_v2.h stands for ("cublasCreate" -> "cublasCreate_v2").
#define SIGNORINI_SYMBOL_TEXT(name) #name
#define SIGNORINI_SYMBOL(name) SIGNORINI_SYMBOL_TEXT(name)

namespace signorini::cuda {

namespace {

// dlopen by soname (the library path, LD_LIBRARY_PATH, the executable's run path), then from the
// toolkit's folder; the reasons of both failures if neither works.
void* open_library(const std::string& soname) {
  void* handle = ::dlopen(soname.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (handle != nullptr) return handle;
  std::string reason = ::dlerror();
  const std::string folder = SIGNORINI_CUDA_LIBRARY_DIR;
  if (!folder.empty()) {
    const std::string path = folder + "/" + soname;
    handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle != nullptr) return handle;
    reason += "; " + std::string(::dlerror());
  }
  throw InputError(fmt::format(
      "the CUDA backend needs {} (of the CUDA toolkit it was built with), which cannot be "
      "loaded: {}; put the toolkit's library folder on LD_LIBRARY_PATH",
      soname, reason));
}

std::string path_of(void* handle) {
  const link_map* map = nullptr;
  if (::dlinfo(handle, RTLD_DI_LINKMAP, &map) == 0 && map != nullptr && map->l_name != nullptr)
    return map->l_name;
  return {};
}

template <class Function>
void resolve(void* handle, const char* library, const char* symbol, Function& target) {
  void* address = ::dlsym(handle, symbol);
  if (address == nullptr)
    throw InputError(
        fmt::format("{} has no function {}: is it of another CUDA version?", library, symbol));
  target = reinterpret_cast<Function>(address);
}

CudaLibraries load() {
  CudaLibraries libs;
  void* cublas = open_library(SIGNORINI_CUBLAS_SONAME);
  void* cusparse = open_library(SIGNORINI_CUSPARSE_SONAME);
  libs.cublas_path = path_of(cublas);
  libs.cusparse_path = path_of(cusparse);
#define SIGNORINI_RESOLVE(member, function) \
  resolve(handle, library, SIGNORINI_SYMBOL(function), table.member);
  {
    void* handle = cublas;
    const char* library = SIGNORINI_CUBLAS_SONAME;
    CublasFunctions& table = libs.cublas;
    SIGNORINI_CUBLAS_FUNCTIONS(SIGNORINI_RESOLVE)
  }
  {
    void* handle = cusparse;
    const char* library = SIGNORINI_CUSPARSE_SONAME;
    CusparseFunctions& table = libs.cusparse;
    SIGNORINI_CUSPARSE_FUNCTIONS(SIGNORINI_RESOLVE)
  }
#undef SIGNORINI_RESOLVE
  return libs;  // the handles stay open for the life of the process
}

}  // namespace

const CudaLibraries& cuda_libraries() {
  // Initialised once, thread-safely; if load() throws, the next call tries again and reports it.
  static const CudaLibraries libraries = load();
  return libraries;
}

}  // namespace signorini::cuda

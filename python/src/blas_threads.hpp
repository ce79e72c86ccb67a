#pragma once
// OpenBLAS on one thread while the library works, as the tool runs (app/process_tuning.cpp sets
// OPENBLAS_NUM_THREADS=1): the library's own threads (OpenMP) do the parallel work, BLAS threads
// on top of them only compete for the cores, and the sums of a threaded BLAS come in another
// order, so that a solve from Python would differ from the tool's in the last bits. numpy in the
// same process shares the OpenBLAS library: its setting is put back afterwards. Found at run time
// (dlsym): another BLAS is left alone.

#include <dlfcn.h>

namespace signorini::python {

class SingleThreadedBlas {
 public:
  SingleThreadedBlas() {
    static const auto set =
        reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
    static const auto get =
        reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
    if (set == nullptr || get == nullptr) return;
    set_ = set;
    saved_ = get();
    if (saved_ != 1) set_(1);
  }
  ~SingleThreadedBlas() {
    if (set_ != nullptr && saved_ != 1) set_(saved_);
  }
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  void (*set_)(int) = nullptr;
  int saved_ = 1;
};

}  // namespace signorini::python

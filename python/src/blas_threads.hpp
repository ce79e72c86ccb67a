#pragma once
// OpenBLAS on one thread while the library works, as the tool runs (app/process_tuning.cpp sets
// OPENBLAS_NUM_THREADS=1): the library's own threads (OpenMP) do the parallel work, BLAS threads
// on top of them only compete for the cores, and the sums of a threaded BLAS come in another
// order, so that a solve from Python would differ from the tool's in the last bits. numpy in the
// same process shares the OpenBLAS library: its setting is put back afterwards. Found at run time
// (dlsym): another BLAS is left alone.

#include <dlfcn.h>

#include <mutex>

namespace signorini::python {

/// While one exists (in any thread: solves in several threads count together), OpenBLAS runs on
/// one thread; the last one to go puts back the number it found.
class SingleThreadedBlas {
 public:
  SingleThreadedBlas() {
    const Api& api = openblas();
    if (api.set == nullptr) return;
    const std::lock_guard lock(state().mutex);
    if (state().users++ == 0) {
      state().saved = api.get();
      if (state().saved != 1) api.set(1);
    }
  }
  ~SingleThreadedBlas() {
    const Api& api = openblas();
    if (api.set == nullptr) return;
    const std::lock_guard lock(state().mutex);
    if (--state().users == 0 && state().saved != 1) api.set(state().saved);
  }
  SingleThreadedBlas(const SingleThreadedBlas&) = delete;
  SingleThreadedBlas& operator=(const SingleThreadedBlas&) = delete;

 private:
  struct Api {
    void (*set)(int) = nullptr;
    int (*get)() = nullptr;
  };
  struct State {
    std::mutex mutex;
    int users = 0;
    int saved = 1;
  };
  static const Api& openblas() {
    static const Api api = [] {
      Api a;
      a.set = reinterpret_cast<void (*)(int)>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads"));
      a.get = reinterpret_cast<int (*)()>(dlsym(RTLD_DEFAULT, "openblas_get_num_threads"));
      if (a.get == nullptr) a.set = nullptr;
      return a;
    }();
    return api;
  }
  static State& state() {
    static State s;
    return s;
  }
};

}  // namespace signorini::python

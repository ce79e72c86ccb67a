#include "model_loading.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "signorini/core/error.hpp"

namespace signorini::app {

Model build_model_for(const LoadedProblem& loaded) {
  try {
    return build_model(loaded.spec);
  } catch (const InputError& e) {
    throw InputError(loaded.path + ": " + e.what());
  }
}

void print_warnings(const LoadedProblem& loaded) {
  std::fflush(stdout);  // in order with what was printed before, on a shared terminal
  for (const std::string& w : loaded.warnings) fmt::print(stderr, "signorini: warning: {}\n", w);
}

}  // namespace signorini::app

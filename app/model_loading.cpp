#include "model_loading.hpp"

#include <fmt/format.h>

#include <cstdio>

#include "signorini/core/error.hpp"

namespace signorini::app {

Model build_model_for(const LoadedProblem& loaded, DistributedEngine* engine) {
  try {
    return build_model(loaded.spec, engine);
  } catch (const InputError& e) {
    throw InputError(loaded.path + ": " + e.what());
  }
}

std::vector<std::string> model_warnings(const LoadedProblem& loaded, const Model& model) {
  std::vector<std::string> out;
  for (const std::string& w : mesh_warnings(loaded.spec, model.mesh))
    out.push_back(loaded.path + ": " + w);
  return out;
}

void print_warnings(const std::vector<std::string>& warnings) {
  std::fflush(stdout);
  for (const std::string& w : warnings) fmt::print(stderr, "signorini: warning: {}\n", w);
}

void print_warnings(const LoadedProblem& loaded) {
  std::fflush(stdout);  // in order with what was printed before, on a shared terminal
  for (const std::string& w : loaded.warnings) fmt::print(stderr, "signorini: warning: {}\n", w);
}

}  // namespace signorini::app

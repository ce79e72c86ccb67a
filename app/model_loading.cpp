#include "model_loading.hpp"

#include "signorini/core/error.hpp"

namespace signorini::app {

Model build_model_for(const LoadedProblem& loaded) {
  try {
    return build_model(loaded.spec);
  } catch (const InputError& e) {
    throw InputError(loaded.path + ": " + e.what());
  }
}

}  // namespace signorini::app

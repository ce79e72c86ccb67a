#include "signorini/petsc/petsc_check.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini::petsc {

void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw NumericalError(
      fmt::format("PETSc: {}: {} (error {})", what, text != nullptr ? text : "?", code));
}

}  // namespace signorini::petsc

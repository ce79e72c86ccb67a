#include "signorini/petsc/petsc_check.hpp"

#include <fmt/format.h>

#include <string>
#include <string_view>

#include "signorini/core/error.hpp"

namespace signorini::petsc {

namespace {

// Where the last error began, on this thread: PETSc calls the handler first where the error is
// raised (PETSC_ERROR_INITIAL) and again in each function that passes it up.
struct ErrorOrigin {
  std::string function;
  std::string message;
};
thread_local ErrorOrigin last_error;

}  // namespace

PetscErrorCode recording_error_handler(MPI_Comm /*comm*/, int /*line*/, const char* function,
                                       const char* /*file*/, PetscErrorCode code,
                                       PetscErrorType type, const char* message,
                                       void* /*context*/) {
  if (type == PETSC_ERROR_INITIAL) {
    last_error.function = function != nullptr ? function : "";
    last_error.message = message != nullptr ? message : "";
  }
  return code;
}

void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  std::string reason = text != nullptr ? text : "";
  // A failed allocation (PetscMallocA, PetscMallocAlign) comes back with a code that has no
  // text (seen on a rank under ulimit -v): say what it is.
  if (code == PETSC_ERR_MEM || std::string_view(last_error.function).starts_with("PetscMalloc"))
    reason = "out of memory";
  else if (reason.empty() && !last_error.function.empty())
    reason = fmt::format("raised in {}{}", last_error.function,
                         last_error.message.empty() ? "" : ": " + last_error.message);
  if (reason.empty()) reason = "?";
  last_error = {};
  throw NumericalError(fmt::format("PETSc: {}: {} (error {})", what, reason, code));
}

}  // namespace signorini::petsc

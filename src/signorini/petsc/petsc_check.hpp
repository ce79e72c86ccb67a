#pragma once
// PETSc's error codes as exceptions: a failed call throws NumericalError with PETSc's own text,
// so that the tool reports it in one line like any other numerical failure.

#include <petscsys.h>

namespace signorini::petsc {

/// Throws NumericalError("PETSc: <what>: <PETSc's message>") when `code` is an error. Where
/// PETSc has no text for the code, the message says where the error began (as
/// recording_error_handler saw it), and "out of memory" where that was one of PETSc's
/// allocations.
void check(PetscErrorCode code, const char* what);

/// PETSc's error handler for signorini (PetscPushErrorHandler): prints nothing, so that an error
/// becomes one line of the tool's and not a traceback on every rank, and keeps where the last
/// error began (its function and message) for check.
PetscErrorCode recording_error_handler(MPI_Comm comm, int line, const char* function,
                                       const char* file, PetscErrorCode code, PetscErrorType type,
                                       const char* message, void* context);

}  // namespace signorini::petsc

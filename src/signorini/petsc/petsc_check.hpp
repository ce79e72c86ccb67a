#pragma once
// PETSc's error codes as exceptions: a failed call throws NumericalError with PETSc's own text,
// so that the tool reports it in one line like any other numerical failure.

#include <petscsys.h>

namespace signorini::petsc {

/// Throws NumericalError("PETSc: <what>: <PETSc's message>") when `code` is an error.
void check(PetscErrorCode code, const char* what);

}  // namespace signorini::petsc

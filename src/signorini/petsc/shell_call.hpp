#pragma once
// A MATSHELL operation's body: the shell's context, and a C++ exception turned into a PETSc
// error (which PETSc then reports up its call stack), for the shells of this engine
// (threaded_product, corrected_transfer, upper_block_operator).

#include <petscmat.h>

#include <exception>

namespace signorini::petsc {

template <class Context, class Body>
PetscErrorCode shell_call(Mat shell, const Body& body) {
  Context* context = nullptr;
  PetscCall(MatShellGetContext(shell, &context));
  try {
    body(*context);
  } catch (const std::exception& e) {
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_LIB, "%s", e.what());
  }
  return 0;
}

/// A shell's MatMult and MatMultAdd from one product of its context, `Apply(context, x, y, w,
/// add)`: w = M x, or w = y + M x (w may be y).
template <class Context, void (*Apply)(const Context&, Vec, Vec, Vec, bool)>
struct ShellProducts {
  static PetscErrorCode multiply(Mat shell, Vec x, Vec y) {
    return shell_call<Context>(shell, [&](const Context& c) { Apply(c, x, y, y, false); });
  }
  static PetscErrorCode multiply_add(Mat shell, Vec x, Vec y, Vec w) {
    return shell_call<Context>(shell, [&](const Context& c) { Apply(c, x, y, w, true); });
  }
};

}  // namespace signorini::petsc

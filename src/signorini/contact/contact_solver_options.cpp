#include "signorini/contact/contact_solver_options.hpp"

#include <fmt/format.h>

#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {
std::string text(double v) {
  return fmt::format("{:g}", v);
}
std::string text(int v) {
  return std::to_string(v);
}

template <class T>
void require(bool ok, const std::string& field, T value, const std::string& expected) {
  if (!ok) throw InputError("solver." + field + " = " + text(value) + ": expected " + expected);
}
bool positive(double v) {
  return std::isfinite(v) && v > 0.0;
}
}  // namespace

bool uses_backend_path(const ContactSolverOptions& o) {
  return o.device == DeviceKind::Cuda || (o.linear.type == LinearSolverType::ConjugateGradient &&
                                          o.linear.preconditioner == PreconditionerType::Multigrid);
}

void validate(const ContactSolverOptions& o) {
  require(positive(o.r), "r", o.r, "a positive number");
  require(positive(o.uzawa_tolerance), "uzawa_tolerance", o.uzawa_tolerance, "a positive number");
  require(positive(o.gnm_tolerance), "gnm_tolerance", o.gnm_tolerance, "a positive number");
  require(o.max_uzawa_iterations >= 1, "max_uzawa_iterations", o.max_uzawa_iterations, ">= 1");
  require(o.max_gnm_iterations >= 1, "max_gnm_iterations", o.max_gnm_iterations, ">= 1");
  require(positive(o.armijo_sigma) && o.armijo_sigma < 0.5, "armijo_sigma", o.armijo_sigma,
          "a number in (0, 0.5)");
  require(o.max_armijo_halvings >= 1, "max_armijo_halvings", o.max_armijo_halvings, ">= 1");
  require(std::isfinite(o.classical_step) && o.classical_step >= 0.0, "classical_step",
          o.classical_step, "a number >= 0 (0: automatic)");
  require(o.max_classical_iterations >= 1, "max_classical_iterations", o.max_classical_iterations,
          ">= 1");
  require(o.max_newton_iterations >= 1, "max_newton_iterations", o.max_newton_iterations, ">= 1");
  validate(o.linear);
  // The backend path (docs/gpu.md) runs the paper's method with conjugate gradients only.
  const bool backend_path = uses_backend_path(o);
  if (o.device == DeviceKind::Cuda && o.linear.type != LinearSolverType::ConjugateGradient)
    throw InputError(fmt::format(
        "solver.device = \"cuda\" with solver.linear.type = \"{}\": the GPU solver is "
        "iterative; set solver.linear.type = \"cg\" (and solver.linear.preconditioner = "
        "\"multigrid\" for speed)",
        enum_to_string(kLinearSolverTypeNames, o.linear.type)));
  if (backend_path && o.method != ContactMethod::UzawaGnm)
    throw InputError(fmt::format("solver.method = \"{}\": the {} runs only \"uzawa_gnm\"",
                                 enum_to_string(kContactMethodNames, o.method),
                                 o.device == DeviceKind::Cuda
                                     ? "GPU solver (solver.device = \"cuda\")"
                                     : "multigrid preconditioner"));
}

}  // namespace signorini

#include "signorini/contact/contact_solver_options.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "signorini/contact/contact_problem.hpp"
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
  if (o.r) require(positive(*o.r), "r", *o.r, "a positive number (or no r: automatic)");
  require(positive(o.auto_r_factor), "auto_r_factor", o.auto_r_factor, "a positive number");
  require(positive(o.kkt_tolerance) && o.kkt_tolerance < 1.0, "kkt_tolerance", o.kkt_tolerance,
          "a number in (0, 1)");
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

double automatic_r(const ContactProblem& p, double factor) {
  // (N A N^T)_jj = nu_j^T A_jj nu_j over node j's free dofs is the normal stiffness of contact
  // node j (force per length); divided by the node's share h_j of the boundary it is a stiffness
  // per area, the units of r (stress per length). So r scales with E / h in every consistent set
  // of units, and r h_j / (N A N^T)_jj = factor: the penalty is as stiff as the body at the node,
  // whatever the units and the mesh size (method.md section 7).
  const ContactSet& c = p.contact;
  const SparseMatrix Nt = c.N.transpose();  // column j = row j of N
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(c.size()));
  for (Index j = 0; j < c.size(); ++j) {
    if (!c.movable[static_cast<std::size_t>(j)] || !(c.weights(j) > 0.0)) continue;
    double stiffness = 0.0;
    for (SparseMatrix::InnerIterator a(Nt, j); a; ++a)
      for (SparseMatrix::InnerIterator b(Nt, j); b; ++b)
        stiffness += a.value() * p.A.coeff(a.row(), b.row()) * b.value();
    if (stiffness > 0.0) values.push_back(stiffness / c.weights(j));
  }
  if (values.empty())
    throw InputError(
        "solver.r: no contact node has a free normal displacement, so r cannot be chosen "
        "automatically; give solver.r");
  // The median: corner nodes (half weights) and nodes beside a clamp do not decide it.
  const auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return factor * *mid;
}

double augmentation_parameter(const ContactProblem& problem, const ContactSolverOptions& options) {
  return options.r ? *options.r : automatic_r(problem, options.auto_r_factor);
}

}  // namespace signorini

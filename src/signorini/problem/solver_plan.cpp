#include "signorini/problem/solver_plan.hpp"

#include <fmt/format.h>

#include "signorini/core/digit_groups.hpp"
#include "signorini/problem/memory_estimate.hpp"

namespace signorini {

namespace {

std::string gigabytes(double bytes) {
  if (bytes >= 1e9) return fmt::format("{:.1f} GB", bytes / 1e9);
  if (bytes >= 1e6) return fmt::format("{:.0f} MB", bytes / 1e6);
  return fmt::format("{:.0f} kB", bytes / 1e3);
}

std::string thousands(Index n) {
  return with_thousands(static_cast<long long>(n));
}

}  // namespace

double estimated_factor_bytes(const ProblemSize& size) {
  // 2D: the peak of a whole solve with CHOLMOD per node (memory_estimate.hpp), factor included.
  return size.dimension == 3
             ? 25e3 * static_cast<double>(size.free_unknowns)
             : estimated_memory_bytes(static_cast<double>(size.nodes), LinearSolverType::Cholmod);
}

SolverPlan plan_solver(const ContactSolverOptions& given, const ProblemSize& size) {
  SolverPlan plan{given, {}};
  ContactSolverOptions& o = plan.options;
  const auto as_configured = [&](const std::string& why) {
    plan.reason = fmt::format("as configured ({})", why);
    return plan;
  };
  if (!given.automatic_path) return as_configured("automatic_path = false");
  if (given.device != DeviceKind::Cpu) return as_configured("a device");
  if (given.linear.type != LinearSolverType::Cholmod)
    return as_configured(fmt::format("linear.type = \"{}\"",
                                     enum_to_string(kLinearSolverTypeNames, given.linear.type)));

  // Classical Uzawa needs one factorisation of A (thousands of steps, each a pair of triangular
  // solves): it has no iterative path; nor has semismooth Newton with friction (a sparse LU of
  // the whole KKT system).
  const bool iterative_allowed =
      given.method == ContactMethod::UzawaGnm ||
      (given.method == ContactMethod::SemismoothNewton && !size.friction);
  const double factor = estimated_factor_bytes(size);
  const bool memory_known = size.memory_bytes > 0.0;
  const auto go_iterative = [&](const std::string& why) {
    o.linear.type = LinearSolverType::ConjugateGradient;
    o.linear.preconditioner = PreconditionerType::Multigrid;
    if (o.inner_tolerance == InnerTolerance::Auto)
      o.inner_tolerance = InnerTolerance::Adaptive;  // inexact Uzawa-GNM: fewer CG iterations
    plan.reason = "iterative, CG with multigrid: " + why;
    return plan;
  };
  if (iterative_allowed && size.dimension == 3 && size.free_unknowns > kIterativeFromUnknowns3D)
    return go_iterative(
        fmt::format("3D with {} free unknowns, above {}, where a sparse factorisation costs more",
                    thousands(size.free_unknowns), thousands(kIterativeFromUnknowns3D)));
  if (iterative_allowed && memory_known && factor > 0.5 * size.memory_bytes)
    return go_iterative(
        fmt::format("a sparse factor of about {} would exceed half of the {} of "
                    "this machine",
                    gigabytes(factor), gigabytes(size.memory_bytes)));
  if (size.friction && (size.dimension == 3 || given.method == ContactMethod::SemismoothNewton)) {
    o.schur_complement = false;
    plan.reason =
        size.dimension == 3
            ? "sparse direct: friction in 3D (condensed, its Newton matrix would be formed and "
              "factorised densely at every GNM step: docs/solvers.md)"
            : "sparse direct: semismooth Newton with friction factorises the full KKT system";
    return plan;
  }
  if (!given.schur_complement) return as_configured("schur_complement = false");
  // With friction the condensed unknowns are every free dof of the contact nodes.
  const double nc = static_cast<double>(size.contact_nodes) * (size.friction ? size.dimension : 1);
  const double dense = kCondensedBytesPerEntry * nc * nc;
  if (memory_known && dense > 0.25 * size.memory_bytes) {
    o.schur_complement = false;
    plan.reason = fmt::format(
        "sparse direct: the condensed matrix of {} contact nodes (about {}) would exceed a "
        "quarter of the {} of this machine",
        thousands(size.contact_nodes), gigabytes(dense), gigabytes(size.memory_bytes));
    return plan;
  }
  plan.reason =
      fmt::format("condensed direct: {} contact nodes{}, a dense matrix of about {}",
                  thousands(size.contact_nodes),
                  size.friction ? " with friction (every free dof of each)" : "", gigabytes(dense));
  return plan;
}

}  // namespace signorini

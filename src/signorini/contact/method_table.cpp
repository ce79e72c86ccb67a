#include "signorini/contact/method_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

using P = SolvePath;
using M = ContactMethod;
// What runs where (method.md; docs/solvers.md). Per row: the path, the method, whether it takes
// the unilateral law, another law of one component, and Tresca's and Coulomb's laws, whether it
// takes rows between bodies, and the function that runs it. The condensed path runs the serial
// methods on the condensed problem (ContactSolver condenses and expands around the row);
// semismooth Newton with friction runs on the sparse direct path instead (table_path). The
// distributed path keeps each contact row on the rank that owns its node's dofs (its Newton
// matrices' node blocks, its projections), so it takes rows against obstacles only. No row:
// refuse() says why.
// clang-format off
constexpr std::array kRows{
    MethodRow{P::Distributed,      M::UzawaGnm,          true, true,  true,  false, solve_uzawa_gnm_distributed},
    MethodRow{P::Distributed,      M::ClassicalUzawa,    true, true,  true,  false, solve_classical_uzawa_distributed},
    MethodRow{P::Distributed,      M::SemismoothNewton,  true, false, false, false, solve_semismooth_newton_distributed},
    MethodRow{P::Backend,          M::UzawaGnm,          true, true,  true,  true,  solve_uzawa_gnm_on_backend},
    MethodRow{P::Backend,          M::SemismoothNewton,  true, false, false, true,  solve_semismooth_newton_on_backend},
    MethodRow{P::CondensedDirect,  M::UzawaGnm,          true, true,  true,  true,  solve_uzawa_gnm},
    MethodRow{P::CondensedDirect,  M::ClassicalUzawa,    true, true,  true,  true,  solve_classical_uzawa},
    MethodRow{P::CondensedDirect,  M::SemismoothNewton,  true, false, false, true,  solve_semismooth_newton},
    MethodRow{P::SparseDirect,     M::UzawaGnm,          true, true,  true,  true,  solve_uzawa_gnm},
    MethodRow{P::SparseDirect,     M::ClassicalUzawa,    true, true,  true,  true,  solve_classical_uzawa},
    MethodRow{P::SparseDirect,     M::SemismoothNewton,  true, false, true,  true,  solve_semismooth_newton},
    MethodRow{P::Iterative,        M::UzawaGnm,          true, true,  true,  true,  solve_uzawa_gnm},
    MethodRow{P::Iterative,        M::ClassicalUzawa,    true, true,  true,  true,  solve_classical_uzawa},
    MethodRow{P::Iterative,        M::SemismoothNewton,  true, false, true,  true,  solve_semismooth_newton},
};
// clang-format on

// Why no row runs this combination, and what to use: the first that applies.
[[noreturn]] void refuse(SolvePath path, ContactMethod method, LawKind kind,
                         std::string_view law_name, const ContactSolverOptions& o,
                         InterfaceKind interface) {
  const std::string method_name(enum_to_string(kContactMethodNames, method));
  const auto runs = [&](const MethodRow& row) {
    return row.path == path && row.method == method && row.takes(kind);
  };
  if (interface == InterfaceKind::BetweenBodies && std::any_of(kRows.begin(), kRows.end(), runs))
    throw InputError(fmt::format(
        "contact between two deformable bodies runs in one process so far, not on the {} path "
        "(its contact rows touch the nodes of both bodies, which may lie on different ranks); "
        "run without mpirun or solver.distributed",
        enum_to_string(kSolvePathNames, path)));
  if (path == P::Backend && method == M::ClassicalUzawa)
    throw InputError(
        fmt::format("solver.method = \"{}\": the {} runs \"uzawa_gnm\" and "
                    "\"semismooth_newton\" only",
                    method_name,
                    o.device == DeviceKind::Cuda ? "GPU solver (solver.device = \"cuda\")"
                                                 : "multigrid preconditioner"));
  if (kind == LawKind::OtherScalar)
    throw InputError(fmt::format(
        "solver.method = \"{}\" solves the unilateral contact law only, not \"{}\"; use "
        "\"uzawa_gnm\"",
        method_name, law_name));
  if (kind == LawKind::Frictional)
    throw InputError(fmt::format(
        "the contact law \"{}\" (friction) with solver.method = \"{}\" runs {}; use "
        "\"uzawa_gnm\"{} there (docs/solvers.md)",
        law_name, method_name,
        path == P::Distributed ? "in one process, not on the distributed path (solver.distributed)"
                               : "on the host's sparse paths, not on the multigrid or GPU path",
        path == P::Distributed ? " or \"classical_uzawa\"" : ""));
  throw InputError(fmt::format("solver.method = \"{}\" does not run on the {} path", method_name,
                               enum_to_string(kSolvePathNames, path)));
}

}  // namespace

LawKind law_kind(const ContactLaw& law) {
  if (law.components() > 1) return LawKind::Frictional;
  return &law == &unilateral_contact_law() ? LawKind::Unilateral : LawKind::OtherScalar;
}

SolvePath table_path(SolvePath planned, ContactMethod method, LawKind kind) {
  if (planned == P::CondensedDirect && method == M::SemismoothNewton && kind == LawKind::Frictional)
    return P::SparseDirect;
  return planned;
}

const MethodRow& method_row(SolvePath path, ContactMethod method, LawKind kind,
                            std::string_view law_name, const ContactSolverOptions& options,
                            InterfaceKind interface) {
  for (const MethodRow& row : kRows)
    if (row.path == path && row.method == method && row.takes(kind) &&
        (interface == InterfaceKind::Obstacle || row.between_bodies))
      return row;
  refuse(path, method, kind, law_name, options, interface);
}

void validate_path(const ContactSolverOptions& options, const DistributedEngine* engine,
                   LawKind kind, std::string_view law_name) {
  // The path as ContactSolver chooses it before its size-based choices, which never make a
  // combination the table refuses (choose_path, contact_solver.cpp).
  const SolvePath path = distributed_path(engine, options) ? SolvePath::Distributed
                         : uses_backend_path(options)      ? SolvePath::Backend
                                                           : SolvePath::SparseDirect;
  (void)method_row(path, options.method, kind, law_name, options);
}

}  // namespace signorini

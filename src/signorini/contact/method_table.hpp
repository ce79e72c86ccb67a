#pragma once
// What runs where, in one table: each way a solve runs is a row (the path × the method × the
// kinds of contact law and of interface it takes) with the function that runs it. ContactSolver
// looks its configuration up here and runs the row's function; a configuration without a row is
// refused, with the reason and what to use instead, by the same lookup (docs/solvers.md). Adding a
// way to run (a method on a new backend, a law on a new path) is adding a row.

#include "signorini/contact/contact_methods.hpp"

namespace signorini {

/// The kinds of contact law the rows tell apart (contact_law.hpp).
enum class LawKind {
  Unilateral,   ///< the paper's frictionless law
  OtherScalar,  ///< another law of one component per node
  Frictional,   ///< Tresca's and Coulomb's laws: d components per node
};
[[nodiscard]] LawKind law_kind(const ContactLaw& law);

/// Runs a method on `problem` from `start`; `multigrid`: the levels of the backend path's
/// preconditioner (may be null).
using MethodRunner = ContactResult (*)(const ContactProblem& problem,
                                       const ContactSolverOptions& options,
                                       const MethodStart& start,
                                       const MultigridHierarchy* multigrid);

struct MethodRow {
  SolvePath path;
  ContactMethod method;
  bool unilateral, other_scalar, frictional;  // the law kinds it takes
  /// Whether it takes rows between bodies (InterfaceKind::BetweenBodies), which touch other
  /// nodes' dofs than their own; every row takes rows against obstacles.
  bool between_bodies;
  MethodRunner run;
  [[nodiscard]] bool takes(LawKind kind) const {
    return kind == LawKind::Unilateral    ? unilateral
           : kind == LawKind::OtherScalar ? other_scalar
                                          : frictional;
  }
};

/// The path a solve of `method` with a law of `kind` takes where `planned` was chosen from the
/// options: the planned one, except where the table sends the combination elsewhere (semismooth
/// Newton with friction factorises the whole KKT system: the sparse direct path instead of the
/// condensed one).
[[nodiscard]] SolvePath table_path(SolvePath planned, ContactMethod method, LawKind kind);

/// The row of the table for this path, method, law and interface; InputError naming the law
/// (`law_name`) and saying what runs there instead where there is none.
[[nodiscard]] const MethodRow& method_row(SolvePath path, ContactMethod method, LawKind kind,
                                          std::string_view law_name,
                                          const ContactSolverOptions& options,
                                          InterfaceKind interface = InterfaceKind::Obstacle);

/// Throws InputError where the options cannot run on the path they take with `engine` (null:
/// none) with a law of `kind` (named `law_name`): the table's check before there is a problem
/// (build_model; with the law once the model has made it). validate() checks the options
/// alone, wherever they are read.
void validate_path(const ContactSolverOptions& options, const DistributedEngine* engine,
                   LawKind kind = LawKind::Unilateral, std::string_view law_name = "unilateral");

}  // namespace signorini

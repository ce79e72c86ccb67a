#pragma once
// The [solver] table of a problem file: every scalar option of ContactSolverOptions, declared
// once (core/option_table.hpp) for the reader, validate(), the effective settings, summary.json
// and the docs. Its [solver.linear] subtable is linalg/linear_solver_option_table.hpp.

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/option_table.hpp"

namespace signorini {

[[nodiscard]] const OptionTable<ContactSolverOptions>& contact_solver_option_table();

}  // namespace signorini

#pragma once
// The [solver.linear] table of a problem file: every option of LinearSolverOptions, declared once
// (core/option_table.hpp) for the reader, the effective settings, summary.json and the docs.

#include "signorini/core/option_table.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

[[nodiscard]] const OptionTable<LinearSolverOptions>& linear_solver_option_table();

}  // namespace signorini

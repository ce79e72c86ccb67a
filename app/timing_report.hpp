#pragma once
// The timing table printed at the end of a run (as deal.II's TimerOutput): where the time went.

#include <string>

#include "signorini/contact/solve_summary.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::app {

/// Columns phase, seconds, percent of the total; the linear-solver phases are indented under
/// "contact solve", which contains them.
std::string timing_report(const Model& model, const SolveSummary& summary);

/// Seconds for a table column: 3 decimals below 100 s, 1 above.
std::string seconds_text(double s);

}  // namespace signorini::app

#pragma once
// The `units` setting of a problem: which consistent set of units its numbers are in, for the
// labels of reports and figures only. The solver needs no units (method.md section 7): lengths
// and stresses in any consistent pair give the same solution, scaled.

#include <string>
#include <vector>

namespace signorini {

/// "LENGTH-STRESS" names: m-Pa, m-kPa, m-MPa, m-GPa, mm-MPa, and the force-unit names mm-N
/// (= mm-MPa: N/mm^2 is MPa) and m-N (= m-Pa).
[[nodiscard]] const std::vector<std::string>& unit_system_names();
[[nodiscard]] bool is_unit_system(const std::string& name);
/// The names, quoted and separated by commas, for messages.
[[nodiscard]] std::string unit_system_choices();

}  // namespace signorini

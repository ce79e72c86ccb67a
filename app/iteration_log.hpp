#pragma once
// The progress records of a contact solve, one per IterationEvent: a line of text for a log, or
// a JSON object for --log-format json (docs/output.md).

#include <nlohmann/json.hpp>
#include <string>

#include "signorini/contact/contact_solver_options.hpp"

namespace signorini::app {

/// Inner (GNM) events:  "  uzawa 3  gnm 2  active 123  residual 1.2e-11  armijo 0"
/// Outer events:        "uzawa 3: ||dl||/||l|| = 4.5e-09, active 123, gnm 2"
/// The outer step is called "newton" for semismooth_newton, and only uzawa_gnm has GNM counts.
std::string iteration_line(ContactMethod method, const IterationEvent& event);

/// {"event": "iteration", "level": "inner" or "outer", "outer": k, "inner": m, "active": ...,
///  "residual": ..., "armijo": ..., "linear_iterations": ...}; the residual is the GNM residual
/// for inner events and ||l^k - l^(k-1)|| / ||l^k|| for outer ones (null if not finite).
nlohmann::json iteration_json(const IterationEvent& event);

}  // namespace signorini::app

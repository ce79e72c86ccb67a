#pragma once
// The progress lines printed while a contact solver runs, one per IterationEvent.

#include <string>

#include "signorini/contact/contact_solver_options.hpp"

namespace signorini::app {

/// Inner (GNM) events:  "  uzawa 3  gnm 2  active 123  residual 1.2e-11  armijo 0"
/// Outer events:        "uzawa 3: ||dl||/||l|| = 4.5e-09, active 123, gnm 2"
/// The outer step is called "newton" for semismooth_newton, and only uzawa_gnm has GNM counts.
std::string iteration_line(ContactMethod method, const IterationEvent& event);

}  // namespace signorini::app

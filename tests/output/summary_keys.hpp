#pragma once
// The keys that summary.json promises (docs/output.md), checked by the io and the app tests.

#include <array>

namespace signorini::testing {

inline constexpr std::array<const char*, 26> kSummaryKeys{"converged",
                                                          "termination",
                                                          "message",
                                                          "method",
                                                          "path",
                                                          "warm_started",
                                                          "M",
                                                          "energy",
                                                          "uzawa_iterations",
                                                          "gnm_iterations",
                                                          "armijo_reductions",
                                                          "active_set_sizes",
                                                          "dual_changes",
                                                          "n_dofs",
                                                          "n_free_dofs",
                                                          "n_contact_nodes",
                                                          "n_active",
                                                          "contact_force",
                                                          "contact_force_vector",
                                                          "kkt",
                                                          "kkt_tolerance",
                                                          "resultants",
                                                          "point_loads",
                                                          "timings",
                                                          "problem",
                                                          "signorini_version"};

}  // namespace signorini::testing

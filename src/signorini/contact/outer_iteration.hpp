#pragma once
// The outer loop shared by every contact method: Uzawa on the modified Lagrangian (13), classical
// Uzawa and the semismooth Newton method. A method supplies one step (from the multipliers l^{k-1}
// to l^k, with its record and whether it converged or failed); the loop keeps the records, reports
// each step to the observer, sets the termination and the message, and says why it stopped at
// the iteration limit.

#include <functional>
#include <optional>
#include <string>

#include "signorini/contact/contact_methods.hpp"

namespace signorini {

/// What one outer step of a method reports.
struct OuterStepOutcome {
  OuterStepRecord record;  ///< complete: counts, dual change, active set size
  Vector l;                ///< l^k; left empty by a step that failed before producing it
  /// Empty: go on; Converged: l is the answer; anything else: stop with that reason (a failure
  /// of the step, GNM's own iteration limit among them).
  std::optional<Termination> stop;
  std::string message;  ///< why it stopped (Converged or a failure)
};

struct OuterLoop {
  int max_steps = 0;
  std::function<OuterStepOutcome(int k, const Vector& l)> step;
  /// The message when max_steps pass without convergence; gets the last record.
  std::function<std::string(const OuterStepRecord& last)> limit_message;
  /// Which steps go to the observer (every step when empty).
  std::function<bool(int k)> report;
};

/// Runs `loop` from l^0 = `l0` (zero for the paper's start, method.md "Conventions"); fills
/// out.l and out.summary's steps, termination and message (not out.u).
void run_outer_loop(const OuterLoop& loop, Vector l0, const ContactSolverOptions& options,
                    ContactResult& out);

/// The message of the Uzawa stopping rule ||l^k - l^(k-1)|| / ||l^k|| < tolerance.
[[nodiscard]] std::string dual_change_message(const OuterStepRecord& rec, double tolerance, int k,
                                              const std::string& steps_name);

}  // namespace signorini

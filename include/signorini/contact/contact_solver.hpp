#pragma once
// Entry point of the contact solvers: solve_contact() validates the options, runs the chosen
// method on the discrete problem (14) and completes the summary with KKT residuals, energies,
// contact force and timings.

#include "signorini/contact/contact_problem.hpp"
#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/solve_summary.hpp"

namespace signorini {

struct ContactResult {
  Vector u;  ///< displacement, free dofs
  Vector l;  ///< contact pressure l_j >= 0 per contact node (l* = -sigma_nu)
  SolveSummary summary;
};

/// Never fails silently: a run that stops short of convergence returns with
/// summary.termination saying why and summary.message giving the residuals. Throws InputError
/// for invalid options and NumericalError if a factorisation fails.
ContactResult solve_contact(const ContactProblem& problem, const ContactSolverOptions& options);

}  // namespace signorini

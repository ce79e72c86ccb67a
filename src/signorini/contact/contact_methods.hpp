#pragma once
// The contact methods themselves (private to the library): solve_contact() picks one and
// completes its summary with KKT residuals, energies and timings.

#include "signorini/contact/contact_solver.hpp"

namespace signorini {

/// ||l_new - l_old||_2 / ||l_new||_2, the paper's Uzawa stopping quantity; 0 if both are zero and
/// +infinity if only l_new is.
double relative_change(const Vector& l_new, const Vector& l_old);

// The methods themselves; solve_contact() calls one and completes its summary.
ContactResult solve_uzawa_gnm(const ContactProblem& problem, const ContactSolverOptions& options);
ContactResult solve_classical_uzawa(const ContactProblem& problem,
                                    const ContactSolverOptions& options);
/// uzawa_gnm with conjugate gradients on a backend (CPU or GPU, docs/gpu.md), used when
/// uses_backend_path(options).
ContactResult solve_uzawa_gnm_on_backend(const ContactProblem& problem,
                                         const ContactSolverOptions& options);
ContactResult solve_semismooth_newton(const ContactProblem& problem,
                                      const ContactSolverOptions& options);

}  // namespace signorini

#pragma once
// The outer loop of the paper's method, Uzawa iterations (13) on the modified Lagrangian (10):
// step (i) minimises Phi for the current multipliers (by GNM, on the host or on a backend),
// step (ii) updates l^{k+1} = (l^k + r ((N x)_j - g_j))_+, until ||l^k - l^{k-1}|| / ||l^k|| is
// below the tolerance (method.md sections 2-4).

#include <functional>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/generalized_newton.hpp"

namespace signorini {

/// Step (i) for Uzawa step k: minimises phi (multipliers set) and returns the GNM record; N x at
/// the minimiser is written to `Nx`.
using UzawaInnerStep = std::function<GnmResult(const ModifiedLagrangian& phi, int k, Vector& Nx)>;

/// Runs (13) from l^0 (zero for the paper's start) with `phi` (whose multipliers it sets); fills
/// out.l and out.summary (steps, termination, message), not out.u.
void run_uzawa_iteration(const ContactSolverOptions& options, ModifiedLagrangian& phi,
                         const UzawaInnerStep& inner, Vector l0, ContactResult& out);

}  // namespace signorini

#pragma once
// The outer loop of the paper's method, Uzawa iterations (13) on the modified Lagrangian (10):
// step (i) minimises Phi for the current multipliers (by GNM, on the host or on a backend),
// step (ii) updates l^{k+1} = (l^k + r ((N x)_j - g_j))_+, until ||l^k - l^{k-1}|| / ||l^k|| is
// below the tolerance (method.md sections 2-4).

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/newton_space.hpp"

namespace signorini {

/// Runs (13) from l^0 (zero for the paper's start) with `phi` (whose multipliers it sets), each
/// step (i) by GNM in `space` (host or backend), which holds x; fills out.l and out.summary
/// (steps, termination, message), not out.u.
void run_uzawa_iteration(const ContactProblem& problem, const ContactSolverOptions& options,
                         ModifiedLagrangian& phi, NewtonSpace& space, Vector l0,
                         ContactResult& out);

/// Whether a solve with the active set S fixed (NewtonSpace::solve_on_active_set) meets the
/// contact conditions to `tolerance`: multipliers on S nonnegative (relative to the largest) and
/// no node off S penetrating (relative to the largest of the gaps and the normal displacements
/// of the contact nodes). The active-set finish's acceptance (docs/solvers.md).
[[nodiscard]] bool contact_conditions_hold(const ContactSet& contact, const ActiveSet& S,
                                           const ActiveSetSolve& solve, double tolerance);

}  // namespace signorini

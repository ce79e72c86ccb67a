#pragma once
// One Newton step of the semismooth Newton method (semismooth_newton_solver.cpp): for a guessed
// active set S, the equality-constrained problem
//   minimise 1/2 x^T A x - b^T x  subject to (N x)_j = g_j for j in S,
// solved exactly, with its multipliers l (l_j = 0 off S: A x - b + N^T diag(h) l = 0) and the
// gap residual (N x - g) of every contact node. The ways to solve it (rotated elimination with a
// sparse factorisation, the Delassus operator of a condensed problem, projected conjugate
// gradients on a backend) are behind this interface, so that one loop serves them all.

#include "signorini/contact/contact_law.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/timing_table.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

class ActiveSetSolver {
 public:
  virtual ~ActiveSetSolver() = default;
  /// Solves the problem of S; returns the linear solver's figures.
  virtual LinearSolveStats solve(const ActiveSet& S, Vector& l, Vector& gap_residual) = 0;
  /// x of the last solve (free dofs, on the host).
  [[nodiscard]] virtual Vector displacement() const = 0;
  /// Factorisations (or preconditioner set-ups) that the last solve() made.
  [[nodiscard]] virtual int last_factorizations() const { return 1; }
  /// Unknowns whose rows the last solve() modified in the factor instead of refactorising.
  [[nodiscard]] virtual int last_factor_updates() const { return 0; }
  /// Whether the steps are solved iteratively, to a tolerance that set_tolerance() may loosen.
  [[nodiscard]] virtual bool iterative() const { return false; }
  /// The relative tolerance of the next solves (0: the solver's own, cg_tolerance).
  virtual void set_tolerance(double /*tolerance*/) {}
  [[nodiscard]] const TimingTable& timings() const { return timings_; }

 protected:
  TimingTable timings_;
};

}  // namespace signorini

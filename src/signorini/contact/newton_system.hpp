#pragma once
// The linear systems of the generalised Newton method (17): H(P) x = rhs with
// H(P) = A + r sum_{j in P} h_j n_j n_j^T for active sets P. Consecutive active sets usually differ
// in a few nodes, so a system is refactorised only when P changes, and both the dense variant (for
// the condensed problems) and the CHOLMOD one (the sparse direct path) update their factor by
// rank-one updates and downdates instead where that is cheaper.

#include <memory>

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/core/error.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

class NewtonSystem {
 public:
  virtual ~NewtonSystem() = default;
  /// Makes H(P) the current matrix (no work if P is the current active set).
  virtual void set_active(const ActiveSet& active) = 0;
  /// The same for any law: a frictionless one is its active set; friction in 2D is the active
  /// rows of N (every D_j diagonal, 0 or 1), updated as an active set; friction's coupled blocks
  /// in 3D go to set_blocks.
  void set_linearization(const Linearization& lin) {
    if (lin.blocks.empty())
      set_active(lin.active);
    else if (!lin.rows.empty())
      set_active(lin.rows);
    else
      set_blocks(lin);
  }
  virtual LinearSolveStats solve(const Vector& rhs, Vector& x) = 0;
  [[nodiscard]] int factorizations() const { return factorizations_; }
  [[nodiscard]] int updates() const { return updates_; }
  [[nodiscard]] virtual const TimingTable& timings() const = 0;

 protected:
  int factorizations_ = 0;  // numeric factorisations so far
  int updates_ = 0;         // rank-one factor updates and downdates so far

  /// H = A + r sum_j h_j N_j^T D_j N_j with friction's blocks D_j (3D: they vary continuously
  /// on sliding nodes), formed and factorised again whenever they change.
  virtual void set_blocks(const Linearization& lin) = 0;
};

/// A sparse system (CHOLMOD or CG, analysed once) for the "cholmod" and "cg" linear solvers, a
/// dense updatable one for "dense".
std::unique_ptr<NewtonSystem> make_newton_system(const ContactProblem& problem,
                                                 const ModifiedLagrangian& phi,
                                                 const LinearSolverOptions& options);

}  // namespace signorini

// Semismooth Newton method on the KKT system of (14), in its primal-dual active set form
// (method.md section 6): for a guessed active set S, impose (N x)_j = g_j on S and l_j = 0 off S,
// solve the equality-constrained problem exactly, and update
//   S <- { j in S : l_j > 0 } u { j not in S : (N x)_j > g_j },
// until S repeats. It uses no penalty parameter, so it checks the Uzawa methods independently.
//
// The constraint (N x)_j = g_j involves the free dofs of node j along nu_j. Each contact node's
// free dofs are rotated by a Householder reflection Q_j whose first column is nu_j restricted to
// them (scaled to unit length, s_j = its norm before scaling); in the rotated unknowns y = Q^T x
// the constraint fixes one unknown, y_{a_j} = g_j / s_j, which is eliminated by replacing its row
// and column with the diagonal: the pattern never changes, so one symbolic analysis serves all.

#include <fmt/format.h>

#include <algorithm>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/modified_lagrangian.hpp"

namespace signorini {

ContactResult solve_semismooth_newton(const ContactProblem& problem,
                                      const ContactSolverOptions& options) {
  ContactResult out;
  SolveSummary& s = out.summary;
  const ContactSet& c = problem.contact;
  const Index n = problem.A.rows();
  const Index nc = c.size();

  // Rotation Q (block diagonal, identity away from contact nodes).
  std::vector<Index> normal_dof(static_cast<std::size_t>(nc), -1);
  Vector scale = Vector::Zero(nc);
  std::vector<bool> in_block(static_cast<std::size_t>(n), false);
  std::vector<Eigen::Triplet<double, int>> qt;
  const SparseMatrix Nt = c.N.transpose();
  for (Index j = 0; j < nc; ++j) {
    if (!c.movable[static_cast<std::size_t>(j)]) continue;
    std::vector<Index> dofs;
    std::vector<double> coef;
    for (SparseMatrix::InnerIterator it(Nt, j); it; ++it) {
      dofs.push_back(it.row());
      coef.push_back(it.value());
    }
    const Eigen::Map<const Vector> cv(coef.data(), static_cast<Index>(coef.size()));
    scale(j) = cv.norm();
    Vector v = cv / scale(j);
    v(0) -= 1.0;  // Householder vector: Q = I - 2 v v^T / (v.v) maps e_1 to cv / |cv|
    const double vv = v.squaredNorm();
    const auto k = static_cast<Index>(dofs.size());
    for (Index a = 0; a < k; ++a) {
      in_block[static_cast<std::size_t>(dofs[static_cast<std::size_t>(a)])] = true;
      for (Index b = 0; b < k; ++b) {
        const double q = (a == b ? 1.0 : 0.0) - (vv > 1e-28 ? 2.0 * v(a) * v(b) / vv : 0.0);
        if (q != 0.0 || a == b)
          qt.emplace_back(static_cast<int>(dofs[static_cast<std::size_t>(a)]),
                          static_cast<int>(dofs[static_cast<std::size_t>(b)]), q);
      }
    }
    normal_dof[static_cast<std::size_t>(j)] = dofs.front();
  }
  for (Index i = 0; i < n; ++i)
    if (!in_block[static_cast<std::size_t>(i)]) qt.emplace_back(static_cast<int>(i), static_cast<int>(i), 1.0);
  SparseMatrix Q(n, n);
  Q.setFromTriplets(qt.begin(), qt.end());
  const SparseMatrix Ar = SparseMatrix(Q.transpose() * problem.A * Q);
  const Vector br = Q.transpose() * problem.b;

  auto solver = make_linear_solver(options.linear);
  solver->analyze(Ar);
  SparseMatrix K = Ar;
  std::vector<bool> fixed(static_cast<std::size_t>(n), false);

  ActiveSet active(static_cast<std::size_t>(nc), false);
  std::vector<ActiveSet> history;
  Vector y = Vector::Zero(n);
  Vector l = Vector::Zero(nc);
  s.termination = Termination::IterationLimit;

  for (int it = 1; it <= options.max_newton_iterations; ++it) {
    // Equality-constrained solve for the active set.
    std::fill(fixed.begin(), fixed.end(), false);
    Vector y_fixed = Vector::Zero(n);
    for (Index j = 0; j < nc; ++j)
      if (active[static_cast<std::size_t>(j)]) {
        const Index a = normal_dof[static_cast<std::size_t>(j)];
        fixed[static_cast<std::size_t>(a)] = true;
        y_fixed(a) = c.gaps(j) / scale(j);
      }
    for (Index col = 0; col < n; ++col)
      for (int k = K.outerIndexPtr()[col]; k < K.outerIndexPtr()[col + 1]; ++k) {
        const Index row = K.innerIndexPtr()[k];
        const bool cut = fixed[static_cast<std::size_t>(row)] || fixed[static_cast<std::size_t>(col)];
        K.valuePtr()[k] = !cut ? Ar.valuePtr()[k] : (row == col ? Ar.valuePtr()[k] : 0.0);
      }
    Vector rhs = br - Ar * y_fixed;
    for (Index i = 0; i < n; ++i)
      if (fixed[static_cast<std::size_t>(i)]) rhs(i) = Ar.coeff(i, i) * y_fixed(i);
    solver->factorize(K);
    const LinearSolveStats st = solver->solve(rhs, y);
    OuterStepRecord rec;
    rec.inner_iterations = 1;
    rec.factorizations = 1;
    rec.linear_iterations = st.iterations;
    if (!st.converged) {
      s.steps.push_back(rec);
      s.termination = Termination::LinearSolverFailure;
      s.message = fmt::format("linear solver did not converge at Newton iteration {} (residual {:.3e})",
                              it, st.residual);
      break;
    }
    // Multipliers from the reactions: (A_r y)_{a_j} + s_j h_j l_j = (b_r)_{a_j} on S.
    const Vector reaction = br - Ar * y;
    Vector l_new = Vector::Zero(nc);
    ActiveSet next(static_cast<std::size_t>(nc), false);
    for (Index j = 0; j < nc; ++j) {
      if (!c.movable[static_cast<std::size_t>(j)]) continue;
      const Index a = normal_dof[static_cast<std::size_t>(j)];
      if (active[static_cast<std::size_t>(j)]) {
        l_new(j) = reaction(a) / (scale(j) * c.weights(j));
        next[static_cast<std::size_t>(j)] = l_new(j) > 0.0;
      } else {
        next[static_cast<std::size_t>(j)] = scale(j) * y(a) - c.gaps(j) > 0.0;
      }
    }
    rec.dual_change = relative_change(l_new, l);
    rec.active_set_size = count_active(active);
    l = std::move(l_new);
    s.steps.push_back(rec);
    if (options.observer)
      options.observer({IterationEvent::Kind::Outer, it, 1, rec.active_set_size, rec.dual_change,
                        0, rec.linear_iterations});
    if (next == active) {
      s.termination = Termination::Converged;
      s.message = fmt::format("active set repeated after {} Newton iterations ({} active nodes)",
                              it, count_active(active));
      break;
    }
    if (std::find(history.begin(), history.end(), next) != history.end()) {
      s.termination = Termination::ActiveSetCycling;
      s.message = fmt::format(
          "active set cycles: iteration {} returns to an earlier active set ({} active nodes)", it,
          count_active(next));
      break;
    }
    history.push_back(active);
    active = std::move(next);
  }
  if (s.termination == Termination::IterationLimit)
    s.message = fmt::format("active set still changing after {} Newton iterations",
                            options.max_newton_iterations);
  s.timings.merge(solver->timings());
  out.u = Q * y;
  out.l = std::move(l);
  return out;
}

}  // namespace signorini

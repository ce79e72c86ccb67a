// Semismooth Newton method on the KKT system of (14), in its primal-dual active set form
// (method.md section 6): for a guessed active set S, impose (N x)_j = g_j on S and l_j = 0 off S,
// solve the equality-constrained problem exactly, and update
//   S <- { j in S : l_j > 0 } u { j not in S : (N x)_j > g_j },
// until S repeats. It uses no penalty parameter, so it checks the Uzawa methods independently.
//
// Three ways to solve the equality-constrained problem (active_set_solver.hpp):
// - sparse (any problem): the contact nodes' free dofs are rotated so that each normal
//   displacement is one unknown (contact/normal_rotation.hpp); in y = Q^T x the constraint fixes
//   it, y_{a_j} = g_j / s_j, and it is eliminated by replacing its row and column with the
//   diagonal, so one symbolic analysis serves all;
// - dense (the condensed problems, one unknown per contact node, (N x)_j = s_j x_{c(j)}): with
//   W = A^-1 computed once, x = x0 - W N^T H l, and the active multipliers solve the small system
//   W_SS y_S = x0_S - t_S (y = s h l, t = g / s): a Newton iteration then costs O(n |S|) plus
//   |S|^3 / 3;
// - on a backend (the iterative path, CPU or GPU): projected conjugate gradients with the
//   multigrid preconditioner of the penalised Newton matrix (projected_active_set_solver.hpp).

#include <fmt/format.h>

#include <Eigen/Cholesky>
#include <algorithm>

#include "signorini/contact/active_set_solver.hpp"
#include "signorini/contact/active_set_update.hpp"
#include "signorini/contact/backend_newton_matrix.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/modified_lagrangian.hpp"
#include "signorini/contact/normal_rotation.hpp"
#include "signorini/contact/outer_iteration.hpp"
#include "signorini/contact/projected_active_set_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/linalg/dense_storage.hpp"
#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

namespace {

class RotatedEliminationSolver final : public ActiveSetSolver {
 public:
  RotatedEliminationSolver(const ContactProblem& p, const LinearSolverOptions& linear)
      : p_(p), rotation_(make_normal_rotation(p.contact, p.A.rows())) {
    Ar_ = rotate_matrix(p.A, rotation_);
    br_ = rotation_.to_rotated(p.b);
    K_ = Ar_;
    y_ = Vector::Zero(p.A.rows());
    fixed_.assign(static_cast<std::size_t>(p.A.rows()), false);
    solver_ = make_linear_solver(linear);
    solver_->analyze(Ar_);
    if (linear.factor_updates != FactorUpdates::Never)
      cholmod_ = dynamic_cast<CholmodSolver*>(solver_.get());
    always_update_ = linear.factor_updates == FactorUpdates::Always;
  }

  LinearSolveStats solve(const ActiveSet& S, Vector& l, Vector& gap_residual) override {
    const ContactSet& c = p_.contact;
    const Index n = Ar_.rows();
    std::vector<bool> fixed(static_cast<std::size_t>(n), false);
    Vector y_fixed = Vector::Zero(n);
    for (Index j = 0; j < c.size(); ++j)
      if (S[static_cast<std::size_t>(j)]) {
        const Index a = rotation_.normal_dof[static_cast<std::size_t>(j)];
        fixed[static_cast<std::size_t>(a)] = true;
        y_fixed(a) = c.gaps(j) / rotation_.scale(j);
      }
    // K: A_r with the rows and columns of the fixed unknowns replaced by their diagonal, from
    // the last factor by row modifications where that is expected to be faster (the sparse
    // direct path's rule, newton_system.cpp), else factorised.
    factorized_ = updated_ = 0;
    if (!(has_factor_ && (fixed == fixed_ || (cholmod_ != nullptr && modify_to(fixed))))) {
      for (Index col = 0; col < n; ++col)
        for (int k = K_.outerIndexPtr()[col]; k < K_.outerIndexPtr()[col + 1]; ++k) {
          const Index row = K_.innerIndexPtr()[k];
          const bool cut =
              fixed[static_cast<std::size_t>(row)] || fixed[static_cast<std::size_t>(col)];
          K_.valuePtr()[k] = !cut ? Ar_.valuePtr()[k] : (row == col ? Ar_.valuePtr()[k] : 0.0);
        }
      solver_->factorize(K_);
      factorized_ = 1;
      modifications_since_factorization_ = 0;
    }
    fixed_ = fixed;
    has_factor_ = true;
    Vector rhs = br_ - Ar_ * y_fixed;
    for (Index i = 0; i < n; ++i)
      if (fixed[static_cast<std::size_t>(i)]) rhs(i) = Ar_.coeff(i, i) * y_fixed(i);
    const LinearSolveStats st = solver_->solve(rhs, y_);
    timings_ = solver_->timings();
    // Multipliers from the reactions: (A_r y)_{a_j} + s_j h_j l_j = (b_r)_{a_j} on S.
    const Vector reaction = br_ - Ar_ * y_;
    l = Vector::Zero(c.size());
    gap_residual = Vector::Zero(c.size());
    for (Index j = 0; j < c.size(); ++j) {
      if (!c.movable[static_cast<std::size_t>(j)]) continue;
      const Index a = rotation_.normal_dof[static_cast<std::size_t>(j)];
      const double s = rotation_.scale(j);
      if (S[static_cast<std::size_t>(j)]) l(j) = reaction(a) / (s * c.weights(j));
      gap_residual(j) = s * y_(a) - c.gaps(j);
    }
    return st;
  }
  [[nodiscard]] Vector displacement() const override { return rotation_.from_rotated(y_); }
  [[nodiscard]] int last_factorizations() const override { return factorized_; }
  [[nodiscard]] int last_factor_updates() const override { return updated_; }

 private:
  // Modifications accumulate rounding: refactorise after this many since the last
  // factorisation, however cheap they are (as the Newton systems of newton_system.cpp).
  static constexpr std::size_t kMaxModifications = 2000;

  // From the factor of K(F) to that of K(F'), F the fixed unknowns: an unknown that becomes
  // fixed has its row and column deleted (the identity's) and then added back as its diagonal
  // alone; one that becomes free has the diagonal deleted and its column of A_r added, without
  // the rows still fixed (Davis and Hager's row modifications, CholmodSolver::delete_row and
  // add_row). So K is the matrix that a factorisation would have been given. False where a
  // factorisation is expected to be faster, or a modification failed (the caller refactorises).
  bool modify_to(const std::vector<bool>& fixed) {
    std::vector<Index> changed;
    double flops = 0.0;
    for (std::size_t i = 0; i < fixed.size(); ++i)
      if (fixed[i] != fixed_[i]) {
        changed.push_back(static_cast<Index>(i));
        flops += 2.0 * cholmod_->row_modification_flops(static_cast<Index>(i));
      }
    if (changed.empty()) return true;
    // The rule of the sparse direct path's Newton systems (newton_system.cpp): modify where that
    // is expected to take less time than the factorisation it replaces, the conversion of the
    // factor to L D L^T counted half.
    if (modifications_since_factorization_ + changed.size() > kMaxModifications ||
        (!always_update_ && cholmod_->predicted_update_seconds(flops) +
                                    0.5 * cholmod_->predicted_conversion_seconds() >
                                cholmod_->last_factorization_seconds()))
      return false;
    std::vector<bool> now = fixed_;  // the unknowns whose row is the diagonal's, as it goes
    std::vector<std::pair<Index, double>> column;
    for (const Index i : changed) {
      const auto k = static_cast<std::size_t>(i);
      if (!cholmod_->delete_row(i)) return false;
      column.clear();
      if (fixed[k]) {
        column.emplace_back(i, Ar_.coeff(i, i));
      } else {
        // Column i of A_r is its row (symmetry); the rows still fixed stay decoupled.
        for (SparseMatrix::InnerIterator it(Ar_, i); it; ++it)
          if (it.row() == i || !now[static_cast<std::size_t>(it.row())])
            column.emplace_back(it.row(), it.value());
      }
      now[k] = fixed[k];
      if (!cholmod_->add_row(i, column)) return false;
    }
    updated_ = static_cast<int>(changed.size());
    modifications_since_factorization_ += changed.size();
    return true;
  }

  const ContactProblem& p_;
  NormalRotation rotation_;
  SparseMatrix Ar_, K_;
  Vector br_, y_;
  std::unique_ptr<LinearSolver> solver_;
  CholmodSolver* cholmod_ = nullptr;  // solver_, where it can modify its factor
  bool always_update_ = false;        // factor_updates = "always"
  std::vector<bool> fixed_;           // the fixed unknowns of the current factor
  bool has_factor_ = false;
  int factorized_ = 0, updated_ = 0;  // by the last solve
  std::size_t modifications_since_factorization_ = 0;
};

class DelassusSolver final : public ActiveSetSolver {
 public:
  explicit DelassusSolver(const ContactProblem& p) : p_(p) {
    ScopedTimer t(timings_, "linear factorization");
    const ContactSet& c = p.contact;
    // W = S^-1 explicitly: the one method that needs the inverse (the Delassus operator).
    const auto view = dense_view(p.A);
    const Eigen::LLT<Eigen::MatrixXd> llt = view
                                                ? Eigen::LLT<Eigen::MatrixXd>(*view)
                                                : Eigen::LLT<Eigen::MatrixXd>(Eigen::MatrixXd(p.A));
    if (llt.info() != Eigen::Success)
      throw NumericalError("dense Cholesky: matrix is not positive definite");
    W_ = llt.solve(Eigen::MatrixXd::Identity(p.A.rows(), p.A.cols()));
    x0_ = llt.solve(p.b);
    column_.assign(static_cast<std::size_t>(c.size()), -1);
    scale_ = Vector::Zero(c.size());
    const SparseMatrix Nt = c.N.transpose();
    for (Index j = 0; j < c.size(); ++j)
      for (SparseMatrix::InnerIterator it(Nt, j); it; ++it) {
        column_[static_cast<std::size_t>(j)] = it.row();
        scale_(j) = it.value();
      }
    x_ = x0_;
  }
  // True where every row of N has at most one entry, nonzero.
  static bool applies(const ContactProblem& p) {
    const SparseMatrix Nt = p.contact.N.transpose();
    for (Index j = 0; j < Nt.cols(); ++j) {
      if (Nt.col(j).nonZeros() > 1) return false;
      for (SparseMatrix::InnerIterator it(Nt, j); it; ++it)
        if (it.value() == 0.0) return false;
    }
    return true;
  }

  LinearSolveStats solve(const ActiveSet& S, Vector& l, Vector& gap_residual) override {
    ScopedTimer t(timings_, "linear solve");
    const ContactSet& c = p_.contact;
    std::vector<Index> nodes, cols;
    for (Index j = 0; j < c.size(); ++j)
      if (S[static_cast<std::size_t>(j)] && column_[static_cast<std::size_t>(j)] >= 0) {
        nodes.push_back(j);
        cols.push_back(column_[static_cast<std::size_t>(j)]);
      }
    const auto k = static_cast<Index>(cols.size());
    Vector y = Vector::Zero(k);
    if (k > 0) {
      Vector rhs(k);
      for (Index a = 0; a < k; ++a) {
        const Index j = nodes[static_cast<std::size_t>(a)];
        rhs(a) = x0_(cols[static_cast<std::size_t>(a)]) - c.gaps(j) / scale_(j);
      }
      const Eigen::MatrixXd Wss = W_(cols, cols);
      y = Wss.llt().solve(rhs);
      x_ = x0_ - W_(Eigen::all, cols) * y;
    } else {
      x_ = x0_;
    }
    l = Vector::Zero(c.size());
    for (Index a = 0; a < k; ++a) {
      const Index j = nodes[static_cast<std::size_t>(a)];
      l(j) = y(a) / (scale_(j) * c.weights(j));
    }
    gap_residual = Vector::Zero(c.size());
    for (Index j = 0; j < c.size(); ++j) {
      const Index col = column_[static_cast<std::size_t>(j)];
      if (col >= 0) gap_residual(j) = scale_(j) * x_(col) - c.gaps(j);
    }
    return {};
  }
  [[nodiscard]] Vector displacement() const override { return x_; }

 private:
  const ContactProblem& p_;
  Eigen::MatrixXd W_;  // A^-1
  Vector x0_, x_, scale_;
  std::vector<Index> column_;  // unknown of contact node j, -1 if none
};

// The primal-dual active set loop, with any ActiveSetSolver; fills out.summary's steps and
// termination, and out.u.
void run_semismooth_newton(const ContactProblem& problem, const ContactSolverOptions& options,
                           const Vector& l0, ActiveSetSolver& solver, ContactResult& out) {
  SolveSummary& s = out.summary;
  const ContactSet& c = problem.contact;
  const Index nc = c.size();
  ActiveSet active(static_cast<std::size_t>(nc), false);
  for (Index j = 0; j < nc; ++j)
    active[static_cast<std::size_t>(j)] = c.movable[static_cast<std::size_t>(j)] && l0(j) > 0.0;
  std::vector<ActiveSet> history;
  // Inexact steps (inner_tolerance = adaptive, on an iterative solver): while the active set
  // still moves, each step is solved only to kLooseNewtonTolerance, enough to tell which nodes
  // press and which penetrate; once a loose step repeats its active set (or returns to an
  // earlier one), the steps are solved exactly, and only an exact step that repeats its active
  // set ends the run, so the answer is the exact method's.
  bool loose = options.adaptive_inner_tolerance() && solver.iterative();
  if (loose) solver.set_tolerance(kLooseNewtonTolerance);
  const auto tighten = [&] {
    loose = false;
    solver.set_tolerance(0.0);
    history.clear();
  };
  OuterLoop loop;
  loop.max_steps = newton_iteration_limit(options, problem.contact.size());
  loop.step = [&](int it, const Vector& l) {
    OuterStepOutcome o;
    OuterStepRecord& rec = o.record;
    Vector gap_residual;
    const LinearSolveStats st = solver.solve(active, o.l, gap_residual);
    rec.inner_iterations = 1;
    rec.factorizations = solver.last_factorizations();
    rec.factor_updates = solver.last_factor_updates();
    rec.linear_iterations = st.iterations;
    if (!st.converged) {
      o.l.resize(0);  // not a step: l^(k-1) stays
      o.stop = Termination::LinearSolverFailure;
      o.message =
          fmt::format("linear solver did not converge at Newton iteration {} (residual {:.3e})", it,
                      st.residual);
      return o;
    }
    // The next active set: nodes pressed (l_j > 0) stay, free nodes that penetrate join.
    ActiveSet next = next_active_set(c, active, o.l, gap_residual);
    rec.dual_change = relative_change(o.l, l);
    rec.active_set_size = count_active(active);
    const bool returns = std::find(history.begin(), history.end(), next) != history.end();
    if (loose && (next == active || returns)) {
      tighten();  // the same active set again, now solved exactly
      if (next != active) active = std::move(next);
    } else if (next == active) {
      o.stop = Termination::Converged;
      o.message = fmt::format("active set repeated after {} Newton iterations ({} active nodes)",
                              it, count_active(active));
    } else if (returns) {
      o.stop = Termination::ActiveSetCycling;
      o.message = fmt::format(
          "active set cycles: iteration {} returns to an earlier active set ({} active nodes)", it,
          count_active(next));
    } else {
      history.push_back(active);
      active = std::move(next);
    }
    return o;
  };
  loop.limit_message = [&](const OuterStepRecord&) {
    return fmt::format("active set still changing after {} Newton iterations", loop.max_steps);
  };
  run_outer_loop(loop, l0, options, out);
  s.timings.merge(solver.timings());
  out.u = solver.displacement();
}

}  // namespace

ContactResult solve_semismooth_newton(const ContactProblem& problem,
                                      const ContactSolverOptions& options, const MethodStart& start,
                                      const MultigridHierarchy* /*multigrid*/) {
  if (problem.contact.components > 1)
    return solve_friction_semismooth_newton(problem, options, start);
  ContactResult out;
  std::unique_ptr<ActiveSetSolver> solver;
  if (options.linear.type == LinearSolverType::Dense && DelassusSolver::applies(problem))
    solver = std::make_unique<DelassusSolver>(problem);
  else
    solver = std::make_unique<RotatedEliminationSolver>(problem, options.linear);
  run_semismooth_newton(problem, options, start.multipliers(problem.contact.size()), *solver, out);
  return out;
}

ContactResult solve_semismooth_newton_on_backend(const ContactProblem& problem,
                                                 const ContactSolverOptions& options,
                                                 const MethodStart& start,
                                                 const MultigridHierarchy* multigrid) {
  ContactResult out;
  TimingTable timings;
  const std::unique_ptr<Backend> backend = make_timed_backend(options, timings);
  // r only scales the preconditioner's stand-in for the constraints; the answer has no r.
  ProjectedActiveSetSolver solver(problem, options, augmentation_parameter(problem, options),
                                  multigrid, *backend, start.displacement(problem.A.rows()));
  run_semismooth_newton(problem, options, start.multipliers(problem.contact.size()), solver, out);
  record_backend(out.summary, *backend, solver.levels(), multigrid);
  out.summary.timings.merge(timings);
  return out;
}

ContactResult solve_semismooth_newton_distributed(const ContactProblem& problem,
                                                  const ContactSolverOptions& options,
                                                  const MethodStart& start,
                                                  const MultigridHierarchy* /*multigrid*/) {
  DistributedEngine& engine = required_engine(problem);
  ContactResult out;
  TimingTable timings;
  const std::unique_ptr<DistributedActiveSetSolver> solver =
      engine.active_set_solver(problem, options, start.displacement(problem.A.rows()), timings);
  run_semismooth_newton(problem, options, start.multipliers(problem.contact.size()), *solver, out);
  record_distributed(out.summary, engine, solver->linear_solver_description());
  out.summary.timings.merge(timings);
  return out;
}

}  // namespace signorini

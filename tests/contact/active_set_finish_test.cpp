// Uzawa-GNM's active-set finish (ContactSolverOptions::active_set_finish, docs/solvers.md): once
// the multipliers settle, the problem with the nodes in contact fixed is solved by projected CG
// and taken as the answer where the KKT conditions hold. Checked against the sparse direct
// solve of the same discrete problem and against Uzawa's steps to the end.

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "../problem/ball_on_block.hpp"
#include "signorini/backend/host_backend.hpp"
#include "signorini/contact/active_set_update.hpp"
#include "signorini/contact/backend_newton_space.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/generalized_newton.hpp"
#include "signorini/contact/uzawa_iteration.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

int cg_iterations(const ContactResult& r) {
  int cg = 0;
  for (const OuterStepRecord& s : r.summary.steps) cg += s.linear_iterations;
  return cg;
}

struct Block {
  Model model;
  ContactSolverOptions iterative;  // CG with multigrid, inexact Uzawa-GNM
};

Block ball_on_block(Index n) {
  ProblemSpec spec = testing::ball_on_block(n, 2e-2);
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Adaptive;
  Block b{build_model(spec), {}};
  b.iterative = b.model.solver;
  return b;
}

// The sparse direct solve of the same discrete problem, Uzawa to 1e-12: the reference.
ContactResult direct_solve(const ContactProblem& p) {
  ContactSolverOptions o;
  o.automatic_path = false;
  o.uzawa_tolerance = 1e-12;
  return solve_contact(p, o);
}

// A 3D block on a rigid ball (the iterative path's problem) and the paper's 2D benchmark: the
// finish ends Uzawa with the sparse direct solution, to the tolerances, with fewer CG
// iterations than Uzawa's steps to the end and tighter KKT residuals.
TEST(ActiveSetFinish, EndsUzawaWithTheDirectSolutionInFewerCgIterations) {
  const Block b = ball_on_block(12);
  const ContactProblem& p = b.model.problem;
  const ContactResult direct = direct_solve(p);
  ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;
  ASSERT_GT(direct.summary.num_active, 10);

  ContactSolverOptions o = b.iterative;
  ASSERT_TRUE(o.active_set_finish);  // the default
  ASSERT_TRUE(uses_backend_path(o));
  const ContactResult finished = solve_contact(p, o, &b.model.multigrid);
  o.active_set_finish = false;
  const ContactResult stepped = solve_contact(p, o, &b.model.multigrid);
  ASSERT_TRUE(finished.summary.converged()) << finished.summary.message;
  ASSERT_TRUE(stepped.summary.converged()) << stepped.summary.message;
  EXPECT_TRUE(finished.summary.active_set_finish);
  EXPECT_FALSE(stepped.summary.active_set_finish);
  EXPECT_NE(finished.summary.message.find("solved for exactly"), std::string::npos)
      << finished.summary.message;

  EXPECT_LT(relative_difference(finished.u, direct.u), 1e-10);
  EXPECT_LT(relative_difference(finished.l, direct.l), 1e-9);
  EXPECT_EQ(finished.summary.num_active, direct.summary.num_active);
  EXPECT_LT(finished.summary.kkt.max(), 1e-11);
  EXPECT_LT(relative_difference(stepped.u, direct.u), 1e-8);
  EXPECT_LT(finished.summary.outer_iterations, stepped.summary.outer_iterations);
  EXPECT_LT(cg_iterations(finished), cg_iterations(stepped))
      << cg_iterations(finished) << " against " << cg_iterations(stepped);
}

TEST(ActiveSetFinish, PaperProblemOnTheBackendPath) {
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(120);
  const ContactResult direct = direct_solve(p);
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  o.inner_tolerance = InnerTolerance::Adaptive;
  const ContactResult finished = solve_contact(p, o, &multigrid);
  ASSERT_TRUE(finished.summary.converged()) << finished.summary.message;
  EXPECT_TRUE(finished.summary.active_set_finish);
  EXPECT_LT(relative_difference(finished.u, direct.u), 1e-10);
  EXPECT_LT(relative_difference(finished.l, direct.l), 1e-9);
  EXPECT_LT(finished.summary.kkt.max(), 1e-11);
  // The exact method (inner_tolerance fixed, the paper's) never finishes early.
  o.inner_tolerance = InnerTolerance::Fixed;
  const ContactResult exact = solve_contact(p, o, &multigrid);
  EXPECT_FALSE(exact.summary.active_set_finish);
}

// The space's solve with a given active set: with the direct solution's contact set it gives
// that solution (u and l); with every contact node held, the nodes that should lift off get
// negative multipliers, which contact_conditions_hold refuses.
TEST(ActiveSetFinish, TheActiveSetSolveAndItsAcceptance) {
  const Block b = ball_on_block(10);
  const ContactProblem& p = b.model.problem;
  const ContactResult direct = direct_solve(p);
  ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;
  const Index nc = p.contact.size();
  ActiveSet right(static_cast<std::size_t>(nc)), all(static_cast<std::size_t>(nc), true);
  for (Index j = 0; j < nc; ++j) right[static_cast<std::size_t>(j)] = direct.l(j) > 0.0;

  HostBackend backend;
  TimingTable timings;
  const double r = 1e3;
  {
    BackendNewtonSpace space(p, b.iterative, &b.model.multigrid, backend, timings,
                             Vector::Zero(p.A.rows()));
    const std::optional<ActiveSetSolve> f = space.solve_on_active_set(right, r, 1e-12);
    ASSERT_TRUE(f.has_value());
    EXPECT_TRUE(f->stats.converged);
    EXPECT_GT(f->stats.iterations, 0);
    EXPECT_LT(relative_difference(space.solution(), direct.u), 1e-10);
    EXPECT_LT(relative_difference(f->l, direct.l), 1e-9);
    EXPECT_TRUE(contact_conditions_hold(p.contact, right, *f, 1e-8));
    // The gaps it reports are N u - g of its solution: zero on the set.
    const Vector gap = p.contact.N * space.solution() - p.contact.gaps;
    EXPECT_LT((gap - f->gap_residual).lpNorm<Eigen::Infinity>(), 1e-12);
    for (Index j = 0; j < nc; ++j)
      if (right[static_cast<std::size_t>(j)]) {
        EXPECT_NEAR(f->gap_residual(j), 0.0, 1e-12);
      }
  }
  {
    BackendNewtonSpace space(p, b.iterative, &b.model.multigrid, backend, timings,
                             Vector::Zero(p.A.rows()));
    const std::optional<ActiveSetSolve> f = space.solve_on_active_set(all, r, 1e-12);
    ASSERT_TRUE(f.has_value());
    EXPECT_LT(f->l.minCoeff(), 0.0);
    EXPECT_FALSE(contact_conditions_hold(p.contact, all, *f, 1e-8));
  }
}

// A space that passes everything to the backend's and records the tolerance of each active-set
// solve and whether it repeated the set it was given.
class RecordingSpace : public NewtonSpace {
 public:
  RecordingSpace(NewtonSpace& inner, const ContactSet& contact)
      : inner_(inner), contact_(contact) {}
  [[nodiscard]] const Vector& contact_values() const override { return inner_.contact_values(); }
  void set_active(const ActiveSet& active, double r) override { inner_.set_active(active, r); }
  NewtonSolveStats solve(const Vector& terms) override { return inner_.solve(terms); }
  void set_linear_tolerance(double t) override { inner_.set_linear_tolerance(t); }
  void direction(ModifiedLagrangian::Direction& dir) override { inner_.direction(dir); }
  void step(double t) override { inner_.step(t); }
  NewtonStepNorms norms(const Vector& forces) override { return inner_.norms(forces); }
  std::optional<ActiveSetSolve> solve_on_active_set(const ActiveSet& S, double r,
                                                    double tolerance) override {
    std::optional<ActiveSetSolve> f = inner_.solve_on_active_set(S, r, tolerance);
    if (f) solves.push_back({tolerance, next_active_set(contact_, S, f->l, f->gap_residual) == S});
    return f;
  }
  [[nodiscard]] int factorizations() const override { return inner_.factorizations(); }

  struct Solve {
    double tolerance;
    bool repeated;  // the primal-dual rule gave back the set solved for
  };
  std::vector<Solve> solves;

 private:
  NewtonSpace& inner_;
  const ContactSet& contact_;
};

// The finish's tolerances (docs/solvers.md): 1e-6 while the set moves; once a set repeats, the
// geometric mean of 1e-6 and the exact tolerance; once it repeats there, exact; the answer is
// the exact solve that repeats its set. A tolerance is tightened only after a repeat.
TEST(ActiveSetFinish, TightensTheSolvesInThreeSteps) {
  const Block b = ball_on_block(12);
  const ContactProblem& p = b.model.problem;
  HostBackend backend;
  TimingTable timings;
  BackendNewtonSpace inner(p, b.iterative, &b.model.multigrid, backend, timings,
                           Vector::Zero(p.A.rows()));
  RecordingSpace space(inner, p.contact);
  ModifiedLagrangian phi(p, augmentation_parameter(p, b.iterative));
  ContactResult out;
  run_uzawa_iteration(p, b.iterative, phi, space, Vector::Zero(p.contact.size()), out);
  ASSERT_TRUE(out.summary.converged()) << out.summary.message;
  ASSERT_TRUE(out.summary.active_set_finish);
  const double loose = kLooseNewtonTolerance;
  const double exact = 10.0 * b.iterative.linear.cg_tolerance;
  const double middle = std::sqrt(loose * exact);
  const std::vector<RecordingSpace::Solve>& s = space.solves;
  ASSERT_GE(s.size(), 3U);
  EXPECT_EQ(s.front().tolerance, loose);
  EXPECT_EQ(s.back().tolerance, exact);
  EXPECT_TRUE(s.back().repeated);
  bool met_middle = false;
  for (std::size_t k = 1; k < s.size(); ++k) {
    const double before = s[k - 1].tolerance, now = s[k].tolerance;
    met_middle = met_middle || now == middle;
    if (now != before) {
      EXPECT_TRUE(s[k - 1].repeated) << "solve " << k + 1 << ": tightened without a repeat";
      EXPECT_TRUE((before == loose && now == middle) || (before == middle && now == exact))
          << "solve " << k + 1 << ": " << before << " -> " << now;
    } else {
      EXPECT_FALSE(s[k - 1].repeated) << "solve " << k + 1 << ": a repeat not tightened";
    }
  }
  EXPECT_TRUE(met_middle);
}

}  // namespace
}  // namespace signorini

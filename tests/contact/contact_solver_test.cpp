// ContactSolver: set up once, solved again for new loads and gaps, warm started; on every path
// the answers equal those of a fresh one-shot solve of the changed problem.

#include "signorini/contact/contact_solver.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::paper_model;
using testing::relative_difference;

ContactSolverOptions options_for(SolvePath path) {
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-12;
  switch (path) {
    case SolvePath::CondensedDirect:
      break;
    case SolvePath::SparseDirect:
      o.schur_complement = false;
      break;
    case SolvePath::Iterative:
      o.linear.type = LinearSolverType::ConjugateGradient;
      o.linear.cg_tolerance = 1e-14;
      break;
    case SolvePath::Backend:
      o.linear.type = LinearSolverType::ConjugateGradient;
      o.linear.preconditioner = PreconditionerType::Multigrid;
      o.linear.cg_tolerance = 1e-14;
      break;
    case SolvePath::Distributed:  // needs a PETSc engine: tests/petsc/
      o.distributed = DistributedMode::Petsc;
      break;
  }
  return o;
}

class EveryPath : public ::testing::TestWithParam<SolvePath> {};

TEST_P(EveryPath, NewLoadsAndGapsGiveTheAnswerOfAFreshSolve) {
  const SolvePath path = GetParam();
  // The backend path's multigrid takes the hierarchy as a set-up argument.
  const auto [problem, multigrid] = testing::paper_problem_with_hierarchy(30);
  const ContactSolverOptions o = options_for(path);

  ContactSolver solver(problem, o, &multigrid);
  EXPECT_EQ(solver.path(), path);
  const ContactResult first = solver.solve();
  ASSERT_TRUE(first.summary.converged()) << first.summary.message;
  EXPECT_EQ(first.summary.path, path);

  // Twice the load and an initial gap of 2e-6 under the left half: a different contact zone.
  ContactProblem changed = problem;
  changed.b *= 2.0;
  for (Index j = 0; j < changed.contact.size(); ++j)
    changed.contact.gaps(j) = j < changed.contact.size() / 2 ? 2e-6 : 0.0;
  solver.set_loads(changed.b);
  solver.set_gaps(changed.contact.gaps);
  const ContactResult second = solver.solve();
  const ContactResult fresh = solve_contact(changed, o, &multigrid);
  ASSERT_TRUE(second.summary.converged()) << second.summary.message;
  ASSERT_TRUE(fresh.summary.converged()) << fresh.summary.message;
  EXPECT_LT(relative_difference(second.u, fresh.u), 1e-9);
  EXPECT_LT(relative_difference(second.l, fresh.l), 1e-8);
  EXPECT_NEAR(second.summary.energy, fresh.summary.energy, 1e-10 * std::abs(fresh.summary.energy));
  EXPECT_GT((second.u - 2.0 * first.u).norm(), 1e-3 * second.u.norm());  // the gap mattered
  // The problem given to the solver is not changed.
  EXPECT_EQ(problem.b, paper_model(30).problem.b);
}

INSTANTIATE_TEST_SUITE_P(ContactSolver, EveryPath,
                         ::testing::Values(SolvePath::CondensedDirect, SolvePath::SparseDirect,
                                           SolvePath::Iterative, SolvePath::Backend),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kSolvePathNames, param_info.param));
                         });

// A warm start from the solution of the same problem: Uzawa-GNM needs one step (the multipliers
// do not change), semismooth Newton one iteration (the active set repeats at once).
TEST(ContactSolver, WarmStartFromTheSolutionConvergesAtOnce) {
  const ContactProblem& p = paper_model(60).problem;
  for (const ContactMethod method : {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton}) {
    ContactSolverOptions o;
    o.method = method;
    ContactSolver solver(p, o);
    const ContactResult cold = solver.solve();
    ASSERT_TRUE(cold.summary.converged()) << cold.summary.message;
    EXPECT_FALSE(cold.summary.warm_started);
    solver.warm_start(cold);
    const ContactResult warm = solver.solve();
    ASSERT_TRUE(warm.summary.converged()) << warm.summary.message;
    EXPECT_TRUE(warm.summary.warm_started);
    EXPECT_LT(warm.summary.outer_iterations, cold.summary.outer_iterations);
    EXPECT_EQ(warm.summary.outer_iterations, 1) << enum_to_string(kContactMethodNames, method);
    EXPECT_LT(relative_difference(warm.u, cold.u), 1e-9);
    solver.cold_start();
    EXPECT_EQ(solver.solve().summary.outer_iterations, cold.summary.outer_iterations);
  }
}

// Load stepping: each step warm started from the last takes fewer Uzawa steps than a cold start.
TEST(ContactSolver, LoadSteppingWithWarmStarts) {
  const ContactProblem& p = paper_model(60).problem;
  ContactSolver solver(p, ContactSolverOptions{});
  ContactResult previous = solver.solve();
  int warm_steps = 0, cold_steps = 0;
  for (const double factor : {1.1, 1.2, 1.3}) {
    solver.set_loads(factor * p.b);
    solver.warm_start(previous);
    previous = solver.solve();
    ASSERT_TRUE(previous.summary.converged()) << previous.summary.message;
    warm_steps += previous.summary.outer_iterations;
    ContactProblem scaled = p;
    scaled.b *= factor;
    const ContactResult cold = solve_contact(scaled, ContactSolverOptions{});
    cold_steps += cold.summary.outer_iterations;
    EXPECT_LT(relative_difference(previous.u, cold.u), 1e-8);
  }
  EXPECT_LT(warm_steps, cold_steps);
}

// A callback may stop a run: after the third outer step (Uzawa) or the fifth GNM iteration, the
// solve ends with stopped_by_callback, the records so far and the current iterate.
TEST(ContactSolver, CallbackStopsTheRun) {
  const ContactProblem& p = paper_model(60).problem;
  for (const bool inner : {false, true}) {
    ContactSolverOptions o;
    int events = 0;
    o.callback = [&](const IterationEvent& e) {
      ++events;
      if (inner)
        return e.kind == IterationEvent::Kind::Inner && e.inner == 5 ? CallbackAction::Stop
                                                                     : CallbackAction::Continue;
      return e.kind == IterationEvent::Kind::Outer && e.outer == 3 ? CallbackAction::Stop
                                                                   : CallbackAction::Continue;
    };
    const ContactResult r = solve_contact(p, o);
    EXPECT_EQ(r.summary.termination, Termination::StoppedByCallback) << r.summary.message;
    EXPECT_FALSE(r.summary.converged());
    EXPECT_EQ(r.summary.outer_iterations, inner ? 1 : 3);
    EXPECT_NE(r.summary.message.find("stopped by the callback"), std::string::npos)
        << r.summary.message;
    EXPECT_EQ(r.summary.message.find("to try"), std::string::npos) << r.summary.message;
    EXPECT_EQ(r.u.size(), p.A.rows());
    EXPECT_GT(events, 0);
  }
}

TEST(ContactSolver, WrongSizesAreRefused) {
  const ContactProblem& p = paper_model(30).problem;
  ContactSolver solver(p, ContactSolverOptions{});
  EXPECT_THROW(solver.set_loads(Vector::Zero(3)), InputError);
  EXPECT_THROW(solver.set_gaps(Vector::Zero(3)), InputError);
  ContactResult other;
  other.u = Vector::Zero(5);
  EXPECT_THROW(solver.warm_start(other), InputError);
}

}  // namespace
}  // namespace signorini

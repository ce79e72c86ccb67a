// The sparse direct path's Newton systems (contact/newton_system.cpp): with CHOLMOD's factor
// updated and downdated as the active set changes, Uzawa-GNM takes the same steps and reaches
// the same u and l as with a factorisation for every active set, in 2D and 3D.

#include "signorini/contact/newton_system.hpp"

#include <gtest/gtest.h>

#include <numeric>

#include "problem/ball_on_block.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

int total(const SolveSummary& s, int OuterStepRecord::*field) {
  return std::accumulate(s.steps.begin(), s.steps.end(), 0,
                         [field](int sum, const OuterStepRecord& r) { return sum + r.*field; });
}

void expect_updates_change_nothing(const ContactProblem& problem, ContactSolverOptions o) {
  o.schur_complement = false;  // the sparse direct path
  o.linear.factor_updates = FactorUpdates::Never;
  const ContactResult refactorised = solve_contact(problem, o);
  o.linear.factor_updates = FactorUpdates::Always;
  const ContactResult updated = solve_contact(problem, o);
  ASSERT_TRUE(refactorised.summary.converged()) << refactorised.summary.message;
  ASSERT_TRUE(updated.summary.converged()) << updated.summary.message;
  EXPECT_EQ(updated.summary.path, SolvePath::SparseDirect);

  // The same iteration, step by step.
  ASSERT_EQ(updated.summary.steps.size(), refactorised.summary.steps.size());
  for (std::size_t k = 0; k < updated.summary.steps.size(); ++k)
    EXPECT_EQ(updated.summary.steps[k].inner_iterations,
              refactorised.summary.steps[k].inner_iterations)
        << "Uzawa step " << k + 1;
  EXPECT_LT(relative_difference(updated.u, refactorised.u), 1e-10);
  EXPECT_LT(relative_difference(updated.l, refactorised.l), 1e-9);
  EXPECT_LT(updated.summary.kkt.max(), 1e-9);

  // One factorisation and updates after it (none refactorised: every change is small enough
  // for "always"), against one factorisation per active set.
  EXPECT_EQ(total(refactorised.summary, &OuterStepRecord::factor_updates), 0);
  EXPECT_GT(total(refactorised.summary, &OuterStepRecord::factorizations), 1);
  EXPECT_EQ(total(updated.summary, &OuterStepRecord::factorizations), 1);
  EXPECT_GT(total(updated.summary, &OuterStepRecord::factor_updates), 0);
}

// Semismooth Newton on the sparse direct path (semismooth_newton_solver.cpp, rotated
// elimination): with the factor's rows modified as unknowns become fixed or free, the same
// active sets step by step and the same u and l as with a factorisation for every active set.
void expect_row_modifications_change_nothing(const ContactProblem& problem,
                                             ContactSolverOptions o) {
  o.method = ContactMethod::SemismoothNewton;
  o.schur_complement = false;
  o.linear.factor_updates = FactorUpdates::Never;
  const ContactResult refactorised = solve_contact(problem, o);
  o.linear.factor_updates = FactorUpdates::Always;
  const ContactResult updated = solve_contact(problem, o);
  ASSERT_TRUE(refactorised.summary.converged()) << refactorised.summary.message;
  ASSERT_TRUE(updated.summary.converged()) << updated.summary.message;
  EXPECT_EQ(updated.summary.path, SolvePath::SparseDirect);

  ASSERT_EQ(updated.summary.steps.size(), refactorised.summary.steps.size());
  ASSERT_GE(updated.summary.steps.size(), 3U);  // active sets that change
  for (std::size_t k = 0; k < updated.summary.steps.size(); ++k)
    EXPECT_EQ(updated.summary.steps[k].active_set_size,
              refactorised.summary.steps[k].active_set_size)
        << "Newton step " << k + 1;
  EXPECT_LT(relative_difference(updated.u, refactorised.u), 1e-10);
  EXPECT_LT(relative_difference(updated.l, refactorised.l), 1e-9);
  EXPECT_LT(updated.summary.kkt.max(), 1e-9);

  EXPECT_EQ(total(refactorised.summary, &OuterStepRecord::factor_updates), 0);
  EXPECT_EQ(total(refactorised.summary, &OuterStepRecord::factorizations),
            static_cast<int>(refactorised.summary.steps.size()));
  EXPECT_EQ(total(updated.summary, &OuterStepRecord::factorizations), 1);
  EXPECT_GT(total(updated.summary, &OuterStepRecord::factor_updates), 0);
}

TEST(SparseNewtonSystem, SemismoothNewtonRowModificationsGiveTheRefactorisedSteps2D) {
  expect_row_modifications_change_nothing(testing::paper_model(60).problem, {});
}

TEST(SparseNewtonSystem, SemismoothNewtonRowModificationsGiveTheRefactorisedSteps3D) {
  ProblemSpec spec = testing::ball_on_block(10, 6e-3);
  expect_row_modifications_change_nothing(build_model(spec).problem, spec.solver);
}

TEST(SparseNewtonSystem, FactorUpdatesGiveTheRefactorisedIterates2D) {
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-12;
  expect_updates_change_nothing(testing::paper_model(60).problem, o);
}

TEST(SparseNewtonSystem, FactorUpdatesGiveTheRefactorisedIterates3D) {
  ProblemSpec spec = testing::ball_on_block(10, 6e-3);
  ContactSolverOptions o = spec.solver;
  o.uzawa_tolerance = 1e-10;
  expect_updates_change_nothing(build_model(spec).problem, o);
}

}  // namespace
}  // namespace signorini

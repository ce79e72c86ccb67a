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

// The sparse direct path solved twice, refactorising every new active set (`never`) and
// modifying the factor (`always`): both converge on that path, with the same number of outer
// steps, u and l to rounding, small KKT residuals, and one factorisation and modifications after
// it against no modification. The callers compare the steps as their method defines them.
void expect_same_solve_refactorised_or_modified(const ContactProblem& problem,
                                                ContactSolverOptions o, ContactResult& refactorised,
                                                ContactResult& updated) {
  o.schur_complement = false;  // the sparse direct path
  o.linear.factor_updates = FactorUpdates::Never;
  refactorised = solve_contact(problem, o);
  o.linear.factor_updates = FactorUpdates::Always;
  updated = solve_contact(problem, o);
  ASSERT_TRUE(refactorised.summary.converged()) << refactorised.summary.message;
  ASSERT_TRUE(updated.summary.converged()) << updated.summary.message;
  EXPECT_EQ(updated.summary.path, SolvePath::SparseDirect);
  ASSERT_EQ(updated.summary.steps.size(), refactorised.summary.steps.size());
  EXPECT_LT(relative_difference(updated.u, refactorised.u), 1e-10);
  EXPECT_LT(relative_difference(updated.l, refactorised.l), 1e-9);
  EXPECT_LT(updated.summary.kkt.max(), 1e-9);
  EXPECT_EQ(total(refactorised.summary, &OuterStepRecord::factor_updates), 0);
  EXPECT_EQ(total(updated.summary, &OuterStepRecord::factorizations), 1);
  EXPECT_GT(total(updated.summary, &OuterStepRecord::factor_updates), 0);
}

void expect_updates_change_nothing(const ContactProblem& problem, const ContactSolverOptions& o) {
  ContactResult refactorised, updated;
  expect_same_solve_refactorised_or_modified(problem, o, refactorised, updated);
  if (::testing::Test::HasFatalFailure()) return;
  // The same iteration, step by step; none refactorised by "always" (every change is small
  // enough), against one factorisation per active set.
  for (std::size_t k = 0; k < updated.summary.steps.size(); ++k)
    EXPECT_EQ(updated.summary.steps[k].inner_iterations,
              refactorised.summary.steps[k].inner_iterations)
        << "Uzawa step " << k + 1;
  EXPECT_GT(total(refactorised.summary, &OuterStepRecord::factorizations), 1);
}

// Semismooth Newton on the sparse direct path (semismooth_newton_solver.cpp, rotated
// elimination): with the factor's rows modified as unknowns become fixed or free, the same
// active sets step by step and the same u and l as with a factorisation for every active set.
void expect_row_modifications_change_nothing(const ContactProblem& problem,
                                             ContactSolverOptions o) {
  o.method = ContactMethod::SemismoothNewton;
  ContactResult refactorised, updated;
  expect_same_solve_refactorised_or_modified(problem, o, refactorised, updated);
  if (::testing::Test::HasFatalFailure()) return;
  ASSERT_GE(updated.summary.steps.size(), 3U);  // active sets that change
  for (std::size_t k = 0; k < updated.summary.steps.size(); ++k)
    EXPECT_EQ(updated.summary.steps[k].active_set_size,
              refactorised.summary.steps[k].active_set_size)
        << "Newton step " << k + 1;
  EXPECT_EQ(total(refactorised.summary, &OuterStepRecord::factorizations),
            static_cast<int>(refactorised.summary.steps.size()));
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

// The solver path chosen from the problem's size and the machine's memory (solver_plan.hpp), and
// through build_model: the path a 3D problem above the threshold solves on, and its answer
// against the direct path's.

#include "signorini/problem/solver_plan.hpp"

#include <gtest/gtest.h>

#include "expect_contains.hpp"
#include "problem/ball_on_block.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

constexpr double kGB = 1e9;

TEST(SolverPlan, TwoDimensionalProblemsStayCondensedWhileTheyFit) {
  const ContactSolverOptions given;
  // The paper's 960x320 mesh: 309,123 nodes, 617,604 free unknowns, 961 contact nodes.
  const SolverPlan plan = plan_solver(given, {2, 309123, 617604, 961, 24 * kGB});
  EXPECT_EQ(plan.options.linear.type, LinearSolverType::Cholmod);
  EXPECT_TRUE(plan.options.schur_complement);
  EXPECT_CONTAINS(plan.reason,
                  "condensed direct: 961 contact nodes, a dense matrix of about 30 MB");
}

// Friction: never condensed (the condensation is onto the normal displacements); in 3D above
// the threshold Uzawa-GNM goes iterative as without friction, semismooth Newton (a sparse LU of
// the KKT system) and classical Uzawa stay direct.
TEST(SolverPlan, FrictionIsCondensedIn2DAndGoesIterativeWithUzawaGnmOnly) {
  ContactSolverOptions given;
  const SolverPlan two = plan_solver(given, {2, 309123, 617604, 961, 24 * kGB, true});
  EXPECT_TRUE(two.options.schur_complement);
  EXPECT_EQ(two.options.linear.type, LinearSolverType::Cholmod);
  // Two unknowns per contact node: four times the frictionless dense matrix (30 MB).
  EXPECT_CONTAINS(two.reason,
                  "condensed direct: 961 contact nodes with friction (every free dof of each), "
                  "a dense matrix of about 118 MB");
  const SolverPlan small3d = plan_solver(given, {3, 3000, 9000, 300, 24 * kGB, true});
  EXPECT_FALSE(small3d.options.schur_complement);
  EXPECT_CONTAINS(small3d.reason, "sparse direct: friction in 3D");
  const SolverPlan three = plan_solver(given, {3, 35000, 100000, 1681, 24 * kGB, true});
  EXPECT_EQ(three.options.linear.type, LinearSolverType::ConjugateGradient);
  given.method = ContactMethod::SemismoothNewton;
  const SolverPlan ssn = plan_solver(given, {3, 35000, 100000, 1681, 24 * kGB, true});
  EXPECT_EQ(ssn.options.linear.type, LinearSolverType::Cholmod);
  EXPECT_FALSE(ssn.options.schur_complement);
  const SolverPlan ssn2d = plan_solver(given, {2, 309123, 617604, 961, 24 * kGB, true});
  EXPECT_FALSE(ssn2d.options.schur_complement);
  EXPECT_CONTAINS(ssn2d.reason, "semismooth Newton with friction");
}

TEST(SolverPlan, ACondensedMatrixThatDoesNotFitGoesSparseDirect) {
  // 50,000 contact nodes: 32 * 50,000^2 bytes = 80 GB of dense matrices.
  const SolverPlan plan = plan_solver(ContactSolverOptions{}, {2, 400000, 800000, 50000, 24 * kGB});
  EXPECT_EQ(plan.options.linear.type, LinearSolverType::Cholmod);
  EXPECT_FALSE(plan.options.schur_complement);
  EXPECT_CONTAINS(plan.reason,
                  "sparse direct: the condensed matrix of 50,000 contact nodes "
                  "(about 80.0 GB) would exceed a quarter of the 24.0 GB");
  // Unknown memory: no memory rule.
  EXPECT_TRUE(plan_solver(ContactSolverOptions{}, {2, 400000, 800000, 50000, 0.0})
                  .options.schur_complement);
}

TEST(SolverPlan, LargeThreeDimensionalProblemsGoIterative) {
  const SolverPlan small =
      plan_solver(ContactSolverOptions{}, {3, 9000, kIterativeFromUnknowns3D, 600, 24 * kGB});
  EXPECT_EQ(small.options.linear.type, LinearSolverType::Cholmod);
  const SolverPlan large =
      plan_solver(ContactSolverOptions{}, {3, 20000, kIterativeFromUnknowns3D + 1, 900, 24 * kGB});
  EXPECT_EQ(large.options.linear.type, LinearSolverType::ConjugateGradient);
  EXPECT_EQ(large.options.linear.preconditioner, PreconditionerType::Multigrid);
  EXPECT_CONTAINS(large.reason, "iterative, CG with multigrid: 3D with 15,001 free unknowns");
  EXPECT_TRUE(uses_backend_path(large.options));
  // With it, the inexact Uzawa-GNM; the direct paths keep the exact one.
  EXPECT_EQ(large.options.inner_tolerance, InnerTolerance::Adaptive);
  EXPECT_FALSE(small.options.adaptive_inner_tolerance());
  ContactSolverOptions fixed;
  fixed.inner_tolerance = InnerTolerance::Fixed;
  EXPECT_EQ(plan_solver(fixed, {3, 20000, kIterativeFromUnknowns3D + 1, 900, 24 * kGB})
                .options.inner_tolerance,
            InnerTolerance::Fixed);
}

TEST(SolverPlan, EachMethodGoesWhereItRuns) {
  // Semismooth Newton runs on the iterative path too (projected CG); classical Uzawa needs the
  // factor of A, so it stays direct.
  const ProblemSize large{3, 20000, kIterativeFromUnknowns3D + 1, 900, 24 * kGB};
  ContactSolverOptions ssn;
  ssn.method = ContactMethod::SemismoothNewton;
  EXPECT_TRUE(uses_backend_path(plan_solver(ssn, large).options));
  EXPECT_NO_THROW(validate(plan_solver(ssn, large).options));
  ContactSolverOptions classical;
  classical.method = ContactMethod::ClassicalUzawa;
  const SolverPlan plan = plan_solver(classical, large);
  EXPECT_EQ(plan.options.linear.type, LinearSolverType::Cholmod);
  EXPECT_NO_THROW(validate(plan.options));
}

TEST(SolverPlan, AFactorThatDoesNotFitGoesIterativeIn2D) {
  // 4 KB per node: 4 million nodes, 16 GB, more than half of 24 GB.
  const SolverPlan plan =
      plan_solver(ContactSolverOptions{}, {2, 4000000, 8000000, 4000, 24 * kGB});
  EXPECT_EQ(plan.options.linear.type, LinearSolverType::ConjugateGradient);
  EXPECT_CONTAINS(plan.reason, "a sparse factor of about 16.4 GB would exceed half of the 24.0 GB");
}

TEST(SolverPlan, WhatTheUserChoseStays) {
  ContactSolverOptions off;
  off.automatic_path = false;
  SolverPlan plan = plan_solver(off, {3, 1000000, 3000000, 20000, 24 * kGB});
  EXPECT_EQ(plan.options.linear.type, LinearSolverType::Cholmod);
  EXPECT_TRUE(plan.options.schur_complement);
  EXPECT_EQ(plan.reason, "as configured (automatic_path = false)");

  ContactSolverOptions cg;
  cg.linear.type = LinearSolverType::ConjugateGradient;  // the paper's Jacobi CG
  plan = plan_solver(cg, {3, 1000000, 3000000, 20000, 24 * kGB});
  EXPECT_EQ(plan.options.linear.preconditioner, PreconditionerType::Jacobi);
  EXPECT_EQ(plan.reason, "as configured (linear.type = \"cg\")");

  ContactSolverOptions plain;
  plain.schur_complement = false;
  plan = plan_solver(plain, {2, 1000, 2000, 50, 24 * kGB});
  EXPECT_FALSE(plan.options.schur_complement);
  EXPECT_EQ(plan.reason, "as configured (schur_complement = false)");
}

// Through build_model: a ball pressed into a block of 35,322 free unknowns is planned onto CG
// with multigrid (its hierarchy built), and solves to the direct path's answer.
TEST(SolverPlan, BuildModelPlansAndBuildsTheHierarchy) {
  ProblemSpec spec = testing::ball_on_block(28, 4e-3);
  spec.solver.uzawa_tolerance = 1e-10;
  const Model model = build_model(spec);
  ASSERT_GT(model.dofs.num_free(), kIterativeFromUnknowns3D);
  EXPECT_EQ(model.solver.linear.type, LinearSolverType::ConjugateGradient);
  EXPECT_FALSE(model.multigrid.prolongations.empty());
  EXPECT_CONTAINS(model.solver_reason, "iterative");
  const ContactResult iterative = solve_contact(model.problem, model.solver, &model.multigrid);
  ASSERT_TRUE(iterative.summary.converged()) << iterative.summary.brief_report();
  EXPECT_EQ(iterative.summary.path, SolvePath::Backend);
  EXPECT_GT(iterative.summary.num_active, 0);

  spec.solver.automatic_path = false;
  const Model direct_model = build_model(spec);
  EXPECT_EQ(direct_model.solver.linear.type, LinearSolverType::Cholmod);
  EXPECT_TRUE(direct_model.multigrid.prolongations.empty());
  const ContactResult direct = solve_contact(direct_model.problem, direct_model.solver);
  EXPECT_EQ(direct.summary.path, SolvePath::CondensedDirect);
  EXPECT_EQ(direct.summary.num_active, iterative.summary.num_active);
  EXPECT_LT((direct.l - iterative.l).norm(), 1e-7 * direct.l.norm());
  EXPECT_LT((direct.u - iterative.u).norm(), 1e-7 * direct.u.norm());
}

}  // namespace
}  // namespace signorini

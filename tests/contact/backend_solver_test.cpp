// The backend path of the paper's method (docs/gpu.md) on the CPU backend: Uzawa-GNM with its
// Newton systems solved by conjugate gradients (multigrid V-cycle or Jacobi), compared with the
// direct CHOLMOD solve of the same discrete problem: the same energies to 1e-8, the same Uzawa
// and first-step GNM counts (Table 1), the same u and l.

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

class BackendPath : public ::testing::TestWithParam<Index> {};

TEST_P(BackendPath, MultigridCgMatchesTheDirectSolve) {
  const Index nx = GetParam();
  const ContactProblem p = testing::paper_problem_with_hierarchy(nx);
  const ContactResult direct = solve_contact(p, ContactSolverOptions{});
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  ASSERT_TRUE(uses_backend_path(o));
  const ContactResult it = solve_contact(p, o);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  EXPECT_NEAR(it.summary.lagrangian, direct.summary.lagrangian,
              1e-8 * std::abs(direct.summary.lagrangian));
  EXPECT_EQ(it.summary.outer_iterations, direct.summary.outer_iterations);
  EXPECT_EQ(it.summary.inner_iterations().front(), direct.summary.inner_iterations().front());
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-8);
  EXPECT_LT(testing::relative_difference(it.l, direct.l), 1e-7);
  EXPECT_LT(it.summary.kkt.max(), 1e-7);
  EXPECT_FALSE(it.summary.device.empty());
  EXPECT_EQ(it.summary.multigrid_levels.front(), p.A.rows());
  // A few V-cycles per Newton system, nearly independent of the mesh.
  int linear = 0, systems = 0;
  for (const OuterStepRecord& s : it.summary.steps) {
    linear += s.linear_iterations;
    systems += s.inner_iterations;
  }
  EXPECT_LE(linear, 40 * systems) << linear << " CG iterations for " << systems << " GNM steps";
}

INSTANTIATE_TEST_SUITE_P(Paper, BackendPath, ::testing::Values(60, 120, 240),
                         [](const auto& param_info) {
                           return std::to_string(param_info.param) + "x" +
                                  std::to_string(param_info.param / 3);
                         });

TEST(BackendPathAggregation, MeshesThatDoNotHalveGetAggregationAndMatchTheDirectSolve) {
  // 61x21 cannot be halved: "auto" coarsening falls back to smoothed aggregation; "geometric"
  // is refused with a message naming the key and the mesh.
  ProblemSpec spec = paper_benchmark(61, 21);
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  const Model model = build_model(spec);
  ASSERT_EQ(model.problem.hierarchy, HierarchyKind::Aggregation);
  ASSERT_FALSE(model.problem.prolongations.empty());
  const ContactResult it = solve_contact(model.problem, spec.solver);
  ContactSolverOptions direct_options;
  const ContactResult direct = solve_contact(model.problem, direct_options);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  EXPECT_NEAR(it.summary.lagrangian, direct.summary.lagrangian,
              1e-8 * std::abs(direct.summary.lagrangian));
  EXPECT_EQ(it.summary.outer_iterations, direct.summary.outer_iterations);
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-8);
  EXPECT_LT(it.summary.kkt.max(), 1e-7);
  EXPECT_EQ(it.summary.multigrid_hierarchy, HierarchyKind::Aggregation);
  EXPECT_GE(it.summary.multigrid_levels.size(), 2U);

  spec.solver.linear.coarsening = MultigridCoarsening::Geometric;
  try {
    (void)build_model(spec);
    ADD_FAILURE() << "geometric coarsening of a 61x21 mesh was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.linear.coarsening"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("61x21"), std::string::npos) << e.what();
  }
  // An even mesh takes the geometric levels under "auto".
  spec = paper_benchmark(60, 20);
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  EXPECT_EQ(build_model(spec).problem.hierarchy, HierarchyKind::Geometric);
  spec.solver.linear.coarsening = MultigridCoarsening::Aggregation;
  EXPECT_EQ(build_model(spec).problem.hierarchy, HierarchyKind::Aggregation);
  // 122x40 halves once, to 61x20: too large a coarsest level for the dense solve, so "auto"
  // continues with aggregation from there; "geometric" is refused.
  spec = paper_benchmark(122, 40);
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  const Model mixed = build_model(spec);
  EXPECT_EQ(mixed.problem.hierarchy, HierarchyKind::GeometricThenAggregation);
  ASSERT_GE(mixed.problem.prolongations.size(), 2U);
  EXPECT_EQ(mixed.problem.coarse_operators.size(), mixed.problem.prolongations.size());
  EXPECT_LE(mixed.problem.coarse_operators.back().rows(), 2000);
  const ContactResult mixed_solve = solve_contact(mixed.problem, spec.solver);
  const ContactResult mixed_direct = solve_contact(mixed.problem, ContactSolverOptions{});
  ASSERT_TRUE(mixed_solve.summary.converged()) << mixed_solve.summary.message;
  EXPECT_NEAR(mixed_solve.summary.lagrangian, mixed_direct.summary.lagrangian,
              1e-8 * std::abs(mixed_direct.summary.lagrangian));
  EXPECT_EQ(mixed_solve.summary.multigrid_hierarchy, HierarchyKind::GeometricThenAggregation);
  spec.solver.linear.coarsening = MultigridCoarsening::Geometric;
  try {
    (void)build_model(spec);
    ADD_FAILURE() << "geometric coarsening of 122x40 down to 61x20 only was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("halves only down to 61x20"), std::string::npos)
        << e.what();
  }
}

TEST(BackendPathJacobi, PaperConfigurationMatchesTheDirectSolve) {
  // The paper's CG with Jacobi (tolerance 1e-13), here on the CPU backend; with
  // solver.device = "cuda" the same code runs on the GPU.
  const ContactProblem& p = testing::paper_model(60).problem;
  const ContactResult direct = solve_contact(p, ContactSolverOptions{});
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  const ContactResult it = solve_uzawa_gnm_on_backend(p, o);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-8);
  EXPECT_EQ(it.summary.steps.size(), direct.summary.steps.size());
  EXPECT_TRUE(it.summary.multigrid_levels.empty());
}

TEST(BackendPathOptions, RefusesWhatItCannotRun) {
  ContactSolverOptions o;
  o.device = DeviceKind::Cuda;  // with the default direct solver
  EXPECT_THROW(validate(o), InputError);
  try {
    validate(o);
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.linear.type = \"cg\""), std::string::npos)
        << e.what();
  }
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.method = ContactMethod::SemismoothNewton;
  EXPECT_THROW(validate(o), InputError);
  o.method = ContactMethod::UzawaGnm;
  EXPECT_NO_THROW(validate(o));
  o.linear.chebyshev_degree = 0;
  EXPECT_THROW(validate(o), InputError);
}

TEST(BackendPathMultigrid, WithoutHierarchyStillConvergesToTheSameSolution) {
  // No prolongations (an odd mesh): the "multigrid" is Chebyshev smoothing alone.
  const Model model = build_model(paper_benchmark(21, 7));
  const ContactResult direct = solve_contact(model.problem, ContactSolverOptions{});
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  const ContactResult it = solve_contact(model.problem, o);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-8);
  EXPECT_EQ(it.summary.multigrid_levels.size(), 1U);
}

}  // namespace
}  // namespace signorini

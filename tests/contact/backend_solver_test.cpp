// The backend path of the paper's method (docs/gpu.md) on the CPU backend: Uzawa-GNM with its
// Newton systems solved by conjugate gradients (multigrid V-cycle or Jacobi), compared with the
// direct CHOLMOD solve of the same discrete problem: the same energies to 1e-8, the same Uzawa
// and first-step GNM counts (Table 1), the same u and l.

#include <gtest/gtest.h>

#include "signorini/contact/contact_methods.hpp"
#include "signorini/contact/method_table.hpp"
#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

class BackendPath : public ::testing::TestWithParam<Index> {};

TEST_P(BackendPath, MultigridCgMatchesTheDirectSolve) {
  const Index nx = GetParam();
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(nx);
  const ContactResult direct = solve_contact(p, ContactSolverOptions{});
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  ASSERT_TRUE(uses_backend_path(o));
  const ContactResult it = solve_contact(p, o, &multigrid);
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

// Inexact Uzawa-GNM (inner_tolerance = adaptive): each Uzawa step minimised to a hundredth of
// the previous step's dual change, each Newton system to a tenth of that. The same solution as
// the exact method to the Uzawa tolerance, with far fewer CG iterations.
TEST_P(BackendPath, AdaptiveInnerToleranceGivesTheSameSolutionWithFewerCgIterations) {
  const Index nx = GetParam();
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(nx);
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  o.inner_tolerance = InnerTolerance::Fixed;
  const ContactResult exact = solve_contact(p, o, &multigrid);
  o.inner_tolerance = InnerTolerance::Adaptive;
  const ContactResult inexact = solve_contact(p, o, &multigrid);
  ASSERT_TRUE(exact.summary.converged()) << exact.summary.message;
  ASSERT_TRUE(inexact.summary.converged()) << inexact.summary.message;
  EXPECT_LT(testing::relative_difference(inexact.u, exact.u), 1e-8);
  EXPECT_LT(testing::relative_difference(inexact.l, exact.l), 1e-7);
  EXPECT_EQ(inexact.summary.num_active, exact.summary.num_active);
  EXPECT_LT(inexact.summary.kkt.max(), 1e-7);
  int cg_exact = 0, cg_inexact = 0;
  for (const OuterStepRecord& s : exact.summary.steps) cg_exact += s.linear_iterations;
  for (const OuterStepRecord& s : inexact.summary.steps) cg_inexact += s.linear_iterations;
  EXPECT_LT(2 * cg_inexact, cg_exact) << cg_inexact << " against " << cg_exact;
  // Auto is the exact method unless build_model plans the iterative path.
  o.inner_tolerance = InnerTolerance::Auto;
  const ContactResult automatic = solve_contact(p, o, &multigrid);
  EXPECT_EQ(automatic.summary.inner_iterations(), exact.summary.inner_iterations());
}

INSTANTIATE_TEST_SUITE_P(Paper, BackendPath, ::testing::Values(60, 120, 240),
                         [](const auto& param_info) {
                           return std::to_string(param_info.param) + "x" +
                                  std::to_string(param_info.param / 3);
                         });

// The paper's benchmark on nx x ny with multigrid CG and the given coarsening.
ProblemSpec multigrid_spec(Index nx, Index ny, MultigridCoarsening coarsening) {
  ProblemSpec spec = paper_benchmark(nx, ny);
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.linear.coarsening = coarsening;
  return spec;
}

// build_model's InputError message ("" if it builds).
std::string model_error(const ProblemSpec& spec) {
  try {
    (void)build_model(spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Multigrid CG on the backend path against the direct solve of the same model.
void expect_matches_the_direct_solve(const ProblemSpec& spec, HierarchyKind kind) {
  const Model model = build_model(spec);
  ASSERT_EQ(model.multigrid.kind, kind);
  ASSERT_FALSE(model.multigrid.prolongations.empty());
  const ContactResult it = solve_contact(model.problem, spec.solver, &model.multigrid);
  ContactSolverOptions direct_options;  // CHOLMOD, condensed, with the same r
  direct_options.r = spec.solver.r;
  const ContactResult direct = solve_contact(model.problem, direct_options);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  EXPECT_NEAR(it.summary.lagrangian, direct.summary.lagrangian,
              1e-8 * std::abs(direct.summary.lagrangian));
  EXPECT_EQ(it.summary.outer_iterations, direct.summary.outer_iterations);
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-8);
  EXPECT_LT(it.summary.kkt.max(), 1e-7);
  EXPECT_EQ(it.summary.multigrid_hierarchy, kind);
  EXPECT_GE(it.summary.multigrid_levels.size(), 2U);
}

TEST(BackendPathCoarsening, AMeshThatDoesNotHalveGetsAggregationAndMatchesTheDirectSolve) {
  expect_matches_the_direct_solve(multigrid_spec(61, 21, MultigridCoarsening::Auto),
                                  HierarchyKind::Aggregation);
  const std::string error = model_error(multigrid_spec(61, 21, MultigridCoarsening::Geometric));
  EXPECT_NE(error.find("solver.linear.coarsening = \"geometric\""), std::string::npos) << error;
  EXPECT_NE(error.find("61x21"), std::string::npos) << error;
}

TEST(BackendPathCoarsening, AMeshThatHalvesTooLittleGetsAggregationBelowItsGeometricLevels) {
  // 122x40 halves once, to 61x20: above the dense coarsest solve's 2,000 unknowns, so "auto"
  // continues from there by aggregation, and "geometric" alone is refused.
  const ProblemSpec spec = multigrid_spec(122, 40, MultigridCoarsening::Auto);
  const Model model = build_model(spec);
  EXPECT_EQ(model.multigrid.coarse_operators.size(), model.multigrid.prolongations.size());
  EXPECT_EQ(model.multigrid.prolongations.front().cols(),
            build_model(multigrid_spec(61, 20, MultigridCoarsening::Auto)).dofs.num_free());
  EXPECT_LE(model.multigrid.coarse_operators.back().rows(), 2000);
  expect_matches_the_direct_solve(spec, HierarchyKind::GeometricThenAggregation);
  EXPECT_NE(model_error(multigrid_spec(122, 40, MultigridCoarsening::Geometric))
                .find("halves only down to 61x20"),
            std::string::npos);
}

TEST(BackendPathCoarsening, EvenMeshesTakeTheGeometricLevelsUnlessAggregationIsAsked) {
  EXPECT_EQ(build_model(multigrid_spec(60, 20, MultigridCoarsening::Auto)).multigrid.kind,
            HierarchyKind::Geometric);
  EXPECT_EQ(build_model(multigrid_spec(60, 20, MultigridCoarsening::Aggregation)).multigrid.kind,
            HierarchyKind::Aggregation);
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
  o.method = ContactMethod::ClassicalUzawa;
  // (The options alone are valid; the path they take refuses them: method_table.hpp.)
  EXPECT_NO_THROW(validate(o));
  EXPECT_THROW(validate_path(o, nullptr), InputError);
  EXPECT_THROW((void)solve_contact(testing::paper_model(30).problem, o), InputError);
  o.method = ContactMethod::SemismoothNewton;  // projected CG (projected_active_set_solver.hpp)
  EXPECT_NO_THROW(validate(o));
  o.method = ContactMethod::UzawaGnm;
  EXPECT_NO_THROW(validate(o));
  o.linear.chebyshev_degree = 0;
  EXPECT_THROW(validate(o), InputError);
}

// Semismooth Newton on the backend path: each Newton step by projected CG with the geometric
// multigrid of the penalised Newton matrix. The same active sets as with the sparse
// factorisation, step by step, and the same solution to the CG tolerance.
TEST(BackendPathSemismoothNewton, MatchesTheSparseDirectSteps) {
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(120);
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  o.schur_complement = false;
  const ContactResult direct = solve_contact(p, o);
  ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  ASSERT_TRUE(uses_backend_path(o));
  const ContactResult it = solve_contact(p, o, &multigrid);
  ASSERT_TRUE(it.summary.converged()) << it.summary.message;
  ASSERT_EQ(it.summary.steps.size(), direct.summary.steps.size());
  for (std::size_t k = 0; k < it.summary.steps.size(); ++k)
    EXPECT_EQ(it.summary.steps[k].active_set_size, direct.summary.steps[k].active_set_size) << k;
  EXPECT_EQ(it.summary.num_active, direct.summary.num_active);
  EXPECT_LT(testing::relative_difference(it.u, direct.u), 1e-10);
  EXPECT_LT(testing::relative_difference(it.l, direct.l), 1e-9);
  EXPECT_LT(it.summary.kkt.max(), 1e-11);
  EXPECT_EQ(it.summary.multigrid_levels.front(), p.A.rows());
  // A warm start from the answer: one Newton step, whose active set repeats.
  ContactSolver warm(p, o, &multigrid);
  warm.warm_start(it);
  const ContactResult again = warm.solve();
  ASSERT_TRUE(again.summary.converged()) << again.summary.message;
  EXPECT_EQ(again.summary.steps.size(), 1U);
  EXPECT_LT(testing::relative_difference(again.u, it.u), 1e-10);
}

// The projection onto the constraints is local only where each dof is in one contact row.
TEST(BackendPathSemismoothNewton, RefusesContactRowsThatShareADof) {
  const auto [problem, multigrid] = testing::paper_problem_with_hierarchy(60);
  ContactProblem p = problem;
  SparseMatrix& N = p.contact.N;
  ASSERT_GE(N.rows(), 2);
  // The first dof with a nonzero entry (N stores the normals' zeros too), given to another row.
  Index row = -1, dof = -1;
  for (Index k = 0; k < N.outerSize() && dof < 0; ++k)
    for (SparseMatrix::InnerIterator it(N, k); it; ++it)
      if (it.value() != 0.0) {
        row = it.row();
        dof = k;
      }
  ASSERT_GE(dof, 0);
  N.coeffRef(row == 0 ? 1 : 0, dof) = 0.5;
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  try {
    (void)solve_contact(p, o, &multigrid);
    ADD_FAILURE() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("share a degree of freedom"), std::string::npos)
        << e.what();
  }
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

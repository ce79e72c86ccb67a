// The GPU solve of the paper's method (solver.device = "cuda", docs/gpu.md) against the CPU on
// the Table 1 meshes: energies to 1e-8 relative, the same Uzawa counts and first-step GNM counts,
// u and l to 1e-8 / 1e-7. Skipped, saying so, where no CUDA GPU is usable.

#include <gtest/gtest.h>

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/contact/contact_methods.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

#define SKIP_WITHOUT_GPU()                                                      \
  do {                                                                          \
    const CudaReport report = cuda_report();                                    \
    if (report.gpus.empty()) GTEST_SKIP() << "no CUDA GPU: " << report.problem; \
  } while (false)

class GpuSolve : public ::testing::TestWithParam<std::tuple<Index, PreconditionerType>> {};

TEST_P(GpuSolve, MatchesTheCpuDirectSolve) {
  SKIP_WITHOUT_GPU();
  const auto [nx, preconditioner] = GetParam();
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(nx);
  const ContactResult cpu = solve_contact(p, ContactSolverOptions{});
  ContactSolverOptions o;
  o.device = DeviceKind::Cuda;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = preconditioner;
  const ContactResult gpu = solve_contact(p, o, &multigrid);
  ASSERT_TRUE(gpu.summary.converged()) << gpu.summary.message;
  EXPECT_NEAR(gpu.summary.lagrangian, cpu.summary.lagrangian,
              1e-8 * std::abs(cpu.summary.lagrangian));
  EXPECT_NEAR(gpu.summary.energy, cpu.summary.energy, 1e-8 * std::abs(cpu.summary.energy));
  EXPECT_EQ(gpu.summary.outer_iterations, cpu.summary.outer_iterations);
  EXPECT_EQ(gpu.summary.inner_iterations().front(), cpu.summary.inner_iterations().front());
  EXPECT_LT(testing::relative_difference(gpu.u, cpu.u), 1e-8);
  EXPECT_LT(testing::relative_difference(gpu.l, cpu.l), 1e-7);
  EXPECT_NE(gpu.summary.device.find("sm_"), std::string::npos) << gpu.summary.device;
}

TEST(GpuSolveAggregation, AMeshThatDoesNotHalveMatchesTheCpuDirectSolve) {
  SKIP_WITHOUT_GPU();
  ProblemSpec spec = paper_benchmark(121, 41);  // smoothed-aggregation levels ("auto")
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.device = DeviceKind::Cuda;
  const Model model = build_model(spec);
  ASSERT_EQ(model.multigrid.kind, HierarchyKind::Aggregation);
  ContactSolverOptions direct;  // CHOLMOD, condensed, with the same r (the paper's)
  direct.r = spec.solver.r;
  const ContactResult cpu = solve_contact(model.problem, direct);
  const ContactResult gpu = solve_contact(model.problem, spec.solver, &model.multigrid);
  ASSERT_TRUE(gpu.summary.converged()) << gpu.summary.message;
  EXPECT_NEAR(gpu.summary.lagrangian, cpu.summary.lagrangian,
              1e-8 * std::abs(cpu.summary.lagrangian));
  EXPECT_EQ(gpu.summary.outer_iterations, cpu.summary.outer_iterations);
  EXPECT_LT(testing::relative_difference(gpu.u, cpu.u), 1e-8);
  EXPECT_EQ(gpu.summary.multigrid_hierarchy, HierarchyKind::Aggregation);
}

TEST_P(GpuSolve, MatchesTheSameAlgorithmOnTheCpuBackend) {
  SKIP_WITHOUT_GPU();
  const auto [nx, preconditioner] = GetParam();
  const auto [p, multigrid] = testing::paper_problem_with_hierarchy(nx);
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = preconditioner;
  const ContactResult host = solve_uzawa_gnm_on_backend(p, o, {}, &multigrid);
  o.device = DeviceKind::Cuda;
  const ContactResult gpu = solve_uzawa_gnm_on_backend(p, o, {}, &multigrid);
  ASSERT_EQ(gpu.summary.steps.size(), host.summary.steps.size());
  for (std::size_t k = 0; k < host.summary.steps.size(); ++k)
    EXPECT_EQ(gpu.summary.steps[k].inner_iterations, host.summary.steps[k].inner_iterations) << k;
  EXPECT_LT(testing::relative_difference(gpu.u, host.u), 1e-9);
}

INSTANTIATE_TEST_SUITE_P(Table1, GpuSolve,
                         ::testing::Values(std::tuple{Index{60}, PreconditionerType::Multigrid},
                                           std::tuple{Index{120}, PreconditionerType::Multigrid},
                                           std::tuple{Index{240}, PreconditionerType::Multigrid},
                                           std::tuple{Index{60}, PreconditionerType::Jacobi}),
                         [](const auto& param_info) {
                           const Index nx = std::get<0>(param_info.param);
                           return std::to_string(nx) + "x" + std::to_string(nx / 3) + "_" +
                                  std::string(enum_to_string(kPreconditionerTypeNames,
                                                             std::get<1>(param_info.param)));
                         });

}  // namespace
}  // namespace signorini

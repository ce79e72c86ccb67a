// Friction on a GPU (docs/gpu.md): Uzawa-GNM with Coulomb's law on the CUDA backend against the
// same algorithm on the CPU backend, in 2D (the active rows of N as weights, as frictionless
// contact has them) and in 3D (the nodes' coupled 3 x 3 blocks W, a sparse matrix multiplied on
// the device): the same Uzawa steps, u to 1e-9 and the tangential forces to 1e-8. Skipped,
// saying so, where no CUDA GPU is usable.

#include <gtest/gtest.h>

#include "problem/ball_on_block.hpp"
#include "signorini/backend/cuda_backend.hpp"
#include "signorini/problem/model.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

TEST(GpuFriction, CoulombMatchesTheCpuBackendIn2DAnd3D) {
  const CudaReport report = cuda_report();
  if (report.gpus.empty()) GTEST_SKIP() << "no CUDA GPU: " << report.problem;
  for (const bool three_d : {false, true}) {
    SCOPED_TRACE(three_d ? "3D" : "2D");
    ProblemSpec spec =
        testing::with_friction(three_d ? testing::ball_on_block(12, 3e-2) : paper_benchmark(60, 20),
                               FrictionModel::Coulomb, three_d ? 0.2 : 0.5);
    spec.solver.automatic_path = false;
    spec.solver.linear.type = LinearSolverType::ConjugateGradient;
    spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
    spec.solver.linear.cg_tolerance = 1e-13;
    spec.solver.inner_tolerance = InnerTolerance::Fixed;
    spec.solver.uzawa_tolerance = 1e-11;
    const Model model = build_model(spec);
    ContactSolverOptions o = model.solver;
    ASSERT_NE(model.problem.law, nullptr);
    o.device = DeviceKind::Cpu;
    const ContactResult cpu = solve_contact(model.problem, o, &model.multigrid);
    o.device = DeviceKind::Cuda;
    const ContactResult gpu = solve_contact(model.problem, o, &model.multigrid);
    ASSERT_TRUE(cpu.summary.converged()) << cpu.summary.message;
    ASSERT_TRUE(gpu.summary.converged()) << gpu.summary.message;
    EXPECT_EQ(gpu.summary.path, SolvePath::Backend);
    EXPECT_EQ(gpu.summary.outer_iterations, cpu.summary.outer_iterations);
    EXPECT_LT(testing::relative_difference(gpu.u, cpu.u), 1e-9);
    EXPECT_LT(testing::relative_difference(gpu.tangential.reshaped(), cpu.tangential.reshaped()),
              1e-8);
    EXPECT_GT(cpu.tangential.cwiseAbs().maxCoeff(), 0.0);
    EXPECT_NE(gpu.summary.device.find("sm_"), std::string::npos) << gpu.summary.device;
  }
}

}  // namespace
}  // namespace signorini

// The multigrid V-cycle on the GPU (docs/gpu.md) against the same cycle on the CPU backend, with
// the geometric and the smoothed-aggregation hierarchies: the same preconditioned residual, a
// cycle captured as one CUDA graph, and CG that reaches CHOLMOD's solution. Built into
// signorini_gpu_tests (label gpu); skipped, saying why, without a usable GPU.

#include <gtest/gtest.h>

#include "signorini/backend/cuda_backend.hpp"
#include "signorini/backend/host_backend.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/pcg.hpp"
#include "signorini/linalg/cholmod_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

class GpuMultigrid
    : public ::testing::TestWithParam<std::tuple<Index, MultigridCoarsening, HierarchyKind>> {};

TEST_P(GpuMultigrid, CycleAndCgMatchTheCpu) {
  const CudaReport report = cuda_report();
  if (report.gpus.empty()) GTEST_SKIP() << "no CUDA GPU: " << report.problem;
  const auto [nx, coarsening, kind] = GetParam();
  ProblemSpec spec = paper_benchmark(nx, nx / 3);
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.linear.coarsening = coarsening;
  const Model model = build_model(spec);
  const ContactProblem& p = model.problem;
  const MultigridHierarchy& h = model.multigrid;
  ASSERT_EQ(h.kind, kind);
  const Vector c = 1e8 * p.contact.weights;  // every contact node active

  HostBackend host;
  const auto gpu = make_cuda_backend(report.gpus.front().ordinal);
  PenalizedOperator host_op(host, p.A, p.contact.N), gpu_op(*gpu, p.A, p.contact.N);
  host_op.set_weights(c);
  gpu_op.set_weights(c);
  MultigridPreconditioner host_mg(host_op, p.A, p.contact.N, h.prolongations, {},
                                  h.coarse_operators);
  MultigridPreconditioner gpu_mg(gpu_op, p.A, p.contact.N, h.prolongations, {}, h.coarse_operators);
  EXPECT_EQ(gpu_mg.level_sizes(), host_mg.level_sizes());

  const DeviceVector hb = to_device(host, p.b), gb = to_device(*gpu, p.b);
  DeviceVector hz(host, host_op.size()), gz(*gpu, gpu_op.size());
  host_mg.apply(hb, hz);
  gpu_mg.apply(gb, gz);
  gpu_mg.apply(gb, gz);  // the replay of the recorded cycle gives the same
  const Vector zh = to_host(hz), zg = to_host(gz);
  EXPECT_LT((zg - zh).norm(), 1e-9 * zh.norm());
  ASSERT_NE(gpu_mg.recorded_cycle(), nullptr);
  EXPECT_TRUE(gpu_mg.recorded_cycle()->is_graph()) << gpu_mg.recorded_cycle()->why_not_graph();

  Pcg pcg(*gpu, gpu_op.size());
  PcgOptions o;
  o.tolerance = 1e-12;
  DeviceVector x(*gpu, gpu_op.size());
  const PcgResult r = pcg.solve(gpu_op, gpu_mg, gb, x, o);
  ASSERT_TRUE(r.converged) << r.iterations;
  const SparseMatrix H =
      SparseMatrix(p.A + SparseMatrix(p.contact.N.transpose() * c.asDiagonal() * p.contact.N));
  CholmodSolver chol;
  chol.analyze(H);
  chol.factorize(H);
  Vector exact;
  chol.solve(p.b, exact);
  EXPECT_LT((to_host(x) - exact).norm(), 1e-8 * exact.norm());
}

INSTANTIATE_TEST_SUITE_P(
    Hierarchies, GpuMultigrid,
    ::testing::Values(
        std::tuple{Index{120}, MultigridCoarsening::Geometric, HierarchyKind::Geometric},
        std::tuple{Index{121}, MultigridCoarsening::Auto, HierarchyKind::Aggregation},
        std::tuple{Index{240}, MultigridCoarsening::Aggregation, HierarchyKind::Aggregation},
        std::tuple{Index{122}, MultigridCoarsening::Auto, HierarchyKind::GeometricThenAggregation}),
    [](const auto& param_info) {
      std::string name(enum_to_string(kHierarchyKindNames, std::get<2>(param_info.param)));
      if (name.find('+') != std::string::npos) name = "mixed";
      return name + std::to_string(std::get<0>(param_info.param));
    });

}  // namespace
}  // namespace signorini

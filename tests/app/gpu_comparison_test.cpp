// The GPU comparison of `signorini bench --device cuda` (app/gpu_comparison.cpp) on rows made by
// hand: which CPU row each GPU row is compared with, the ratios, and the largest mesh choice.
// (The rows of a real run come from a GPU; these check the table's arithmetic and matching.)

#include "gpu_comparison.hpp"

#include <gtest/gtest.h>

#include "expect_contains.hpp"

namespace signorini::app {
namespace {

BenchmarkRow row(Index nx, const std::string& configuration, DeviceKind device, double contact,
                 double energy) {
  BenchmarkRow r;
  r.nx = nx;
  r.ny = nx / 3;
  r.configuration = configuration;
  r.device_kind = device;
  r.linear =
      device == DeviceKind::Cuda ? LinearSolverType::ConjugateGradient : LinearSolverType::Cholmod;
  r.t_contact = contact;
  r.t_total = contact + 0.5;
  r.energy = energy;
  r.n_dofs = 2 * (nx + 1) * (nx / 3 + 1);
  r.paper = paper_table1_row(r.nx, r.ny);
  return r;
}

TEST(GpuComparison, ComparesEachGpuRowWithTheCpuReferenceOfItsMesh) {
  std::vector<BenchmarkRow> rows;
  rows.push_back(row(480, "uzawa_gnm/cholmod+schur", DeviceKind::Cpu, 0.66, -6.7157449e-05));
  rows.push_back(row(960, "uzawa_gnm/cholmod+schur", DeviceKind::Cpu, 3.6, -6.7159825e-05));
  BenchmarkRow g480 =
      row(480, "uzawa_gnm/cg+multigrid@cuda", DeviceKind::Cuda, 0.165, -6.7157449e-05 * (1 + 2e-9));
  g480.preconditioner = PreconditionerType::Multigrid;
  g480.device = "NVIDIA H100 80GB HBM3 (sm_90, 79.1 GiB)";
  g480.linear_iterations = 225;
  rows.push_back(g480);
  BenchmarkRow cpu_mg = row(480, "uzawa_gnm/cg+multigrid", DeviceKind::Cpu, 1.79, -6.7157449e-05);
  cpu_mg.linear = LinearSolverType::ConjugateGradient;
  cpu_mg.preconditioner = PreconditionerType::Multigrid;
  rows.push_back(cpu_mg);
  rows.push_back(row(7680, "uzawa_gnm/cg+multigrid@cuda", DeviceKind::Cuda, 20.0, -6.7e-05));
  rows.back().preconditioner = PreconditionerType::Multigrid;

  const std::string t = gpu_comparison_table(rows);
  EXPECT_CONTAINS(t, "GPU: NVIDIA H100 80GB HBM3");
  // 480x160: 0.66 / 0.165 = 4.00, the paper's 480.60 and 38.06 s, dM/M = 2e-9.
  EXPECT_CONTAINS(t, "4.00");
  EXPECT_CONTAINS(t, "480.60");
  EXPECT_CONTAINS(t, "38.06");
  EXPECT_CONTAINS(t, "2.0e-09");
  // The same algorithm on the CPU backend: 1.79 / 0.165 = 10.85.
  EXPECT_CONTAINS(t, "same algorithm on the CPU: 1.790 s, CPU/GPU 10.85");
  // 7680x2560 has no CPU reference: its ratio is "-", and no CPU row is invented.
  const auto line = t.substr(t.find("7680x2560"));
  EXPECT_EQ(line.find("same algorithm"), std::string::npos) << line;
  EXPECT_NE(line.substr(0, line.find('\n')).find(" - "), std::string::npos) << line;
  // CPU rows are not GPU rows.
  EXPECT_EQ(t.find("960x320"), std::string::npos);
}

TEST(GpuComparison, LargestMeshFitsTheMemoryAndTheIndexLimit) {
  // 575 bytes per unknown (measured on the CPU backend) in 16 GiB: 0.85 * 16 GiB / 575 = 25.4 M
  // unknowns at most.
  const double gib = 1073741824.0;
  const Index nx = largest_paper_mesh_nx(575.0, 16 * gib);
  EXPECT_EQ(nx % 480, 0);
  EXPECT_LE(paper_mesh_unknowns(nx) * 575.0, 0.85 * 16 * gib);
  EXPECT_GT(paper_mesh_unknowns(nx + 480) * 575.0, 0.85 * 16 * gib);
  // On 141 GiB the 2^31 nonzeros of 32-bit indices bind first.
  const Index big = largest_paper_mesh_nx(575.0, 141 * gib);
  EXPECT_LT(paper_mesh_unknowns(big) * 18.0, 2147483647.0);
  EXPECT_GT(paper_mesh_unknowns(big + 480) * 18.0, 2147483647.0 - 1e9);
  EXPECT_EQ(largest_paper_mesh_nx(1e12, gib), 480);  // never below the paper's finest mesh
}

}  // namespace
}  // namespace signorini::app

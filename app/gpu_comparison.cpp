#include "gpu_comparison.hpp"

#include <fmt/format.h>

#include <cmath>

#include "timing_report.hpp"

namespace signorini::app {

namespace {

const BenchmarkRow* find_row(const std::vector<BenchmarkRow>& rows, Index nx, Index ny,
                             const std::string& configuration) {
  for (const auto& r : rows)
    if (r.nx == nx && r.ny == ny && r.configuration == configuration) return &r;
  return nullptr;
}

}  // namespace

std::string gpu_comparison_table(const std::vector<BenchmarkRow>& rows) {
  std::string out;
  const std::string reference = "uzawa_gnm/cholmod+schur";
  out += fmt::format(
      "\nGPU (contact solve, seconds) against the CPU of this run ({}) and the paper's Table 1 "
      "(CuPy CG on a Tesla P100, and its CPU)\n",
      reference);
  std::string device;
  for (const auto& r : rows)
    if (r.device_kind == DeviceKind::Cuda && !r.device.empty()) device = r.device;
  if (!device.empty()) out += fmt::format("GPU: {}\n", device);
  out += fmt::format("{:>11} {:<34} {:>9} {:>8} {:>8} {:>9} {:>9} {:>8} {:>8} {:>9} {:>9} {:>8}\n",
                     "mesh", "configuration", "unknowns", "GPU", "total", "CPU ref", "CPU/GPU",
                     "paperCPU", "paperGPU", "dM/M", "CG it", "GPU MB");
  for (const auto& r : rows) {
    if (r.device_kind != DeviceKind::Cuda) continue;
    const BenchmarkRow* ref = find_row(rows, r.nx, r.ny, reference);
    const BenchmarkRow* same_cpu = nullptr;  // the same algorithm on the CPU backend
    for (const auto& c : rows)
      if (c.nx == r.nx && c.ny == r.ny && c.device_kind == DeviceKind::Cpu &&
          c.linear == r.linear && c.preconditioner == r.preconditioner)
        same_cpu = &c;
    const double cpu = ref ? ref->t_contact : 0.0;
    out += fmt::format(
        "{:>11} {:<34} {:>9} {:>8} {:>8} {:>9} {:>9} {:>8} {:>8} {:>9} {:>9} {:>8.0f}\n",
        fmt::format("{}x{}", r.nx, r.ny), r.configuration, r.n_dofs, seconds_text(r.t_contact),
        seconds_text(r.t_total), ref ? seconds_text(cpu) : "-",
        ref ? fmt::format("{:.2f}", cpu / r.t_contact) : "-",
        r.paper ? fmt::format("{:.2f}", r.paper->cpu_seconds) : "-",
        r.paper ? fmt::format("{:.2f}", r.paper->gpu_seconds) : "-",
        ref ? fmt::format("{:.1e}", std::abs(r.energy - ref->energy) / std::abs(ref->energy)) : "-",
        r.linear_iterations, r.device_peak_bytes / 1048576.0);
    if (same_cpu)
      out += fmt::format("{:>11} {:<34} same algorithm on the CPU: {} s, CPU/GPU {:.2f}\n", "",
                         same_cpu->configuration, seconds_text(same_cpu->t_contact),
                         same_cpu->t_contact / r.t_contact);
  }
  out += fmt::format(
      "CPU/GPU: the CPU reference's contact solve over the GPU's; dM/M: relative difference of "
      "M(u*, l*) to the CPU reference.\n");
  return out;
}

double paper_mesh_unknowns(Index nx) {
  return 2.0 * static_cast<double>(nx + 1) * static_cast<double>(nx / 3 + 1);
}

Index largest_paper_mesh_nx(double bytes_per_unknown, double gpu_bytes) {
  const double budget = 0.85 * gpu_bytes;
  const double max_unknowns = 2147483647.0 / 18.0;
  Index nx = 480;
  while (paper_mesh_unknowns(nx + 480) * bytes_per_unknown < budget &&
         paper_mesh_unknowns(nx + 480) < max_unknowns)
    nx += 480;
  return nx;
}

}  // namespace signorini::app

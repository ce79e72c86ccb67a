// `signorini bench`: runs the benchmark suite of the library and prints two tables, timings and
// accuracy, with the paper's figures beside ours; optionally writes every row as JSON.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <thread>

#include "commands.hpp"
#include "gpu_comparison.hpp"
#include "problem_bench.hpp"
#include "signorini/backend/cuda_backend.hpp"
#include "signorini/benchmark/paper_benchmark_suite.hpp"
#include "signorini/core/error.hpp"
#include "signorini/output/atomic_file.hpp"
#include "timing_report.hpp"
#include "whole_process_bench.hpp"

namespace signorini::app {

namespace {

std::pair<Index, Index> parse_mesh(const std::string& text) {
  const auto x = text.find('x');
  try {
    if (x != std::string::npos) {
      std::size_t used1 = 0, used2 = 0;
      const long nx = std::stol(text.substr(0, x), &used1);
      const long ny = std::stol(text.substr(x + 1), &used2);
      if (used1 == x && used2 == text.size() - x - 1 && nx >= 1 && ny >= 1) return {nx, ny};
    }
  } catch (const std::exception&) {
  }
  throw InputError("--mesh '" + text + "': expected NXxNY with positive integers, e.g. 480x160");
}

nlohmann::json to_json(const BenchmarkRow& r) {
  nlohmann::json j;
  j["mesh"] = fmt::format("{}x{}", r.nx, r.ny);
  j["configuration"] = r.configuration;
  j["method"] = enum_to_string(kContactMethodNames, r.method);
  j["linear_solver"] = enum_to_string(kLinearSolverTypeNames, r.linear);
  j["schur_complement"] = r.schur_complement;
  j["n_dofs"] = r.n_dofs;
  j["n_contact_nodes"] = r.n_contact;
  j["converged"] = r.converged;
  j["termination"] = r.termination;
  j["outer_iterations"] = r.outer_iterations;
  j["gnm_first"] = r.gnm_first;
  j["gnm_later"] = r.gnm_later;
  j["gnm_later_max"] = r.gnm_later_max;
  j["cg_iterations"] = r.linear_iterations;
  j["factorizations"] = r.factorizations;
  j["factor_updates"] = r.factor_updates;
  j["seconds"] = {{"mesh", r.t_mesh},         {"assembly", r.t_assembly},
                  {"analysis", r.t_analysis}, {"factorization", r.t_factorization},
                  {"solves", r.t_solves},     {"contact_solve", r.t_contact},
                  {"total", r.t_total},       {"linear_solve", r.t_linear}};
  j["contact_over_linear"] = r.ratio;
  j["peak_memory_bytes"] = r.peak_bytes;
  j["M"] = r.energy;
  j["kkt"] = {{"equilibrium", r.kkt.equilibrium},
              {"penetration", r.kkt.penetration},
              {"sign", r.kkt.sign},
              {"complementarity", r.kkt.complementarity}};
  if (r.diff_plain_u >= 0.0)
    j["difference_to_plain"] = {{"u", r.diff_plain_u}, {"l", r.diff_plain_l}};
  if (!r.device.empty()) {
    j["device"] = r.device;
    j["device_kind"] = enum_to_string(kDeviceKindNames, r.device_kind);
    j["preconditioner"] = enum_to_string(kPreconditionerTypeNames, r.preconditioner);
    j["device_peak_bytes"] = r.device_peak_bytes;
  }
  if (r.paper)
    j["paper"] = {{"cpu_seconds", r.paper->cpu_seconds},
                  {"gpu_seconds", r.paper->gpu_seconds},
                  {"M", r.paper->energy},
                  {"gnm_first", r.paper->gnm_first},
                  {"uzawa_iterations", r.paper->uzawa}};
  return j;
}

std::string duration_text(double seconds) {
  if (seconds < 60.0) return fmt::format("{:.0f} s", std::max(1.0, seconds));
  if (seconds < 3600.0) return fmt::format("{:.0f} min", seconds / 60.0);
  return fmt::format("{:.1f} h", seconds / 3600.0);
}

void write_json(const BenchArguments& args, const BenchmarkOptions& options,
                const std::vector<BenchmarkRow>& rows) {
  if (args.json_file.empty()) return;
  nlohmann::json j;
  j["benchmark"] = "paper";
  j["repeats"] = options.repeats;
  j["hardware_threads"] = std::thread::hardware_concurrency();
  j["rows"] = nlohmann::json::array();
  for (const auto& r : rows) j["rows"].push_back(to_json(r));
  write_file_atomically(args.json_file, j.dump(2) + "\n");
  fmt::print("rows written to {}\n", args.json_file);
}

// --device cuda: the CPU reference (direct, condensed), the GPU with multigrid CG on every mesh,
// the paper's configuration (Jacobi CG) on the GPU and on the CPU up to 480x160, and the same
// multigrid algorithm on the CPU backend up to 960x320 (the same-algorithm ratio).
void gpu_configurations(const BenchArguments& args, BenchmarkOptions& options) {
  using C = BenchmarkConfiguration;
  const auto uzawa = ContactMethod::UzawaGnm;
  const auto cg = LinearSolverType::ConjugateGradient;
  std::vector<C> configs;
  C direct{uzawa, LinearSolverType::Cholmod, true};
  direct.max_nx = 3840;  // beyond, the factor does not fit a 128 GB host
  configs.push_back(direct);
  C mg_gpu{uzawa, cg, false};
  mg_gpu.device = DeviceKind::Cuda;
  mg_gpu.preconditioner = PreconditionerType::Multigrid;
  configs.push_back(mg_gpu);
  if (!args.no_cg) {
    C jacobi_gpu{uzawa, cg, false, 480};
    jacobi_gpu.device = DeviceKind::Cuda;
    configs.push_back(jacobi_gpu);
    configs.push_back(C{uzawa, cg, false, 480});  // the paper's CPU configuration
  }
  C mg_cpu{uzawa, cg, false, 960};
  mg_cpu.preconditioner = PreconditionerType::Multigrid;
  configs.push_back(mg_cpu);
  options.configurations = configs;
  options.compare_plain_max_nx = 0;
}

// --largest: the largest paper mesh that fits on the GPU (gpu_comparison.hpp), extrapolated
// from the bytes per unknown of the largest GPU row of this run.
std::vector<BenchmarkRow> largest_gpu_mesh(const std::vector<BenchmarkRow>& rows,
                                           const BenchmarkOptions& base) {
  const BenchmarkRow* biggest = nullptr;
  for (const auto& r : rows)
    if (r.device_kind == DeviceKind::Cuda && r.preconditioner == PreconditionerType::Multigrid &&
        (!biggest || r.n_dofs > biggest->n_dofs))
      biggest = &r;
  const CudaReport report = cuda_report();
  if (!biggest || biggest->device_peak_bytes <= 0.0 || report.gpus.empty()) return {};
  const double per_unknown = biggest->device_peak_bytes / static_cast<double>(biggest->n_dofs);
  const double memory = static_cast<double>(report.gpus.front().total_memory);
  const Index nx = largest_paper_mesh_nx(per_unknown, memory);
  fmt::print(
      "\n--largest: {:.0f} bytes per unknown on the GPU at {}x{}, {:.1f} GiB of GPU memory: "
      "{}x{} ({:.3g} unknowns)\n",
      per_unknown, biggest->nx, biggest->ny, memory / 1073741824.0, nx, nx / 3,
      paper_mesh_unknowns(nx));
  BenchmarkOptions o = base;
  o.meshes = {{nx, nx / 3}};
  o.configurations.clear();
  for (const auto& c : base.configurations)
    if (c.device == DeviceKind::Cuda && c.preconditioner == PreconditionerType::Multigrid)
      o.configurations.push_back(c);
  o.repeats = 1;
  return run_paper_benchmark(o);
}

// Table 1 of the paper beside ours: the rows of the paper's configuration on its meshes.
void print_table1(const std::vector<BenchmarkRow>& rows) {
  bool header = false;
  for (const auto& r : rows) {
    if (!r.paper || r.method != ContactMethod::UzawaGnm || r.linear != LinearSolverType::Cholmod ||
        !r.schur_complement || r.device_kind != DeviceKind::Cpu)
      continue;
    if (!header) {
      fmt::print(
          "\nTable 1 of the paper beside ours (uzawa_gnm on the condensed problem, r = 1e8; our "
          "time end to end, best of the repeats)\n");
      fmt::print("{:>8} {:>7} {:>4} {:>9} {:>9} {:>6} {:>6} {:>15} {:>14} {:>9} {:>9} {:>9}\n",
                 "mesh", "n_p", "n_d", "GNM", "paper", "Uzawa", "paper", "M(u*, l*)", "paper M",
                 "ours (s)", "CPU (s)", "GPU (s)");
      header = true;
    }
    fmt::print(
        "{:>8} {:>7} {:>4} {:>9} {:>9} {:>6} {:>6} {:>15.7e} {:>14.6e} {:>9} {:>9.2f} {:>9.2f}\n",
        fmt::format("{}x{}", r.nx, r.ny), r.n_dofs, r.n_contact,
        fmt::format("{}/{}", r.gnm_first, r.gnm_later), fmt::format("{}/2", r.paper->gnm_first),
        r.outer_iterations, r.paper->uzawa, r.energy, r.paper->energy, seconds_text(r.t_total),
        r.paper->cpu_seconds, r.paper->gpu_seconds);
  }
  if (header)
    fmt::print(
        "The paper: IBM POWER8, 2 x 10 cores, and an NVIDIA Tesla P100, conjugate gradients on "
        "both; ours: this machine, {} hardware threads.\n",
        std::thread::hardware_concurrency());
}

// --whole-process, --peers: each solve a separate process (whole_process_bench.hpp), the paper's
// configuration only.
int whole_process(const BenchArguments& args, const std::vector<std::pair<Index, Index>>& meshes) {
  const std::vector<std::pair<bool, const char*>> other = {{args.full, "--full"},
                                                           {!args.methods.empty(), "--method"},
                                                           {args.cg, "--cg"},
                                                           {args.plain, "--plain"},
                                                           {args.no_cg, "--no-cg"},
                                                           {args.no_plain, "--no-plain"},
                                                           {args.device != "cpu", "--device"},
                                                           {args.largest, "--largest"}};
  for (const auto& [given, flag] : other)
    if (given)
      throw InputError(fmt::format(
          "{} does not go with --whole-process or --peers, which run the paper's configuration "
          "(signorini solve examples/paper.toml) on the meshes of --mesh, --larger, --huge",
          flag));
  if (!args.peer_configs.empty() && !args.peers)
    throw InputError("--peer-config goes with --peers");
  if (args.interleave && args.warmup >= 0)
    throw InputError("--warmup does not go with --interleave, which runs no warm-up");
  WholeProcessOptions o;
  o.warmup = args.warmup >= 0 ? args.warmup : 1;
  o.interleave = args.interleave;
  o.meshes = meshes;
  o.repeats = args.repeats;
  o.peers = args.peers;
  o.peer_configs = args.peer_configs;
  o.json_file = args.json_file;
  return run_whole_process_bench(o);
}

}  // namespace

int run_bench(const BenchArguments& args) {
  if (!args.problem_file.empty()) {
    if (args.full || args.larger || args.huge || !args.meshes.empty() || args.whole_process ||
        args.peers || args.cg || args.plain || args.device != "cpu" || args.warmup >= 0 ||
        args.interleave)
      throw InputError(
          "--problem times one problem file: it takes --repeats and --json only (the paper's "
          "meshes and configurations are options of the paper's benchmark)");
    return run_problem_bench({args.problem_file, args.repeats, args.json_file});
  }
  BenchmarkOptions options = args.full ? full_benchmark_options() : BenchmarkOptions{};
  options.repeats = args.repeats;
  if (!args.meshes.empty()) {
    options.meshes.clear();
    for (const auto& m : args.meshes) options.meshes.push_back(parse_mesh(m));
  }
  if (args.larger)
    for (const auto& m : larger_paper_meshes())
      if (std::find(options.meshes.begin(), options.meshes.end(), m) == options.meshes.end())
        options.meshes.push_back(m);
  if (args.huge) options.meshes.emplace_back(3840, 1280);
  if (args.whole_process || args.peers || !args.peer_configs.empty())
    return whole_process(args, options.meshes);
  if (args.warmup >= 0 || args.interleave)
    throw InputError(fmt::format("{} goes with --whole-process or --peers",
                                 args.interleave ? "--interleave" : "--warmup"));
  for (const auto& name : args.methods) {
    const auto m = enum_from_string(kContactMethodNames, name);
    if (!m)
      throw InputError("--method '" + name + "': expected " + enum_choices(kContactMethodNames));
    const BenchmarkConfiguration c{*m, LinearSolverType::Cholmod, true};
    const bool present =
        std::any_of(options.configurations.begin(), options.configurations.end(),
                    [&](const BenchmarkConfiguration& o) { return o.name() == c.name(); });
    if (!present) options.configurations.push_back(c);
  }
  if (args.cg && !args.full) options.configurations.push_back(paper_cg_configuration());
  if (args.plain && !args.full) {
    options.configurations.push_back(plain_sparse_configuration());
    options.compare_plain_max_nx = 480;
  }
  if ((args.no_cg || args.no_plain) && !args.full)
    throw InputError("--no-cg and --no-plain go with --full (the default runs neither)");
  std::erase_if(options.configurations, [&](const BenchmarkConfiguration& c) {
    return (args.no_cg && c.linear == LinearSolverType::ConjugateGradient) ||
           (args.no_plain && c.linear == LinearSolverType::Cholmod && !c.schur_complement);
  });
  if (args.no_plain) options.compare_plain_max_nx = 0;
  const bool gpu = args.device == "cuda";
  if (gpu) {
    // Fail now, with the reason, rather than after the CPU rows (docs/gpu.md).
    const CudaReport report = cuda_report();
    if (report.gpus.empty())
      throw InputError(fmt::format(
          "--device cuda: {}",
          report.built ? "no usable CUDA GPU (" + report.problem + ")" : report.problem));
    if (!args.methods.empty())
      throw InputError("--method: the GPU comparison (--device cuda) runs uzawa_gnm only");
    if (args.meshes.empty() && !args.larger && !args.full)  // the GPU's case is the large mesh
      for (const auto& m : larger_paper_meshes()) options.meshes.push_back(m);
    gpu_configurations(args, options);
  } else if (args.largest) {
    throw InputError("--largest needs --device cuda");
  }
  const bool table1_only = !args.full && !args.larger && !args.huge && args.meshes.empty() &&
                           args.methods.empty() && !args.cg && !args.plain && !gpu;
  options.linear_yardstick = !table1_only;  // Table 1 alone needs no contact/linear ratio
  options.progress = [](const std::string& line) {
    fmt::print(stderr, "  running {}\n", line);
    std::fflush(stderr);
  };

  fmt::print(
      "signorini bench: the paper's problem (Section 5), best of {} (meshes above 1e6 unknowns "
      "once), {} hardware threads; estimated time {} (a 2-core machine)\n",
      options.repeats, std::thread::hardware_concurrency(),
      duration_text(estimated_seconds(options)));
  std::fflush(stdout);
  auto rows = run_paper_benchmark(options);
  print_table1(rows);
  if (table1_only) {
    bool ok = true;
    for (const auto& r : rows) ok = ok && r.converged;
    fmt::print(
        "\nMore: --larger (960x320, 1920x640), --huge (3840x1280), --cg (the paper's CG "
        "configuration), --plain, --method semismooth_newton, --full (all of them, minutes); "
        "docs/performance.md.\n");
    write_json(args, options, rows);
    return ok ? kSuccess : kNotConverged;
  }

  fmt::print(
      "\nTimings (seconds; contact = everything after assembly; linear = one linear-elastic "
      "solve of the same mesh with the same linear solver)\n");
  fmt::print(
      "{:>9} {:<31} {:>8} {:>5} {:>7} {:>5} {:>7} {:>7} {:>8} {:>8} {:>8} {:>7} {:>8} {:>8} "
      "{:>8} {:>6} {:>8} {:>8} {:>8}\n",
      "mesh", "configuration", "unknowns", "n_d", "GNM", "outer", "CG it", "mesh", "assembly",
      "analysis", "factor", "solves", "contact", "total", "linear", "ratio", "peak MB", "paperCPU",
      "paperGPU");
  for (const auto& r : rows) {
    const std::string gnm =
        r.method == ContactMethod::UzawaGnm
            ? (r.gnm_later_max > r.gnm_later
                   ? fmt::format("{}/{}({})", r.gnm_first, r.gnm_later, r.gnm_later_max)
                   : fmt::format("{}/{}", r.gnm_first, r.gnm_later))
            : "-";
    fmt::print(
        "{:>9} {:<31} {:>8} {:>5} {:>7} {:>5} {:>7} {:>7} {:>8} {:>8} {:>8} {:>7} {:>8} {:>8} "
        "{:>8} {:>6} {:>8.0f} {:>8} {:>8}\n",
        fmt::format("{}x{}", r.nx, r.ny), r.configuration, r.n_dofs, r.n_contact, gnm,
        r.outer_iterations, r.linear_iterations, seconds_text(r.t_mesh), seconds_text(r.t_assembly),
        seconds_text(r.t_analysis), seconds_text(r.t_factorization), seconds_text(r.t_solves),
        seconds_text(r.t_contact), seconds_text(r.t_total),
        r.t_linear > 0 ? seconds_text(r.t_linear) : "-",
        r.t_linear > 0 ? fmt::format("{:.2f}", r.ratio) : "-", r.peak_bytes / 1048576.0,
        r.paper ? fmt::format("{:.2f}", r.paper->cpu_seconds) : "-",
        r.paper ? fmt::format("{:.2f}", r.paper->gpu_seconds) : "-");
  }
  fmt::print(
      "\nAccuracy (KKT residuals relative, see docs/solvers.md; difference to the plain sparse "
      "path, relative 2-norms)\n");
  fmt::print("{:>9} {:<31} {:>10} {:>16} {:>13} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}\n", "mesh",
             "configuration", "converged", "M(u*,l*)", "paper M", "equil.", "penetr.", "sign",
             "compl.", "du plain", "dl plain");
  bool ok = true;
  for (const auto& r : rows) {
    ok = ok && r.converged;
    fmt::print(
        "{:>9} {:<31} {:>10} {:>16.8e} {:>13} {:>9.1e} {:>9.1e} {:>9.1e} {:>9.1e} {:>9} {:>9}\n",
        fmt::format("{}x{}", r.nx, r.ny), r.configuration, r.converged ? "yes" : r.termination,
        r.energy, r.paper ? fmt::format("{:.6e}", r.paper->energy) : "-", r.kkt.equilibrium,
        r.kkt.penetration, r.kkt.sign, r.kkt.complementarity,
        r.diff_plain_u >= 0 ? fmt::format("{:.1e}", r.diff_plain_u) : "-",
        r.diff_plain_l >= 0 ? fmt::format("{:.1e}", r.diff_plain_l) : "-");
  }
  fmt::print(
      "\nGNM: iterations at the first Uzawa step / usual count at later ones (largest in "
      "parentheses); the paper: 7/2, 8/2, 9/2, 10/2 and 6, 7, 8, 11 Uzawa iterations.\n");

  if (gpu) {
    auto all = rows;
    if (args.largest) {
      const auto extra = largest_gpu_mesh(rows, options);
      all.insert(all.end(), extra.begin(), extra.end());
      for (const auto& r : extra) ok = ok && r.converged;
    }
    fmt::print("{}", gpu_comparison_table(all));
    rows = std::move(all);
  }

  write_json(args, options, rows);
  return ok ? kSuccess : kNotConverged;
}

}  // namespace signorini::app

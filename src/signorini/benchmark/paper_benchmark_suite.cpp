#include "signorini/benchmark/paper_benchmark_suite.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/peak_memory.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {

namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double sum_of(const TimingTable& t, std::initializer_list<const char*> phases) {
  double s = 0.0;
  for (const char* p : phases) s += t.seconds(p);
  return s;
}

ContactSolverOptions solver_options(const BenchmarkConfiguration& c) {
  ContactSolverOptions o;  // the paper's defaults, with its r = 1e8 (Section 5)
  o.r = 1e8;
  o.method = c.method;
  o.linear.type = c.linear;
  o.schur_complement = c.schur_complement;
  o.device = c.device;
  o.linear.preconditioner = c.preconditioner;
  return o;
}

// One plain linear-elastic solve of the benchmark with the contact boundary clamped in its normal
// direction (y on the bottom edge): analysis + factorisation + solve, best of `repeats`.
double linear_solve_seconds(Index nx, Index ny, LinearSolverType type, int repeats) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    ProblemSpec spec = paper_benchmark(nx, ny);
    spec.clamps.push_back({"bottom", {false, true, false}});
    const Mesh mesh = make_rectangle_mesh(spec.mesh);
    const DofMap dofs = make_dof_map(mesh, spec.clamps);
    const SparseMatrix A = assemble_stiffness(mesh, dofs, spec.elasticity);
    Vector b = Vector::Zero(dofs.num_free());
    for (const TractionSpec& t : spec.tractions)
      add_traction_load(mesh, dofs, mesh.boundary_part(t.boundary), t.p, 2, b);
    LinearSolverOptions lo;
    lo.type = type;
    auto solver = make_linear_solver(lo);
    const auto t0 = std::chrono::steady_clock::now();
    solver->analyze(A);
    solver->factorize(A);
    Vector x = Vector::Zero(A.rows());
    solver->solve(b, x);
    best = std::min(best, seconds_since(t0));
  }
  return best;
}

}  // namespace

std::string BenchmarkConfiguration::name() const {
  std::string s(enum_to_string(kContactMethodNames, method));
  s += "/";
  s += enum_to_string(kLinearSolverTypeNames, linear);
  if (linear == LinearSolverType::Cholmod) s += schur_complement ? "+schur" : "+plain";
  if (linear == LinearSolverType::ConjugateGradient &&
      (device == DeviceKind::Cuda || preconditioner != PreconditionerType::Jacobi)) {
    s += "+";
    s += enum_to_string(kPreconditionerTypeNames, preconditioner);
  }
  if (device != DeviceKind::Cpu) {
    s += "@";
    s += enum_to_string(kDeviceKindNames, device);
  }
  return s;
}

std::optional<PaperRow> paper_table1_row(Index nx, Index ny) {
  static constexpr PaperRow kRows[] = {
      {60, 7, 6, 1.89, 5.06, -6.700472e-05},
      {120, 8, 7, 7.70, 8.76, -6.711822e-05},
      {240, 9, 8, 56.35, 17.24, -6.714898e-05},
      {480, 10, 11, 480.60, 38.06, -6.715744e-05},
  };
  for (const PaperRow& r : kRows)
    if (r.nx == nx && 3 * ny == nx) return r;
  return std::nullopt;
}

std::vector<std::pair<Index, Index>> larger_paper_meshes() {
  return {{960, 320}, {1920, 640}};
}

BenchmarkConfiguration paper_cg_configuration() {
  return {ContactMethod::UzawaGnm, LinearSolverType::ConjugateGradient, false, 480};
}

BenchmarkConfiguration plain_sparse_configuration() {
  return {ContactMethod::UzawaGnm, LinearSolverType::Cholmod, false, 480};
}

BenchmarkOptions full_benchmark_options() {
  BenchmarkOptions o;
  for (const auto& m : larger_paper_meshes()) o.meshes.push_back(m);
  o.configurations = {
      {ContactMethod::UzawaGnm, LinearSolverType::Cholmod, true},
      {ContactMethod::SemismoothNewton, LinearSolverType::Cholmod, true},
      paper_cg_configuration(),
      plain_sparse_configuration(),
  };
  o.compare_plain_max_nx = 480;
  return o;
}

double estimated_seconds(const BenchmarkOptions& options) {
  // Seconds at 480x160 and the exponent of their growth with the number of unknowns n
  // (docs/performance.md: condensed 0.66 s -> 130 s at 3840x1280, n^1.28).
  constexpr double kUnknowns480 = 154882.0;
  const auto scaled = [&](double seconds_480, double exponent, double n) {
    return seconds_480 * std::pow(n / kUnknowns480, exponent);
  };
  double total = 0.0;
  for (const auto& [nx, ny] : options.meshes) {
    const double n = 2.0 * static_cast<double>(nx + 1) * static_cast<double>(ny + 1);
    const int repeats = n > 1e6 ? 1 : std::max(1, options.repeats);
    bool yardstick_direct = false, yardstick_cg = false;
    for (const BenchmarkConfiguration& c : options.configurations) {
      if (nx > c.max_nx) continue;
      double run = 0.0;
      if (c.device == DeviceKind::Cuda)
        run = 2.0 + scaled(0.2, 1.0, n);  // start-up, then a GPU's speed
      else if (c.linear == LinearSolverType::ConjugateGradient &&
               c.preconditioner == PreconditionerType::Multigrid)
        run = scaled(1.8, 1.1, n);
      else if (c.linear == LinearSolverType::ConjugateGradient)
        run = scaled(57.0, 1.8, n);
      else if (c.schur_complement)
        run = scaled(0.66, 1.28, n);
      else
        run = scaled(4.9, 1.4, n);
      total += repeats * run;
      if (c.schur_complement && c.linear == LinearSolverType::Cholmod &&
          nx <= options.compare_plain_max_nx)
        total += scaled(4.9, 1.4, n);
      if (options.linear_yardstick && c.device == DeviceKind::Cpu) {
        if (c.linear == LinearSolverType::ConjugateGradient && !yardstick_cg) {
          yardstick_cg = true;
          total += repeats * scaled(2.4, 1.5, n);
        } else if (c.linear != LinearSolverType::ConjugateGradient && !yardstick_direct) {
          yardstick_direct = true;
          total += repeats * scaled(0.53, 1.28, n);
        }
      }
    }
  }
  return total;
}

std::vector<BenchmarkRow> run_paper_benchmark(const BenchmarkOptions& options) {
  std::vector<BenchmarkRow> rows;
  auto say = [&](const std::string& s) {
    if (options.progress) options.progress(s);
  };
  for (const auto& [nx, ny] : options.meshes) {
    std::map<LinearSolverType, double> linear_time;  // the yardstick, once per linear solver
    for (const BenchmarkConfiguration& config : options.configurations) {
      if (nx > config.max_nx) continue;
      say(fmt::format("{}x{} {}", nx, ny, config.name()));
      const ContactSolverOptions solver = solver_options(config);
      const bool large = 2 * (nx + 1) * (ny + 1) > 1000000;
      const int repeats = large ? 1 : std::max(1, options.repeats);

      BenchmarkRow row;
      row.nx = nx;
      row.ny = ny;
      row.configuration = config.name();
      row.method = config.method;
      row.linear = config.linear;
      row.schur_complement = config.schur_complement;
      row.device_kind = config.device;
      row.preconditioner = config.preconditioner;
      row.paper = paper_table1_row(nx, ny);
      row.t_total = 1e300;
      ContactResult best_result;
      for (int r = 0; r < repeats; ++r) {
        reset_peak_resident();
        const auto t0 = std::chrono::steady_clock::now();
        ProblemSpec spec = paper_benchmark(nx, ny);
        spec.solver = solver;  // so that the model carries the multigrid hierarchy if needed
        const Model model = build_model(spec);
        ContactResult res = solve_contact(model.problem, solver, &model.multigrid);
        const double total = seconds_since(t0);
        row.peak_bytes = std::max(row.peak_bytes, peak_resident_bytes());
        if (total >= row.t_total) continue;
        row.t_total = total;
        row.n_dofs = model.dofs.num_dofs();
        row.n_contact = model.problem.contact.size();
        row.t_mesh = model.timings.seconds("mesh");
        row.t_assembly =
            sum_of(model.timings, {"assembly", "loads", "contact set", "multigrid hierarchy"});
        const TimingTable& t = res.summary.timings;
        // Backend path: upload = analysis, preconditioner set-ups = factorisations.
        row.t_analysis = sum_of(t, {"linear analysis", "condensation analysis", "device setup",
                                    "device upload", "multigrid setup"});
        row.t_factorization =
            sum_of(t, {"linear factorization", "linear factor update", "condensation factorization",
                       "condensation Schur complement", "preconditioner setup"});
        row.device = res.summary.device;
        row.device_peak_bytes = static_cast<double>(res.summary.device_peak_bytes);
        row.t_solves = sum_of(t, {"linear solve", "condensation solve"});
        row.t_contact = t.seconds("contact solve");
        best_result = std::move(res);
      }
      const SolveSummary& s = best_result.summary;
      row.converged = s.converged();
      row.termination = enum_to_string(kTerminationNames, s.termination);
      row.outer_iterations = s.outer_iterations;
      const auto inner = s.inner_iterations();
      if (!inner.empty()) row.gnm_first = inner.front();
      std::map<int, int> counts;
      for (std::size_t k = 1; k < inner.size(); ++k) {
        ++counts[inner[k]];
        row.gnm_later_max = std::max(row.gnm_later_max, inner[k]);
      }
      int most = 0;
      for (const auto& [count, times] : counts)
        if (times > most) {
          most = times;
          row.gnm_later = count;
        }
      for (const auto& step : s.steps) {
        row.linear_iterations += step.linear_iterations;
        row.factorizations += step.factorizations;
        row.factor_updates += step.factor_updates;
      }
      row.energy = s.lagrangian;
      row.kkt = s.kkt;

      if (config.schur_complement && config.linear == LinearSolverType::Cholmod &&
          nx <= options.compare_plain_max_nx) {
        const Model model = build_model(paper_benchmark(nx, ny));
        ContactSolverOptions plain = solver;
        plain.schur_complement = false;
        const ContactResult p = solve_contact(model.problem, plain, &model.multigrid);
        row.diff_plain_u = (best_result.u - p.u).norm() / p.u.norm();
        row.diff_plain_l = (best_result.l - p.l).norm() / std::max(p.l.norm(), 1e-300);
      }
      if (uses_backend_path(solver) || !options.linear_yardstick) {  // no yardstick
        rows.push_back(std::move(row));
        continue;
      }
      if (!linear_time.contains(config.linear)) {
        say(fmt::format("{}x{} linear solve ({})", nx, ny,
                        enum_to_string(kLinearSolverTypeNames, config.linear)));
        linear_time[config.linear] = linear_solve_seconds(nx, ny, config.linear, repeats);
      }
      row.t_linear = linear_time[config.linear];
      row.ratio = row.t_contact / row.t_linear;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

}  // namespace signorini

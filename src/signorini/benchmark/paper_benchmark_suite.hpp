#pragma once
// The benchmark suite behind `signorini bench`: the paper's problem (Section 5) on its four meshes
// and larger ones, for several solver configurations, with phase timings, peak memory, iteration
// counts, energies, KKT residuals, the difference to the plain (uncondensed) path, and, measured
// in the same run on the same mesh with the same linear solver, one plain linear-elastic solve
// (the contact boundary clamped in the normal direction) as the yardstick.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "signorini/contact/solve_summary.hpp"

namespace signorini {

/// One solver configuration of the suite.
struct BenchmarkConfiguration {
  ContactMethod method = ContactMethod::UzawaGnm;
  LinearSolverType linear = LinearSolverType::Cholmod;
  bool schur_complement = true;
  /// Largest nx this configuration runs on (CG and the plain path are slow on big meshes).
  Index max_nx = 1 << 30;
  /// With CG: where it runs and its preconditioner (cuda, or multigrid: the backend path).
  DeviceKind device = DeviceKind::Cpu;
  PreconditionerType preconditioner = PreconditionerType::Jacobi;
  [[nodiscard]] std::string name() const;
};

struct BenchmarkOptions {
  /// Meshes nx x ny. Default: the paper's four (Table 1).
  std::vector<std::pair<Index, Index>> meshes{{60, 20}, {120, 40}, {240, 80}, {480, 160}};
  /// Default: the paper's method on the condensed problem, with the paper's r = 1e8: Table 1.
  std::vector<BenchmarkConfiguration> configurations{
      {ContactMethod::UzawaGnm, LinearSolverType::Cholmod, true},
  };
  int repeats = 3;  ///< best of `repeats` for timings (meshes above 1e6 unknowns run once)
  /// Compare each condensed result with the plain path on meshes up to this nx (0: never).
  Index compare_plain_max_nx = 0;
  /// Time one linear-elastic solve of each mesh as the yardstick of the contact solve.
  bool linear_yardstick = true;
  /// Called with a line of progress text.
  std::function<void(const std::string&)> progress;
};

/// The meshes beyond the paper's that `--larger` adds: 960x320 and 1920x640.
std::vector<std::pair<Index, Index>> larger_paper_meshes();

/// The whole suite (`signorini bench --full`): the paper's meshes and the larger ones; the
/// paper's method and the semismooth Newton method on the condensed problem, the paper's own
/// configuration (uzawa_gnm with CG) up to 480x160, and the plain sparse path of uzawa_gnm up to
/// 480x160, compared with the condensed one.
BenchmarkOptions full_benchmark_options();

/// The paper's configuration: uzawa_gnm with Jacobi-preconditioned CG, no condensation, up to
/// 480x160 (57 s there on two cores).
BenchmarkConfiguration paper_cg_configuration();

/// The plain sparse path of uzawa_gnm (no condensation), up to 480x160.
BenchmarkConfiguration plain_sparse_configuration();

/// A rough estimate of the wall time of run_paper_benchmark(options) on a 2-core machine like
/// this project's, in seconds: the measured times of docs/performance.md (480x160: 0.66 s
/// condensed, 4.9 s plain sparse, 57 s with CG, 1.8 s with multigrid), scaled to each mesh by
/// the growth measured from 480x160 to 3840x1280, times the repeats.
double estimated_seconds(const BenchmarkOptions& options);

/// Table 1 of the paper for one of its meshes.
struct PaperRow {
  Index nx;
  int gnm_first;
  int uzawa;
  double cpu_seconds;
  double gpu_seconds;
  double energy;
};
std::optional<PaperRow> paper_table1_row(Index nx, Index ny);

struct BenchmarkRow {
  Index nx = 0, ny = 0;
  std::string configuration;
  ContactMethod method = ContactMethod::UzawaGnm;
  LinearSolverType linear = LinearSolverType::Cholmod;
  bool schur_complement = true;
  DeviceKind device_kind = DeviceKind::Cpu;
  PreconditionerType preconditioner = PreconditionerType::Jacobi;
  std::string device;            ///< the backend's description (backend path only)
  double device_peak_bytes = 0;  ///< most memory held on the backend (backend path only)
  Index n_dofs = 0, n_contact = 0;
  bool converged = false;
  std::string termination;
  int outer_iterations = 0;  ///< Uzawa (or Newton) iterations
  int gnm_first = 0;         ///< GNM iterations at the first Uzawa step
  int gnm_later = 0;         ///< usual GNM count at later steps (mode)
  int gnm_later_max = 0;
  long linear_iterations = 0;  ///< CG iterations, all steps
  int factorizations = 0;
  int factor_updates = 0;
  // Seconds (best of the repeats): mesh, assembly (stiffness, loads, contact set), and the phases
  // of the contact solve.
  double t_mesh = 0, t_assembly = 0, t_analysis = 0, t_factorization = 0, t_solves = 0;
  double t_contact = 0;   ///< the whole contact solve (everything after assembly)
  double t_total = 0;     ///< end to end: mesh + assembly + contact solve
  double t_linear = 0;    ///< one linear solve: analysis + factorisation + solve
  double ratio = 0;       ///< t_contact / t_linear
  double peak_bytes = 0;  ///< peak resident memory of the case
  double energy = 0;      ///< M(u*, l*)
  KktResiduals kkt;
  double diff_plain_u = -1, diff_plain_l = -1;  ///< vs the plain path; -1: not compared
  std::optional<PaperRow> paper;
};

/// Runs every configuration on every mesh (configurations skip meshes beyond their max_nx).
std::vector<BenchmarkRow> run_paper_benchmark(const BenchmarkOptions& options);

}  // namespace signorini

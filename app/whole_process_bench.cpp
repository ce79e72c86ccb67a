#include "whole_process_bench.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <thread>

#include "child_process.hpp"
#include "commands.hpp"
#include "data_files.hpp"
#include "signorini/core/digit_groups.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/effective_settings.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/output/atomic_file.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini::app {

namespace fs = std::filesystem;

namespace {

// The paper's problem as a problem file: the library's paper_benchmark() written out by the
// effective-settings writer, with the traction formulas as text (the spec holds them as
// functions). Read back and checked against paper_benchmark(), so that the file and the
// in-process benchmark cannot drift apart.
std::string paper_problem_toml() {
  const ProblemSpec paper = paper_benchmark(60, 20);
  ExpressionTexts texts;
  texts.tractions = {{"0", "1"}, {"0", "-2/3*(3 - x)"}};
  if (paper.tractions.size() != texts.tractions.size())
    throw std::logic_error("paper_benchmark() has " + std::to_string(paper.tractions.size()) +
                           " tractions; the whole-process benchmark writes 2");
  const std::string text = effective_toml(paper, texts);
  const ProblemSpec read = parse_problem_string(text, "paper.toml").spec;
  auto differs = [](double a, double b) { return std::abs(a - b) > 1e-14 * (1.0 + std::abs(b)); };
  for (std::size_t k = 0; k < paper.tractions.size(); ++k)
    for (double x : {0.0, 0.7, 1.5, 3.0})
      for (double y : {0.0, 0.5, 1.0}) {
        const Point at(x, y, 0.0);
        const Eigen::Vector3d want = paper.tractions[k].p(at), got = read.tractions[k].p(at);
        if (paper.tractions[k].boundary != read.tractions[k].boundary || differs(got(0), want(0)) ||
            differs(got(1), want(1)))
          throw std::logic_error(fmt::format(
              "the problem file written for `signorini solve` differs from paper_benchmark() in "
              "traction {} at ({}, {})",
              k + 1, x, y));
      }
  if (differs(read.elasticity.material.E, paper.elasticity.material.E) ||
      differs(read.elasticity.material.nu, paper.elasticity.material.nu) ||
      read.elasticity.plane_model != paper.elasticity.plane_model || read.contacts.size() != 1 ||
      read.contacts[0].boundary != paper.contacts[0].boundary || read.solver.r != paper.solver.r ||
      read.solver.method != paper.solver.method ||
      read.solver.linear.type != paper.solver.linear.type ||
      read.solver.schur_complement != paper.solver.schur_complement)
    throw std::logic_error(
        "the problem file written for `signorini solve` differs from paper_benchmark()");
  return text;
}

std::string last_line(std::string text) {
  while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
  const auto newline = text.rfind('\n');
  return newline == std::string::npos ? text : text.substr(newline + 1);
}

nlohmann::json read_json(const fs::path& file, const std::string& what) {
  try {
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (f == nullptr) throw std::runtime_error(std::strerror(errno));
    std::string text;
    char buffer[65536];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, f)) > 0) text.append(buffer, n);
    std::fclose(f);
    return nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("cannot read {} '{}': {}", what, file.string(), e.what()));
  }
}

double number_or_nan(const nlohmann::json& j, const char* key) {
  return j.contains(key) && j[key].is_number() ? j[key].get<double>()
                                               : std::numeric_limits<double>::quiet_NaN();
}

// One program on one mesh: every repeat, and the fastest.
struct Measured {
  std::string program;  // "signorini" or "petsc_snesvi <config>"
  std::string config;   // the peer's configuration ("" for signorini)
  std::vector<ChildRun> runs;
  ChildRun best;
  double timers_total = std::numeric_limits<double>::quiet_NaN();  // its own phase timers
  double energy = std::numeric_limits<double>::quiet_NaN();        // J(u)
  bool converged = false;
  long active = -1;
  long iterations = -1;  // the peer's SNES iterations
  double relative_difference = std::numeric_limits<double>::quiet_NaN();  // peers: to signorini

  void add(const ChildRun& run, double timers, double j, bool ok, long n_active, long its) {
    runs.push_back(run);
    if (runs.size() == 1 || run.wall_seconds < best.wall_seconds) {
      best = run;
      timers_total = timers;
    }
    // Every repeat solves the same problem: the energy of the last run stands for all, and a
    // run that did not converge marks the row.
    energy = j;
    converged = (runs.size() == 1 || converged) && ok;
    active = n_active;
    iterations = its;
  }
};

std::string mesh_name(const std::pair<Index, Index>& m) {
  return fmt::format("{}x{}", m.first, m.second);
}

void check_exit(const ChildRun& run, const std::string& what, int converged_or_not) {
  if (run.signal != 0)
    throw std::runtime_error(
        fmt::format("{} was ended by signal {} ({})", what, run.signal, last_line(run.errors)));
  if (run.exit_status != 0 && run.exit_status != converged_or_not)
    throw InputError(fmt::format(
        "{} exited with status {}: {}", what, run.exit_status,
        last_line(run.errors).empty() ? std::string("no message") : last_line(run.errors)));
}

nlohmann::json to_json(const std::string& mesh, const Measured& m) {
  nlohmann::json j;
  j["mesh"] = mesh;
  j["program"] = m.config.empty() ? "signorini" : "petsc_snesvi";
  if (!m.config.empty()) j["config"] = m.config;
  j["wall_seconds"] = m.best.wall_seconds;
  j["user_seconds"] = m.best.user_seconds;
  j["system_seconds"] = m.best.system_seconds;
  j["minor_faults"] = m.best.minor_faults;
  j["major_faults"] = m.best.major_faults;
  j["peak_rss_bytes"] = m.best.peak_rss_bytes;
  j["timers_total_seconds"] = m.timers_total;
  nlohmann::json walls = nlohmann::json::array();
  for (const ChildRun& r : m.runs) walls.push_back(r.wall_seconds);
  j["wall_seconds_each"] = walls;
  j["energy"] = m.energy;
  j["converged"] = m.converged;
  j["active_nodes"] = m.active;
  if (!m.config.empty()) {
    j["snes_iterations"] = m.iterations;
    j["relative_energy_difference"] = m.relative_difference;
  }
  return j;
}

}  // namespace

double relative_difference(double a, double b) {
  return b != 0.0 ? std::abs(a - b) / std::abs(b) : std::abs(a - b);
}

int run_whole_process_bench(const WholeProcessOptions& options) {
  const ScratchFolder scratch;
  const fs::path problem = scratch.path() / "paper.toml";
  write_file_atomically(problem.string(), paper_problem_toml());
  const std::string self = own_executable();
  const std::vector<std::string> environment = user_environment();

  // The peer: its script, an interpreter with numpy and petsc4py, or one line saying why not.
  std::string python, script;
  std::vector<std::string> configs;
  if (options.peers) {
    script = find_data_file("peers/petsc_snesvi.py", "bench/peers/petsc_snesvi.py",
                            "SIGNORINI_PEER_SCRIPT");
    python = find_python("bench --peers", "numpy and petsc4py");
    std::string why;
    if (python.empty()) {
      why = "no python3 was found";
    } else {
      const ChildRun check = run_child({python, "-c", "import numpy, petsc4py"}, environment);
      if (check.exit_status != 0)
        why = fmt::format("petsc4py (or numpy) is not importable by {}", python);
    }
    if (!why.empty()) {
      fmt::print(
          "peer skipped: {} (Debian: apt-get install python3-petsc4py; SIGNORINI_PYTHON chooses "
          "the interpreter)\n",
          why);
      python.clear();
    } else {
      configs = options.peer_configs.empty() ? std::vector<std::string>{""} : options.peer_configs;
    }
  }

  fmt::print(
      "signorini bench --whole-process: the paper's problem, each run a separate process, best "
      "of {} by wall time ({}), {} hardware threads\n  signorini: {} solve <paper.toml> --set "
      "mesh.nx=NX --set mesh.ny=NY -o <folder> -q\n",
      options.repeats,
      options.interleave
          ? std::string("programs interleaved repeat by repeat")
          : fmt::format("program by program, after {} warm-up run(s) each", options.warmup),
      std::thread::hardware_concurrency(), self);
  if (!python.empty())
    fmt::print("  peer:      {} {} --nx NX --ny NY{} --json <file> --quiet\n", python, script,
               configs.front().empty() && configs.size() == 1 ? "" : " --config CONFIG");
  std::fflush(stdout);

  struct Row {
    std::string mesh;
    std::vector<Measured> measured;  // signorini first, then each peer configuration
  };
  std::vector<Row> rows;
  int run_number = 0;
  for (const auto& mesh : options.meshes) {
    Row row{mesh_name(mesh), {}};
    row.measured.push_back(Measured{"signorini", "", {}, {}});
    for (const std::string& c : configs) {
      const std::string shown = c.empty() ? "default" : c;
      row.measured.push_back(Measured{"petsc_snesvi " + shown, shown, {}, {}});
    }
    const std::string nx = std::to_string(mesh.first), ny = std::to_string(mesh.second);
    // One run of program p (0: signorini, k > 0: the peer's configuration k - 1); a timed run
    // is added to its row, a warm-up run is checked (exit status, energy) and dropped.
    const auto run_program = [&](std::size_t p, int number, bool timed) {
      Measured& m = row.measured[p];
      const std::string what =
          timed ? fmt::format("{}/{}", number, options.repeats) : std::string("warm-up");
      fmt::print(stderr, "  running {} {} ({})\n", row.mesh, m.program, what);
      if (p == 0) {
        const fs::path out = scratch.path() / fmt::format("solve-{}", ++run_number);
        const ChildRun run = run_child({self, "solve", problem.string(), "--set", "mesh.nx=" + nx,
                                        "--set", "mesh.ny=" + ny, "-o", out.string(), "-q"},
                                       environment);
        check_exit(run, fmt::format("signorini solve at {}", row.mesh), kNotConverged);
        const nlohmann::json summary = read_json(out / "summary.json", "the summary of a solve");
        if (timed)
          m.add(run,
                summary.contains("timings") ? number_or_nan(summary["timings"], "total")
                                            : std::numeric_limits<double>::quiet_NaN(),
                number_or_nan(summary, "energy"),
                summary.value("converged", false) && run.exit_status == 0,
                summary.value("n_active", -1L), -1);
        std::error_code ec;
        fs::remove_all(out, ec);
        return;
      }
      const std::string& config = configs[p - 1];
      const fs::path json = scratch.path() / fmt::format("peer-{}.json", ++run_number);
      std::vector<std::string> argv = {python, script,   "--nx",        nx,       "--ny",
                                       ny,     "--json", json.string(), "--quiet"};
      if (!config.empty()) {
        argv.emplace_back("--config");
        argv.push_back(config);
      }
      const ChildRun run = run_child(argv, environment);
      check_exit(run, fmt::format("the peer ({}) at {}", m.program, row.mesh), kNotConverged);
      const nlohmann::json result = read_json(json, "the peer's result");
      if (config.empty() && result.contains("config"))
        m.config = result["config"].get<std::string>();
      m.program = "petsc_snesvi " + m.config;
      if (timed)
        m.add(run,
              result.contains("seconds") ? number_or_nan(result["seconds"], "total")
                                         : std::numeric_limits<double>::quiet_NaN(),
              number_or_nan(result, "energy"),
              result.value("converged", false) && run.exit_status == 0,
              result.value("active_nodes", -1L), result.value("snes_iterations", -1L));
      std::error_code ec;
      fs::remove(json, ec);
    };
    if (options.interleave) {
      // Repeat by repeat, so that a change in the machine's load affects every program alike;
      // but each run then follows another program's (docs/performance.md).
      for (int r = 0; r < options.repeats; ++r)
        for (std::size_t p = 0; p < row.measured.size(); ++p) run_program(p, r + 1, true);
    } else {
      // Program by program: its warm-up runs, then its timed repeats back to back. A run that
      // follows a larger process waits for the memory that process gave back (on a virtual
      // machine several tenths of a second at 480x160, docs/performance.md); after a warm-up
      // each timed run follows a run of its own program, whatever the other programs' sizes.
      for (std::size_t p = 0; p < row.measured.size(); ++p) {
        for (int w = 0; w < options.warmup; ++w) run_program(p, w + 1, false);
        for (int r = 0; r < options.repeats; ++r) run_program(p, r + 1, true);
      }
    }
    for (std::size_t k = 1; k < row.measured.size(); ++k)
      row.measured[k].relative_difference =
          relative_difference(row.measured[k].energy, row.measured[0].energy);
    rows.push_back(std::move(row));
  }

  fmt::print(
      "\nWhole process, best of {} by wall time (CPU time, page faults and peak memory of that "
      "run from wait4; timers: the program's own phase timers' total; rel. diff: |J - J_signorini| "
      "/ |J_signorini|)\n",
      options.repeats);
  fmt::print("{:>9} {:<25} {:>9} {:>8} {:>8} {:>13} {:>8} {:>10} {:>19} {:>10} {:>8} {:>6}\n",
             "mesh", "program", "wall (s)", "user (s)", "sys (s)", "minor faults", "peak MB",
             "timers (s)", "J(u)", "rel. diff", "ratio", "active");
  bool converged = true, agree = true;
  for (const Row& row : rows) {
    const double base = row.measured[0].best.wall_seconds;
    for (const Measured& m : row.measured) {
      converged = converged && m.converged;
      const bool peer = !m.config.empty();
      const bool off = peer && !(m.relative_difference <= kPeerEnergyTolerance);
      agree = agree && !off;
      fmt::print(
          "{:>9} {:<25} {:>9.3f} {:>8.3f} {:>8.3f} {:>13} {:>8.0f} {:>10.3f} {:>19.11e} {:>10} "
          "{:>8} {:>6}{}\n",
          row.mesh, m.program, m.best.wall_seconds, m.best.user_seconds, m.best.system_seconds,
          with_thousands(m.best.minor_faults), m.best.peak_rss_bytes / 1048576.0, m.timers_total,
          m.energy, peer ? fmt::format("{:.1e}", m.relative_difference) : "-",
          peer ? fmt::format("{:.2f}", m.best.wall_seconds / base) : "1.00", m.active,
          (m.converged ? "" : "  NOT CONVERGED") + std::string(off ? "  <-- ENERGIES DIFFER" : ""));
    }
  }
  if (!python.empty())
    fmt::print(
        "ratio: wall time over signorini's on the same mesh; active: contact nodes in contact. "
        "The peer: PETSc SNESVI, bench/peers/README.md.\n");

  if (!options.json_file.empty()) {
    nlohmann::json j;
    j["benchmark"] = "paper";
    j["mode"] = "whole_process";
    j["repeats"] = options.repeats;
    j["warmup"] = options.interleave ? 0 : options.warmup;
    j["order"] = options.interleave ? "interleaved" : "program by program";
    j["hardware_threads"] = std::thread::hardware_concurrency();
    j["signorini"] = self;
    if (!python.empty()) {
      j["peer_script"] = script;
      j["python"] = python;
    }
    j["rows"] = nlohmann::json::array();
    for (const Row& row : rows)
      for (const Measured& m : row.measured) j["rows"].push_back(to_json(row.mesh, m));
    write_file_atomically(options.json_file, j.dump(2) + "\n");
    fmt::print("rows written to {}\n", options.json_file);
  }

  if (!agree) {
    std::fflush(stdout);
    for (const Row& row : rows)
      for (const Measured& m : row.measured)
        if (!m.config.empty() && !(m.relative_difference <= kPeerEnergyTolerance))
          fmt::print(stderr,
                     "signorini: warning: at {} the peer ({}) has J(u) = {:.11e} and signorini "
                     "{:.11e}: they differ by {:.1e} relative, more than {:.0e}; the two do not "
                     "solve the same discrete problem, or one did not converge\n",
                     row.mesh, m.program, m.energy, row.measured[0].energy, m.relative_difference,
                     kPeerEnergyTolerance);
    return kInternalError;
  }
  return converged ? kSuccess : kNotConverged;
}

}  // namespace signorini::app

// signorini: the command-line front end of the library (run_tool; main.cpp and, for MPI runs,
// mpi_main.cpp are the programs around it).
//
//   signorini --version
//   signorini check examples/paper.toml
//   signorini solve examples/paper.toml -o results/paper
//   signorini solve examples/paper.toml -o results/paper --set mesh.nx=120 --set mesh.ny=40
//   signorini solve examples/paper.toml -o results/ssn --set solver.method=semismooth_newton
//   signorini solve examples/paper.toml -o results/paper --plot --log-format json
//   signorini plot results/paper
//   signorini bench --repeats 3 --json results/bench.json
//
// Exit status: 0 solved (or checked), 2 bad input, 3 not converged (results written anyway),
// 4 numerical failure, 1 anything else. Errors are one line on stderr: "signorini: error: ...".

#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdio>
#include <exception>
#include <new>

#include "commands.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"

namespace {

using namespace signorini::app;

// On several MPI ranks (docs/distributed.md) a failure may be every rank's alike (bad input,
// which each rank finds in the same problem file or agrees on; a solver that fails in a
// collective call) or one rank's alone while the others wait for it in a collective call (its
// part of the mesh, its memory). The failing rank waits a while for the others to fail too: if
// all do, rank 0 says it and each rank returns the status; if not, this rank says it, naming
// itself, and ends them all.
constexpr double kSecondsToMeet = 10.0;

int fail(int status, const std::string& message, const signorini::DistributedEngine* engine) {
  std::fflush(stdout);  // keep the order of what was printed when both go to one terminal
  std::string line = message;
  for (char& c : line)
    if (c == '\n' || c == '\r') c = ' ';
  const bool several = engine != nullptr && engine->size() > 1;
  const bool alone = several && !engine->meet_within(kSecondsToMeet);
  if (!several || alone || engine->rank() == 0)
    fmt::print(stderr, "signorini: error: {}{}\n",
               alone ? fmt::format("rank {}: ", engine->rank()) : "", line);
  if (alone) {
    std::fflush(stderr);
    engine->abort(status);
  }
  return status;
}

// CLI::PositiveNumber's message spells out the largest double; this one says what is expected.
const CLI::Validator kPositive(
    [](const std::string& text) {
      double value = 0.0;
      const bool number = CLI::detail::lexical_cast(text, value);
      return number && std::isfinite(value) && value > 0.0
                 ? std::string()
                 : fmt::format("'{}': expected a positive number", text);
    },
    "POSITIVE");

}  // namespace

namespace signorini::app {

int run_tool(int argc, char** argv, DistributedEngine* engine) {
  CLI::App app{
      "Contact of a linear elastic body with rigid obstacles (the Signorini problem, "
      "frictionless or with Tresca or Coulomb friction), in 2D and 3D, by the "
      "modified-Lagrangian Uzawa method with generalised Newton steps.\n"
      "Exit status: 0 ok, 2 bad input, 3 not converged (results still written), "
      "4 numerical failure, 1 other errors.",
      "signorini"};
  bool show_version = false;
  app.add_flag("--version", show_version, "Print the version and the compiled backends");
  app.require_subcommand(0, 1);

  SolveArguments solve;
  solve.engine = engine;
  CLI::App* solve_cmd = app.add_subcommand("solve", "Solve a problem file and write the results");
  solve_cmd
      ->add_option("PROBLEM", solve.problem_file,
                   "Problem file (TOML, see "
                   "docs/problem-format.md)")
      ->required();
  solve_cmd
      ->add_option("-o,--output", solve.output_dir,
                   "Folder for the results (created if needed; docs/output.md)")
      ->required();
  solve_cmd
      ->add_option("--set", solve.overrides,
                   "Override a setting of the file, e.g. --set mesh.nx=480 (repeatable)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);
  solve_cmd->add_flag("-q,--quiet", solve.quiet,
                      "Print nothing but errors and warnings (no settings, progress, report); a "
                      "solve still running after a minute says so on stderr, then at 2, 4, 8, "
                      "... minutes");
  solve_cmd
      ->add_option("--log-format", solve.log_format,
                   "text (default; a status line on a terminal) or json (one JSON object per "
                   "line, docs/output.md)")
      ->type_name("FORMAT");
  CLI::Option* plot_flag = solve_cmd->add_flag(
      "--plot", solve.plot, "Also draw the figures into the output folder (as signorini plot)");
  solve_cmd
      ->add_option("--scale", solve.plot_options.scale,
                   "With --plot: magnification of the deformed body (default: automatic)")
      ->check(kPositive)
      ->needs(plot_flag);
  solve_cmd
      ->add_option("--plot-format", solve.plot_options.formats,
                   "With --plot: the formats of the figures, png, svg or pdf, or several "
                   "separated by commas (default: png)")
      ->type_name("LIST")
      ->needs(plot_flag);
  solve_cmd
      ->add_option("--plot-steps", solve.plot_options.steps,
                   "With --plot and a loading history: also draw the contact figure of these load "
                   "steps, numbers separated by commas or all")
      ->type_name("LIST")
      ->needs(plot_flag);

  CheckArguments check;
  check.engine = engine;
  CLI::App* check_cmd =
      app.add_subcommand("check", "Validate a problem file and build its model, without solving");
  check_cmd->add_option("PROBLEM", check.problem_file, "Problem file (TOML)")->required();
  check_cmd->add_option("--set", check.overrides, "Override a setting of the file (repeatable)")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);

  PlotArguments plot;
  CLI::App* plot_cmd = app.add_subcommand(
      "plot", "Draw the figures of a solve's output folder as PNG, SVG or PDF (needs matplotlib)");
  plot_cmd->add_option("OUTDIR", plot.output_dir, "Output folder of signorini solve")->required();
  plot_cmd
      ->add_option("--scale", plot.options.scale,
                   "Magnification of the deformed body (default: automatic)")
      ->check(kPositive);
  plot_cmd
      ->add_option("--hertz-radius", plot.options.hertz_radius,
                   "3D: draw Hertz's pressure profile for a sphere of this radius pressed onto a "
                   "rigid plane (default: that of a rigid sphere obstacle, if there is one)")
      ->type_name("R")
      ->check(kPositive);
  plot_cmd
      ->add_option("--symmetry", plot.options.symmetry,
                   "3D: the model is 1/N of the body (symmetry planes held by rollers); Hertz's "
                   "profile takes N times its contact force (default 1)")
      ->type_name("N")
      ->check(CLI::PositiveNumber);
  plot_cmd
      ->add_option("--steps", plot.options.steps,
                   "With a loading history: also draw the contact figure of these load steps "
                   "(from steps/), numbers separated by commas or all")
      ->type_name("LIST");
  plot_cmd
      ->add_option("--format", plot.options.formats,
                   "The formats of the figures: png, svg or pdf, or several separated by commas "
                   "(default: png)")
      ->type_name("LIST");

  BenchArguments bench;
  CLI::App* bench_cmd = app.add_subcommand(
      "bench",
      "Time the paper's benchmark: by default Table 1 beside the paper's (seconds); more meshes "
      "and solver configurations on request (docs/performance.md)");
  bench_cmd->add_option("--repeats,--repeat", bench.repeats, "Best of N runs (default 3)")
      ->check(kPositive);
  bench_cmd->add_flag("--full", bench.full,
                      "The whole suite: meshes up to 1920x640, semismooth Newton, the paper's CG "
                      "configuration and the plain sparse path (minutes)");
  bench_cmd->add_flag("--larger", bench.larger, "Add the meshes 960x320 and 1920x640");
  bench_cmd->add_flag("--huge", bench.huge, "Add the 3840x1280 mesh (9.8 million unknowns)");
  bench_cmd->add_option("--mesh", bench.meshes,
                        "Mesh NXxNY, e.g. 480x160, instead of the paper's four (repeatable)");
  bench_cmd->add_option("--method", bench.methods,
                        "Also this contact method on the condensed problem (repeatable)");
  bench_cmd->add_flag("--cg", bench.cg,
                      "Also the paper's configuration: CG with Jacobi, no condensation (up to "
                      "480x160; about a minute there)");
  bench_cmd->add_flag("--plain", bench.plain,
                      "Also the plain sparse path (no condensation), compared with the condensed "
                      "one");
  bench_cmd->add_flag("--no-cg", bench.no_cg, "With --full: skip the paper's CG configuration");
  bench_cmd->add_flag("--no-plain", bench.no_plain, "With --full: skip the plain sparse path");
  bench_cmd->add_option("--json", bench.json_file, "Also write the results as JSON to this file");
  bench_cmd
      ->add_option("--device", bench.device,
                   "cuda: also solve on the GPU (CG with multigrid, and the paper's CG with "
                   "Jacobi) and compare with the CPU in the same run (docs/gpu.md)")
      ->check(CLI::IsMember({"cpu", "cuda"}));
  bench_cmd->add_flag(
      "--largest", bench.largest,
      "With --device cuda: also the largest nx = 3 ny mesh that fits in GPU memory");
  bench_cmd->add_flag("--whole-process", bench.whole_process,
                      "Run each solve as a separate process (signorini solve) and measure it "
                      "from outside: wall, CPU, page faults, peak memory");
  bench_cmd->add_flag("--peers", bench.peers,
                      "As --whole-process, and the same problem by PETSc SNESVI "
                      "(bench/peers/petsc_snesvi.py; needs python3-petsc4py) in the same run");
  bench_cmd
      ->add_option("--problem", bench.problem_file,
                   "Instead of the paper's benchmark: this problem file's contact solve and whole "
                   "process against one linear solve of the same discrete problem, in the same "
                   "run (bench/hertz_million.sh: a Hertz problem of a million unknowns)")
      ->type_name("FILE");
  bench_cmd
      ->add_option("--peer-config", bench.peer_configs,
                   "With --peers: the peer's configuration (mumps, cholmod, petsc, gamg; "
                   "repeatable; default: the script's)")
      ->type_name("NAME");
  bench_cmd
      ->add_option("--warmup", bench.warmup,
                   "With --whole-process or --peers: untimed runs of each program before its "
                   "timed repeats (default 1)")
      ->check(CLI::NonNegativeNumber);
  bench_cmd->add_flag("--interleave", bench.interleave,
                      "With --whole-process or --peers: run the programs repeat by repeat "
                      "instead of program by program (no warm-up; each run follows another "
                      "program's)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help
    return fail(kBadInput, e.what(), engine);
  }

  try {
    if (show_version) {
      fmt::print("{}", version_text());
      return kSuccess;
    }
    if (*solve_cmd) return run_solve(solve);
    if (*check_cmd) return run_check(check);
    // On several MPI ranks only solve and check take part (docs/distributed.md): the figures
    // and the benchmarks are one process's work, and N copies would race for the same files.
    if (engine != nullptr && engine->size() > 1 && (*plot_cmd || *bench_cmd))
      return fail(kBadInput,
                  fmt::format("signorini {} runs in one process, not on {} MPI ranks: run it "
                              "without mpirun (solve and check run distributed)",
                              *plot_cmd ? "plot" : "bench", engine->size()),
                  engine);
    if (*plot_cmd) return run_plot(plot);
    if (*bench_cmd) return run_bench(bench);
    return fail(kBadInput, "expected a command: solve, check, plot or bench (see signorini --help)",
                engine);
  } catch (const signorini::InputError& e) {
    return fail(kBadInput, e.what(), engine);
  } catch (const signorini::NumericalError& e) {
    return fail(kNumericalError, std::string("numerical failure: ") + e.what(), engine);
  } catch (const std::bad_alloc&) {
    return fail(kInternalError, "out of memory", engine);
  } catch (const std::exception& e) {
    return fail(kInternalError, std::string("internal error: ") + e.what(), engine);
  }
}

}  // namespace signorini::app

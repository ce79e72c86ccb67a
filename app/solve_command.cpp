// `signorini solve PROBLEM.toml -o OUTDIR`: read, echo the settings, build, solve with a progress
// log, report, write the results, and with --plot draw the figures.

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

#include "commands.hpp"
#include "model_loading.hpp"
#include "plotting.hpp"
#include "progress.hpp"
#include "signorini/backend/make_backend.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/output/summary_json.hpp"
#include "signorini/problem/load_stepping.hpp"
#include "signorini/problem/resultants.hpp"
#include "timing_report.hpp"

namespace signorini::app {

namespace {

const std::vector<std::string> kResultFiles = {"summary.json", "contact.csv", "solution.vtu",
                                               "contact.vtu"};

std::string listed(const std::string& folder, const std::vector<std::string>& files) {
  std::string s;
  for (const std::string& f : files) s += (s.empty() ? "" : ", ") + folder + "/" + f;
  return s;
}

nlohmann::json paths(const std::string& folder, const std::vector<std::string>& files) {
  nlohmann::json j = nlohmann::json::array();
  for (const std::string& f : files) j.push_back(folder + "/" + f);
  return j;
}

// The script's one-line message (captured, so that it cannot land in the middle of a status
// line), and our exit status.
int failed_plot(Progress& progress, const PlotRun& run) {
  const int status = exit_status_of(run);
  std::string message = run.errors;
  const std::string prefix = "signorini: error: ";
  if (message.starts_with(prefix)) message.erase(0, prefix.size());
  while (!message.empty() && message.back() == '\n') message.pop_back();
  progress.report("", {{"event", "error"}, {"status", status}, {"message", message}});
  progress.suspend();
  std::fflush(stdout);
  std::fputs(run.errors.c_str(), stderr);
  return status;
}

// -q: a run still solving after a minute says so on stderr (then after 2, 4, 8, ... minutes).
constexpr double kQuietNoteSeconds = 60.0;

int solve(const SolveArguments& args, LogFormat format) {
  // On several MPI ranks (docs/distributed.md) every rank reads the problem and builds the model
  // and takes part in the solve; rank 0 alone reports and writes (the others' stdout goes
  // nowhere: mpi_main.cpp).
  const DistributedEngine* engine = args.engine;
  const bool root = engine == nullptr || engine->rank() == 0;
  LoadedProblem loaded = read_problem_file(args.problem_file, args.overrides);
  ProblemSpec& spec = loaded.spec;
  if (root) print_warnings(loaded);

  Progress::Options options;
  options.quiet = args.quiet || !root;
  if (args.quiet && root) options.note_after_seconds = kQuietNoteSeconds;
  options.format = format;
  options.terminal = format == LogFormat::Text && Progress::is_terminal(stdout);
  Progress progress(spec.solver.method, options);
  if (format == LogFormat::Json)
    for (const std::string& w : loaded.warnings)
      progress.report("", {{"event", "warning"}, {"message", w}});
  // The effective settings, as TOML: the log of a run is enough to repeat it.
  progress.report(fmt::format("# {}: effective settings\n{}\n", loaded.path, loaded.effective_toml),
                  {{"event", "settings"}, {"file", loaded.path}, {"toml", loaded.effective_toml}});

  // Before the solve, so that a missing matplotlib fails in a second and not after a long run.
  if (args.plot) {
    progress.phase("checking the plotting tools");
    const PlotRun run = check_plotting(args.plot_options.formats);
    if (run.status != 0) return failed_plot(progress, run);
  }

  // Likewise a missing GPU (docs/gpu.md): the solve would stop at its first step.
  if (spec.solver.device == DeviceKind::Cuda) {
    progress.phase("opening the GPU");
    (void)make_backend(DeviceKind::Cuda);  // throws InputError, with the reason
  }

  progress.phase("building the model");
  const Model model = build_model_for(loaded, args.engine);
  if (root) {
    const std::vector<std::string> more = model_warnings(loaded, model);
    print_warnings(more);
    if (format == LogFormat::Json)
      for (const std::string& w : more) progress.report("", {{"event", "warning"}, {"message", w}});
  }
  progress.report(fmt::format("model: {} dofs ({} free), {} contact nodes\n", model.num_dofs(),
                              model.dofs.num_free(), model.problem.contact.size()),
                  {{"event", "model"},
                   {"n_dofs", model.num_dofs()},
                   {"n_free_dofs", model.dofs.num_free()},
                   {"n_contact_nodes", model.problem.contact.size()}});
  // Before the solve, so that an unusable -o fails in a second and not after a long run. The
  // files themselves are written only once the solve is over.
  // Rank 0 makes it, and every rank learns whether that failed, so that none waits for the
  // others in the solve.
  std::string folder_error;
  if (root) {
    try {
      create_output_folder(args.output_dir);
    } catch (const InputError& e) {
      folder_error = e.what();
    }
  }
  if (engine != nullptr ? engine->any(!folder_error.empty()) : !folder_error.empty())
    throw InputError(root ? folder_error : "the output folder (rank 0 says why)");

  progress.phase("contact solve");
  ContactSolverOptions solver = model.solver;  // the path planned from the problem's size
  solver.observer = [&progress](const IterationEvent& e) { progress.iteration(e); };
  // [loading]: each step's files as it is solved (steps/, solution.pvd); the last step's
  // results are the run's (write_results below).
  ContactResult result =
      solve_model(model, solver, spec.load_factors, [&](int step, const ContactResult& r) {
        const LoadStepRecord& s = r.summary.load_steps.back();
        progress.report(
            fmt::format("load step {} of {}: factor {:g}, {} ({} outer iterations, {} nodes in "
                        "contact)\n",
                        step, spec.load_factors.size(), s.factor,
                        s.converged ? "converged" : "NOT converged", s.outer_iterations, s.active),
            {{"event", "load_step"},
             {"step", step},
             {"factor", s.factor},
             {"converged", s.converged},
             {"outer_iterations", s.outer_iterations}});
        // (On the ranks' parts of the mesh every rank writes its piece of the step.)
        if (root || model.is_part()) write_load_step(args.output_dir, step, r, model);
      });
  progress.finish_iterations();
  const SolveSummary& summary = result.summary;
  // Once, for the report, the log and summary.json; on the ranks' parts of the mesh by all of
  // them together (docs/distributed.md), else on rank 0.
  const Resultants resultants =
      root || model.is_part() ? compute_resultants(model, result) : Resultants{};
  if (root) {
    nlohmann::json event = summary_to_json(result, model, spec, resultants);
    event.erase("problem");  // the settings event has it
    event["event"] = "summary";
    progress.report(
        fmt::format("\n{}{}\ntimings:\n{}", summary.brief_report(),
                    resultants_report(resultants, model.mesh.dim()), timing_report(model, summary)),
        event);
  }

  // (Every rank of a distributed solve writes its piece of solution.pvtu: write_results.)
  progress.phase("writing the results");
  write_results(args.output_dir, result, model, spec, resultants);
  if (!root) return summary.converged() ? kSuccess : kNotConverged;
  std::vector<std::string> files = kResultFiles;
  if (model.is_part())  // no whole solution.vtu: its pieces (below)
    files.erase(std::find(files.begin(), files.end(), "solution.vtu"));
  if (!spec.load_factors.empty()) {  // and the steps' files in steps/
    files.emplace_back("solution.pvd");
    files.emplace_back("steps");
  }
  if (summary.path == SolvePath::Distributed) {
    files.emplace_back("solution.pvtu");  // and its pieces, unless listed (one rank's)
    for (const std::string& piece : solution_pieces("solution", summary.ranks))
      if (std::find(files.begin(), files.end(), piece) == files.end()) files.push_back(piece);
  }
  progress.report(fmt::format("results: {}\n", listed(args.output_dir, files)),
                  {{"event", "results"}, {"files", paths(args.output_dir, files)}});

  if (!summary.converged()) {
    progress.suspend();
    std::fflush(stdout);
    // The message has the KKT residuals and what to try (solve_contact).
    fmt::print(stderr, "signorini: not converged ({}): {}; results written to '{}'\n",
               enum_to_string(kTerminationNames, summary.termination), summary.message,
               args.output_dir);
  }

  if (args.plot) {
    progress.phase("plotting");
    const PlotRun run = plot_results(args.output_dir, args.plot_options, true);
    if (run.status != 0) return failed_plot(progress, run);
    const std::vector<std::string> figures = drawn_figure_files(args.output_dir, args.plot_options);
    progress.report(fmt::format("figures: {}\n", listed(args.output_dir, figures)),
                    {{"event", "figures"}, {"files", paths(args.output_dir, figures)}});
  }
  return summary.converged() ? kSuccess : kNotConverged;
}

}  // namespace

int run_solve(const SolveArguments& args) {
  const auto format = enum_from_string(kLogFormatNames, args.log_format);
  if (!format)
    throw InputError("--log-format '" + args.log_format + "': expected " +
                     enum_choices(kLogFormatNames));
  if (*format != LogFormat::Json || args.quiet) return solve(args, *format);
  // A program reading the JSON log learns of a failure from the log too (the one-line message
  // still goes to stderr, from main()).
  const auto error_event = [](int status, const std::string& message) {
    std::fflush(stdout);
    fmt::print("{}\n",
               nlohmann::json{{"event", "error"}, {"status", status}, {"message", message}}.dump());
    std::fflush(stdout);
  };
  try {
    return solve(args, *format);
  } catch (const InputError& e) {
    error_event(kBadInput, e.what());
    throw;
  } catch (const NumericalError& e) {
    error_event(kNumericalError, std::string("numerical failure: ") + e.what());
    throw;
  }
}

}  // namespace signorini::app

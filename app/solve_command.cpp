// `signorini solve PROBLEM.toml -o OUTDIR`: read, echo the settings, build, solve with a progress
// log, report, write the results.

#include <fmt/format.h>

#include <cstdio>

#include "commands.hpp"
#include "iteration_log.hpp"
#include "model_loading.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/io/result_writer.hpp"
#include "timing_report.hpp"

namespace signorini::app {

int run_solve(const SolveArguments& args) {
  LoadedProblem loaded = read_problem_file(args.problem_file, args.overrides);
  ProblemSpec& spec = loaded.spec;
  const bool verbose = !args.quiet;
  if (verbose) {
    // The effective settings, as TOML: the log of a run is enough to repeat it.
    fmt::print("# {}: effective settings\n{}\n", loaded.path, loaded.effective_toml);
  }
  const Model model = build_model_for(loaded);
  if (verbose)
    fmt::print("model: {} dofs ({} free), {} contact nodes\n", model.dofs.num_dofs(),
               model.dofs.num_free(), model.problem.contact.size());
  // Before the solve, so that an unusable -o fails in a second and not after a long run. The
  // files themselves are written only once the solve is over.
  create_output_folder(args.output_dir);

  if (verbose) {
    const ContactMethod method = spec.solver.method;
    spec.solver.observer = [method](const IterationEvent& e) {
      fmt::print("{}\n", iteration_line(method, e));
      std::fflush(stdout);  // progress is for watching a long run as it goes
    };
  }
  const ContactResult result = solve_contact(model.problem, spec.solver);
  const SolveSummary& summary = result.summary;
  if (verbose)
    fmt::print("\n{}\ntimings:\n{}", summary.brief_report(), timing_report(model, summary));

  write_results(args.output_dir, result, model, spec);
  if (verbose)
    fmt::print("results: {}/summary.json, {}/contact.csv\n", args.output_dir, args.output_dir);

  if (!summary.converged()) {
    std::fflush(stdout);
    fmt::print(stderr,
               "signorini: not converged ({}): {}; KKT residuals: equilibrium {:.2e}, "
               "penetration {:.2e}, sign {:.2e}, complementarity {:.2e}; results written to "
               "'{}'\n",
               enum_to_string(kTerminationNames, summary.termination), summary.message,
               summary.kkt.equilibrium, summary.kkt.penetration, summary.kkt.sign,
               summary.kkt.complementarity, args.output_dir);
    return kNotConverged;
  }
  return kSuccess;
}

}  // namespace signorini::app

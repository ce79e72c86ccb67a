// `signorini plot OUTDIR`: the paper's figures from the results of a solve, as PNG (SVG, PDF on
// request) (tools/plot_results.py, docs/output.md).

#include <fmt/format.h>

#include "commands.hpp"
#include "plotting.hpp"

namespace signorini::app {

int run_plot(const PlotArguments& args) {
  const PlotRun run = plot_results(args.output_dir, args.options, false);
  if (run.status == 0) {
    std::string files;
    for (const std::string& f : drawn_figure_files(args.output_dir, args.options))
      files += (files.empty() ? "" : ", ") + args.output_dir + "/" + f;
    fmt::print("figures: {}\n", files);
    return kSuccess;
  }
  return exit_status_of(run);  // the script has said what went wrong, on stderr
}

}  // namespace signorini::app

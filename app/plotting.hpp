#pragma once
// The figures of an output folder, drawn by tools/plot_results.py with matplotlib in the
// system's Python (docs/output.md, "Figures"). The script is found beside an installed tool
// (share/signorini/) or in the source tree (data_files.hpp); the environment variables
// SIGNORINI_PLOT_SCRIPT and SIGNORINI_PYTHON override the script and the interpreter.

#include <optional>
#include <string>
#include <vector>

namespace signorini::app {

/// What to draw, as `signorini plot` and `solve --plot` take it.
struct PlotOptions {
  std::optional<double> scale;  ///< magnification of the deformed body; empty: automatic
  /// 3D: the radius of Hertz's profile drawn beside the pressure; empty: that of a rigid sphere
  /// obstacle, if there is one.
  std::optional<double> hertz_radius;
  /// 3D: the model is 1/symmetry of the body; Hertz's profile takes that many times its force.
  int symmetry = 1;
  /// The formats, separated by commas: png, svg, pdf (the script checks them).
  std::string formats = "png";
  /// With a loading history, the load steps whose contact figure is drawn too: numbers
  /// separated by commas, or "all" (the script checks them); empty: none.
  std::string steps;
};

/// The files the script writes into the output folder for `formats` (as PlotOptions::formats)
/// and the problem's dimension (2 or 3), in the order of docs/output.md; `friction`: the 2D
/// results have friction's columns, and contact_friction is drawn too.
std::vector<std::string> figure_files(const std::string& formats, int dimension,
                                      bool friction = false);

/// The files of the figures of load steps (PlotOptions::steps, checked by the script before) in
/// `outdir`: "contact_friction_step_0003.png" and the like, in the order of the steps.
std::vector<std::string> step_figure_files(const std::string& outdir, const std::string& formats,
                                           const std::string& steps);

/// Every figure a run of the script with `options` wrote into `outdir` (figure_files and
/// step_figure_files).
std::vector<std::string> drawn_figure_files(const std::string& outdir, const PlotOptions& options);

/// The dimension of the results in `outdir`, as the script decides it: 3 if contact.csv has a z
/// column, else 2 (also when it cannot be read: the script says why).
int result_dimension(const std::string& outdir);

/// Whether contact.csv in `outdir` has friction's columns (a `state` column), as the script
/// decides it.
bool result_has_friction(const std::string& outdir);

/// How the script ended: its exit status (0 done, 2 a missing package or an unusable folder,
/// which it reports on stderr in one line, 1 a failure of the script) and, when captured, what it
/// wrote to stderr.
struct PlotRun {
  int status = 0;
  std::string errors;
};

/// Runs the script with `arguments`. With `capture`, its stdout goes to /dev/null and its stderr
/// into PlotRun::errors, for the caller to print when the terminal is free (a status line may be
/// on it); otherwise both go where ours go. Throws InputError if there is no Python interpreter
/// or no script.
PlotRun run_plot_script(const std::vector<std::string>& arguments, bool capture);

/// Draws the figures of `outdir`.
PlotRun plot_results(const std::string& outdir, const PlotOptions& options, bool capture);

/// Whether the script can run (numpy and matplotlib are there) and knows `formats`: the script
/// with --check, its stderr captured.
PlotRun check_plotting(const std::string& formats);

/// Our exit status for a run of the script: kSuccess, kBadInput or kInternalError.
int exit_status_of(const PlotRun& run);

}  // namespace signorini::app

#pragma once
// The subcommands of the `signorini` tool and its exit statuses.

#include <string>
#include <vector>

#include "plotting.hpp"

namespace signorini {
class DistributedEngine;  // (contact/distributed_engine.hpp)
}  // namespace signorini

namespace signorini::app {

/// Exit statuses, documented in `signorini --help` and docs/problem-format.md.
enum ExitStatus : int {
  kSuccess = 0,         ///< solved and converged (or: the check passed)
  kInternalError = 1,   ///< a bug or an unexpected failure (e.g. out of memory)
  kBadInput = 2,        ///< the problem file, an option or the output folder is unusable, or
                        ///< plotting lacks python3/matplotlib
  kNotConverged = 3,    ///< the solver stopped short; results are written with converged = false
  kNumericalError = 4,  ///< a numerical failure (e.g. a factorisation of an SPD matrix failed)
};

struct SolveArguments {
  /// The program's distributed engine (signorini-mpi's, docs/distributed.md); null in the serial
  /// tool.
  DistributedEngine* engine = nullptr;
  std::string problem_file;
  std::string output_dir;
  std::vector<std::string> overrides;  ///< --set key=value
  bool quiet = false;
  std::string log_format = "text";  ///< "text" or "json" (one JSON object per line)
  bool plot = false;                ///< also draw the figures (as `signorini plot`)
  PlotOptions plot_options;         ///< --scale, --plot-format
};

struct PlotArguments {
  std::string output_dir;
  PlotOptions options;  ///< --scale, --format, --hertz-radius
};

struct CheckArguments {
  DistributedEngine* engine = nullptr;  ///< as SolveArguments::engine
  std::string problem_file;
  std::vector<std::string> overrides;
};

struct BenchArguments {
  int repeats = 3;                   ///< best of N
  bool full = false;                 ///< the whole suite (full_benchmark_options())
  bool larger = false;               ///< add 960x320 and 1920x640
  bool huge = false;                 ///< add 3840x1280 (9.8 million unknowns)
  std::vector<std::string> meshes;   ///< "480x160", ...; empty: the paper's four
  std::vector<std::string> methods;  ///< more contact methods on the condensed problem
  bool cg = false;                   ///< add the paper's configuration (uzawa_gnm with CG)
  bool plain = false;                ///< add the plain sparse path and the comparison with it
  bool no_cg = false;                ///< with --full: skip the paper's configuration
  bool no_plain = false;             ///< with --full: skip the plain sparse path
  std::string json_file;             ///< also write the rows as JSON here
  std::string device = "cpu";        ///< "cuda": add the GPU configurations and the GPU table
  bool largest = false;  ///< with cuda: also the largest nx = 3 ny mesh that fits on the GPU
  /// Each run a separate process (`signorini solve`), measured from outside: wall, CPU, page
  /// faults, peak memory (whole_process_bench.hpp).
  bool whole_process = false;
  bool peers = false;                     ///< with the whole process: also the PETSc peer
  std::vector<std::string> peer_configs;  ///< the peer's --config values; empty: its default
  int warmup = -1;          ///< whole process: untimed runs per program first (-1: not given, 1)
  bool interleave = false;  ///< whole process: repeat by repeat across programs
  /// A problem file to time against one linear solve instead of the paper's benchmark
  /// (problem_bench.hpp).
  std::string problem_file;
};

/// `signorini bench`: the paper's benchmark on several meshes and solver configurations.
int run_bench(const BenchArguments& args);

/// The whole tool: parses the command line, runs the command, returns the exit status (errors
/// are one line on stderr). main.cpp and mpi_main.cpp call it, the latter with its engine.
int run_tool(int argc, char** argv, DistributedEngine* engine = nullptr);

/// `signorini solve`: returns kSuccess or kNotConverged; throws InputError or NumericalError.
int run_solve(const SolveArguments& args);

/// `signorini check`: reads the file and builds the model without solving.
int run_check(const CheckArguments& args);

/// `signorini plot OUTDIR`: draws the figures of a solve's output folder (tools/plot_results.py).
int run_plot(const PlotArguments& args);

/// "signorini 0.1.0" and the compiled backends with their versions, several lines.
std::string version_text();

}  // namespace signorini::app

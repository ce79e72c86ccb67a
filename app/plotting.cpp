#include "plotting.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>

#include "commands.hpp"
#include "data_files.hpp"
#include "signorini/core/error.hpp"

extern char** environ;

namespace signorini::app {

namespace {

std::string plotting_python() {
  std::string python = find_python("plotting", "numpy and matplotlib");
  if (python.empty())
    throw InputError(
        "plotting needs python3 with matplotlib, and no python3 was found (Debian: apt-get "
        "install python3-matplotlib)");
  return python;
}

std::string find_script() {
  return find_data_file("plot_results.py", "tools/plot_results.py", "SIGNORINI_PLOT_SCRIPT");
}

}  // namespace

namespace {
// The formats as the script reads --format: lower case, spaces ignored, each format once.
std::vector<std::string> chosen_formats(const std::string& formats) {
  std::vector<std::string> chosen;
  std::size_t start = 0;
  while (start <= formats.size()) {
    const std::size_t end = std::min(formats.find(',', start), formats.size());
    std::string format;
    for (const char c : formats.substr(start, end - start))
      if (!std::isspace(static_cast<unsigned char>(c)))
        format += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (std::find(chosen.begin(), chosen.end(), format) == chosen.end()) chosen.push_back(format);
    start = end + 1;
  }
  return chosen;
}
}  // namespace

std::vector<std::string> figure_files(const std::string& formats, int dimension, bool friction) {
  const std::vector<std::string> chosen = chosen_formats(formats);
  std::vector<std::string> files;
  const std::vector<const char*> names =
      dimension == 3
          ? std::vector<const char*>{"contact_pressure_map", "contact_pressure", "convergence"}
          : std::vector<const char*>{"contact_displacement", "contact_pressure",
                                     "deformed_von_mises", "convergence"};
  std::vector<const char*> all = names;
  if (friction) all.push_back(dimension == 3 ? "contact_friction_map" : "contact_friction");
  for (const char* name : all)
    for (const std::string& format : chosen) files.push_back(fmt::format("{}.{}", name, format));
  return files;
}

std::vector<std::string> step_figure_files(const std::string& outdir, const std::string& formats,
                                           const std::string& steps) {
  std::string text;
  for (const char c : steps)
    if (!std::isspace(static_cast<unsigned char>(c))) text += c;
  if (text.empty()) return {};
  // The steps: those listed, or with "all" every steps/contact_NNNN.csv there is.
  std::vector<int> numbers;
  if (text == "all") {
    for (int k = 1; std::filesystem::exists(std::filesystem::path(outdir) / "steps" /
                                            fmt::format("contact_{:04d}.csv", k));
         ++k)
      numbers.push_back(k);
  } else {
    std::size_t start = 0;
    while (start <= text.size()) {
      const std::size_t end = std::min(text.find(',', start), text.size());
      numbers.push_back(std::stoi(text.substr(start, end - start)));
      start = end + 1;
    }
    std::sort(numbers.begin(), numbers.end());
    numbers.erase(std::unique(numbers.begin(), numbers.end()), numbers.end());
  }
  const int dimension = result_dimension(outdir);
  const bool friction = result_has_friction(outdir);
  const std::string base = dimension == 3
                               ? (friction ? "contact_friction_map" : "contact_pressure_map")
                               : (friction ? "contact_friction" : "contact_pressure");
  std::vector<std::string> files;
  for (const int k : numbers)
    for (const std::string& format : chosen_formats(formats))
      files.push_back(fmt::format("{}_step_{:04d}.{}", base, k, format));
  return files;
}

namespace {
// Whether contact.csv's header in `outdir` has the column `name` (false when it cannot be read:
// the script says why).
bool has_column(const std::string& outdir, const std::string& name) {
  std::ifstream in(std::filesystem::path(outdir) / "contact.csv");
  std::string header;
  if (!in || !std::getline(in, header)) return false;
  std::size_t start = 0;
  while (start <= header.size()) {
    const std::size_t end = std::min(header.find(',', start), header.size());
    std::string column;
    for (const char c : header.substr(start, end - start))
      if (!std::isspace(static_cast<unsigned char>(c))) column += c;
    if (column == name) return true;
    start = end + 1;
  }
  return false;
}
}  // namespace

std::vector<std::string> drawn_figure_files(const std::string& outdir, const PlotOptions& options) {
  std::vector<std::string> files =
      figure_files(options.formats, result_dimension(outdir), result_has_friction(outdir));
  for (std::string& f : step_figure_files(outdir, options.formats, options.steps))
    files.push_back(std::move(f));
  return files;
}

int result_dimension(const std::string& outdir) {
  return has_column(outdir, "z") ? 3 : 2;
}

bool result_has_friction(const std::string& outdir) {
  return has_column(outdir, "state");
}

PlotRun run_plot_script(const std::vector<std::string>& arguments, bool capture) {
  std::vector<std::string> argv_text = {plotting_python(), find_script()};
  argv_text.insert(argv_text.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);

  // An unnamed temporary file, removed when closed, takes the script's stderr.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> errors(capture ? std::tmpfile() : nullptr,
                                                         &std::fclose);
  if (capture && !errors) throw std::runtime_error("plotting: cannot create a temporary file");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (capture) {
    posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, ::fileno(errors.get()), STDERR_FILENO);
  }
  // What was printed so far comes before what the script prints.
  std::fflush(stdout);
  std::fflush(stderr);
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw InputError(fmt::format("plotting: cannot run '{}': {}", argv_text[0], std::strerror(rc)));
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0) {
    if (errno != EINTR) throw std::runtime_error("plotting: waitpid failed");
  }
  PlotRun run;
  if (capture) {
    std::rewind(errors.get());
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, errors.get())) > 0)
      run.errors.append(buffer, n);
  }
  if (!WIFEXITED(status))
    throw std::runtime_error(
        fmt::format("plotting: the plot script was ended by signal {}", WTERMSIG(status)));
  run.status = WEXITSTATUS(status);
  return run;
}

PlotRun plot_results(const std::string& outdir, const PlotOptions& options, bool capture) {
  std::vector<std::string> arguments = {"--quiet", "--format", options.formats};
  if (options.scale) {
    arguments.emplace_back("--scale");
    arguments.push_back(fmt::format("{:.17g}", *options.scale));
  }
  if (options.hertz_radius) {
    arguments.emplace_back("--hertz-radius");
    arguments.push_back(fmt::format("{:.17g}", *options.hertz_radius));
  }
  if (options.symmetry != 1) {
    arguments.emplace_back("--symmetry");
    arguments.push_back(std::to_string(options.symmetry));
  }
  if (!options.steps.empty()) {
    arguments.emplace_back("--steps");
    arguments.push_back(options.steps);
  }
  arguments.emplace_back("--");  // a folder named "-x" is not an option
  arguments.push_back(outdir);
  return run_plot_script(arguments, capture);
}

PlotRun check_plotting(const std::string& formats) {
  return run_plot_script({"--check", "--format", formats}, true);
}

int exit_status_of(const PlotRun& run) {
  if (run.status == 0) return kSuccess;
  return run.status == kBadInput ? kBadInput : kInternalError;
}

}  // namespace signorini::app

#pragma once
// Running another program as a child process and measuring it as the shell's `time` would: wall
// time from start to exit, and the kernel's account of the child from wait4() (CPU time, page
// faults, peak resident memory). Used by `signorini bench --whole-process` (docs/performance.md,
// "Whole process and the PETSc peer").

#include <filesystem>
#include <string>
#include <vector>

namespace signorini::app {

/// What one run of a child cost, and how it ended.
struct ChildRun {
  int exit_status = -1;  ///< the exit status, or -1 when it was ended by a signal
  int signal = 0;        ///< the signal that ended it, or 0
  double wall_seconds = 0.0;
  double user_seconds = 0.0;    ///< CPU time in user mode (the child and what it waited for)
  double system_seconds = 0.0;  ///< CPU time in the kernel
  long minor_faults = 0;        ///< page faults served without I/O (first touches, mostly)
  long major_faults = 0;        ///< page faults that needed I/O
  double peak_rss_bytes = 0.0;  ///< the largest resident set (ru_maxrss)
  std::string errors;           ///< what it wrote to stderr (when captured)
};

/// Runs argv[0] (a path, not looked up on PATH) with `argv` and the environment `environment`
/// ("NAME=value" entries), stdin from /dev/null and stdout to /dev/null; its stderr is captured
/// into ChildRun::errors. Waits for it. Throws std::runtime_error when it cannot be started.
ChildRun run_child(const std::vector<std::string>& argv,
                   const std::vector<std::string>& environment);

/// This process's environment, as "NAME=value" entries, without the settings that the tool's
/// own start-up tuning added (process_tuning.hpp): the environment the user started the tool
/// with, as far as it can be told, so that a child runs as it would from the shell.
std::vector<std::string> user_environment();

/// A folder under $TMPDIR (or /tmp) for a benchmark's files and the children's results, removed
/// with everything in it at the end. Throws InputError when it cannot be made.
class ScratchFolder {
 public:
  ScratchFolder();
  ~ScratchFolder();
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  [[nodiscard]] const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// The path of the running executable (/proc/self/exe resolved), or "/proc/self/exe".
std::string own_executable();

}  // namespace signorini::app

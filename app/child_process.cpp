#include "child_process.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <stdlib.h>  // mkdtemp
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string_view>

#include "process_tuning.hpp"
#include "signorini/core/error.hpp"

extern char** environ;

namespace signorini::app {

namespace {

// What process_tuning.cpp adds to the environment before it re-executes the tool: its marker,
// OPENBLAS_NUM_THREADS=1 and its malloc tunables, appended to the user's GLIBC_TUNABLES (after
// a ':') when the user had set no glibc.malloc tunable (process_tuning.hpp declares them).
constexpr std::string_view kTunedMarker = kProcessTunedMarker;
constexpr std::string_view kTunedMalloc = kTunedMallocSettings;

double seconds(const timeval& t) {
  return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
}

}  // namespace

ChildRun run_child(const std::vector<std::string>& argv,
                   const std::vector<std::string>& environment) {
  if (argv.empty()) throw std::runtime_error("run_child: no program");
  std::vector<std::string> args = argv, env = environment;
  std::vector<char*> c_args, c_env;
  for (std::string& a : args) c_args.push_back(a.data());
  c_args.push_back(nullptr);
  for (std::string& e : env) c_env.push_back(e.data());
  c_env.push_back(nullptr);

  // An unnamed temporary file, removed when closed, takes the child's stderr.
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> errors(std::tmpfile(), &std::fclose);
  if (!errors) throw std::runtime_error("cannot create a temporary file for a child's stderr");
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDIN_FILENO, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, ::fileno(errors.get()), STDERR_FILENO);
  std::fflush(stdout);
  std::fflush(stderr);

  const auto start = std::chrono::steady_clock::now();
  pid_t pid = 0;
  const int rc = ::posix_spawn(&pid, c_args[0], &actions, nullptr, c_args.data(), c_env.data());
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0)
    throw std::runtime_error(fmt::format("cannot run '{}': {}", argv[0], std::strerror(rc)));
  int status = 0;
  rusage usage{};
  while (::wait4(pid, &status, 0, &usage) < 0) {
    if (errno != EINTR)
      throw std::runtime_error(fmt::format("waiting for '{}': {}", argv[0], std::strerror(errno)));
  }
  const auto end = std::chrono::steady_clock::now();

  ChildRun run;
  run.wall_seconds = std::chrono::duration<double>(end - start).count();
  run.user_seconds = seconds(usage.ru_utime);
  run.system_seconds = seconds(usage.ru_stime);
  run.minor_faults = usage.ru_minflt;
  run.major_faults = usage.ru_majflt;
  run.peak_rss_bytes = static_cast<double>(usage.ru_maxrss) * 1024.0;  // kilobytes on Linux
  if (WIFEXITED(status)) {
    run.exit_status = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    run.signal = WTERMSIG(status);
  }
  std::rewind(errors.get());
  char buffer[4096];
  std::size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof buffer, errors.get())) > 0) run.errors.append(buffer, n);
  return run;
}

std::vector<std::string> user_environment() {
  std::vector<std::string> env;
  bool tuned = false;
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string_view entry = *e;
    if (entry.substr(0, entry.find('=')) == kTunedMarker) tuned = true;
  }
  for (char** e = environ; *e != nullptr; ++e) {
    std::string entry = *e;
    const std::string_view name = std::string_view(entry).substr(0, entry.find('='));
    if (tuned && name == kTunedMarker) continue;
    if (tuned && entry == "OPENBLAS_NUM_THREADS=1") continue;  // the tuning's (or the user's)
    if (tuned && name == "GLIBC_TUNABLES" && entry.ends_with(kTunedMalloc)) {
      entry.resize(entry.size() - kTunedMalloc.size());
      if (entry.ends_with(':')) entry.pop_back();
      if (entry == "GLIBC_TUNABLES=") continue;
    }
    env.push_back(std::move(entry));
  }
  return env;
}

std::string own_executable() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("/proc/self/exe") : exe.string();
}

ScratchFolder::ScratchFolder() {
  std::string pattern =
      (std::filesystem::temp_directory_path() / "signorini-bench-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr)
    throw InputError(
        fmt::format("cannot create a temporary folder '{}': {}", pattern, std::strerror(errno)));
  path_ = pattern;
}

ScratchFolder::~ScratchFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

}  // namespace signorini::app

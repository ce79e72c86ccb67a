#pragma once
// Running the `signorini` tool from a test: both streams captured, the exit status decoded.

#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "temporary_folder.hpp"

namespace signorini::testing {

struct ToolRun {
  int status = -1;
  std::string out;
  std::string err;
};

inline std::string read_text(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

/// 'text', for a shell command line (the paths of the tests have no single quotes).
inline std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

/// Runs the tool with `arguments` (already quoted where needed) and stdin from /dev/null;
/// `environment` ("NAME=value ...", quoted where needed) is set for it alone.
inline ToolRun run_tool(const TemporaryFolder& dir, const std::string& arguments,
                        const std::string& environment = "") {
  const std::filesystem::path out = dir / "stdout.txt";
  const std::filesystem::path err = dir / "stderr.txt";
  const std::string command = (environment.empty() ? "" : "env " + environment + " ") +
                              quoted(SIGNORINI_APP_PATH) + " " + arguments + " > " +
                              quoted(out.string()) + " 2> " + quoted(err.string()) + " < /dev/null";
  const int raw = std::system(command.c_str());
  ToolRun r;
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  r.out = read_text(out);
  r.err = read_text(err);
  return r;
}

inline std::size_t count_lines(const std::string& text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

}  // namespace signorini::testing

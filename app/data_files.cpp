#include "data_files.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini::app {

std::string find_data_file(const std::string& relative, const std::string& source_relative,
                           const char* env_override) {
  namespace fs = std::filesystem;
  if (const char* chosen = std::getenv(env_override)) {
    std::error_code ec;
    if (!fs::is_regular_file(chosen, ec))
      throw InputError(fmt::format("{} = '{}' is not a file (expected the path of {})",
                                   env_override, chosen, relative));
    return chosen;
  }
  std::vector<fs::path> places;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) places.push_back(exe.parent_path().parent_path() / SIGNORINI_DATA_SUBDIR / relative);
  places.push_back(fs::path(SIGNORINI_SOURCE_DIR) / source_relative);
  for (const fs::path& place : places)
    if (fs::is_regular_file(place, ec)) return place.string();
  std::string tried;
  for (const fs::path& place : places) tried += (tried.empty() ? "" : ", ") + place.string();
  throw InputError(fmt::format("{} not found (looked in {}); set {} to its path", relative, tried,
                               env_override));
}

namespace {
bool executable(const std::filesystem::path& path) {
  std::error_code ec;
  return !path.empty() && std::filesystem::is_regular_file(path, ec) &&
         ::access(path.c_str(), X_OK) == 0;
}
}  // namespace

std::string find_python(const std::string& purpose, const std::string& packages) {
  if (const char* chosen = std::getenv("SIGNORINI_PYTHON")) {
    if (!executable(chosen))
      throw InputError(
          fmt::format("{}: SIGNORINI_PYTHON = '{}' is not an executable file: expected a Python 3 "
                      "interpreter with {}",
                      purpose, chosen, packages));
    return chosen;
  }
  if (executable("/usr/bin/python3")) return "/usr/bin/python3";
  if (const char* path = std::getenv("PATH")) {
    const std::string dirs = path;
    std::size_t start = 0;
    while (start <= dirs.size()) {
      const std::size_t end = std::min(dirs.find(':', start), dirs.size());
      const std::string dir = dirs.substr(start, end - start);
      const std::filesystem::path candidate =
          std::filesystem::path(dir.empty() ? "." : dir) / "python3";
      if (executable(candidate)) return candidate.string();
      start = end + 1;
    }
  }
  return "";
}

}  // namespace signorini::app

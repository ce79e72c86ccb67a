#include "data_files.hpp"

#include <fmt/format.h>

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

}  // namespace signorini::app

#pragma once
// A fresh folder under the system's temporary directory, removed with everything in it at the
// end of the test (also used by tests/app).

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <string>

namespace signorini::testing {

class TemporaryFolder {
 public:
  TemporaryFolder() {
    // Process id and a counter: tests run in parallel by ctest never share a folder.
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("signorini_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  ~TemporaryFolder() {
    std::error_code ec;  // a destructor must not throw; a leftover in /tmp is harmless
    std::filesystem::permissions(path_, std::filesystem::perms::owner_all,
                                 std::filesystem::perm_options::add, ec);
    std::filesystem::remove_all(path_, ec);
  }

  [[nodiscard]] const std::filesystem::path& path() const { return path_; }
  [[nodiscard]] std::filesystem::path operator/(const std::string& name) const {
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace signorini::testing

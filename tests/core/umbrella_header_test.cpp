// The umbrella header signorini/signorini.hpp reaches every public header: a user who includes
// it has the whole API (solve_model of problem/load_stepping.hpp was once left out). Followed
// through the headers' own #include "signorini/..." lines, from the source tree.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "signorini/signorini.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

TEST(UmbrellaHeader, ReachesEveryPublicHeader) {
  const fs::path include = fs::path(SIGNORINI_TEST_DATA_DIR) / ".." / "include";
  const std::regex line(R"(^\s*#\s*include\s*"(signorini/[^"]+)\")");
  std::set<std::string> reached;
  std::vector<std::string> todo{"signorini/signorini.hpp"};
  while (!todo.empty()) {
    const std::string header = todo.back();
    todo.pop_back();
    if (!reached.insert(header).second) continue;
    std::ifstream in(include / header);
    if (!in) continue;  // (config.hpp is made by the build, in the build tree)
    std::string text;
    std::smatch m;
    while (std::getline(in, text))
      if (std::regex_search(text, m, line)) todo.push_back(m[1].str());
  }
  std::vector<std::string> missing;
  for (const auto& entry : fs::recursive_directory_iterator(include / "signorini")) {
    // (eigen_sparse_move.hpp goes inside Eigen's SparseMatrix, through the compile definition
    // EIGEN_SPARSEMATRIX_PLUGIN, not an #include.)
    if (entry.path().extension() != ".hpp" || entry.path().filename() == "eigen_sparse_move.hpp")
      continue;
    const std::string name = fs::relative(entry.path(), include).generic_string();
    if (!reached.contains(name)) missing.push_back(name);
  }
  EXPECT_TRUE(missing.empty()) << "not reached from signorini/signorini.hpp: " << [&] {
    std::string out;
    for (const std::string& m : missing) out += m + " ";
    return out;
  }();
  EXPECT_GT(reached.size(), 40u);
}

}  // namespace
}  // namespace signorini

// The library's layering (docs/design/architecture.md): each module of src/signorini/ and
// include/signorini/ includes only modules of lower layers, so that a new obstacle shape touches
// interface/, a new contact law contact/, a new backend backend/. Read from the source tree's
// #include "signorini/<module>/..." lines.
//
// The edges that still break the layering are listed in kKnownViolations: the test fails when a
// new one appears, and also when a listed one is gone (then delete it from the list).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <utility>

namespace signorini {
namespace {

namespace fs = std::filesystem;

// The layers, lowest first: a module may include the modules of lower layers only.
const std::map<std::string, int> kLayer = {
    {"core", 0},                         // types, errors, option tables, timing
    {"mesh", 1},      {"backend", 1},    // cells and readers; vectors on devices
    {"fem", 2},       {"iterative", 2},  // elements, assembly; CG and multigrid
    {"linalg", 3},    {"parallel", 3},   // factorisations; communication, partitions
    {"interface", 4},                    // what touches what: sets, obstacles, gaps
    {"contact", 5},                      // laws and the solvers' loops
    {"petsc", 6},                        // the distributed backend of the loops
    {"problem", 7},                      // the model pipeline
    {"input", 8},     {"benchmark", 8},  // problem files; the paper's benchmark
    {"output", 9},                       // result files
};

// (from, to) edges that break the layering today, to be removed.
const std::set<std::pair<std::string, std::string>> kKnownViolations = {};

std::map<std::pair<std::string, std::string>, std::string> module_edges() {
  const fs::path root = fs::path(SIGNORINI_TEST_DATA_DIR) / "..";
  const std::regex line(R"(^\s*#\s*include\s*[<"]signorini/([a-z_]+)/[^">]+[">])");
  std::map<std::pair<std::string, std::string>, std::string> edges;  // -> an example file
  for (const char* base : {"src/signorini", "include/signorini"})
    for (const auto& entry : fs::recursive_directory_iterator(root / base)) {
      if (!entry.is_regular_file()) continue;
      const fs::path relative = fs::relative(entry.path(), root / base);
      const std::string from = relative.begin()->string();
      if (!kLayer.contains(from)) continue;
      std::ifstream in(entry.path());
      std::string text;
      std::smatch m;
      while (std::getline(in, text))
        if (std::regex_search(text, m, line) && m[1] != from && kLayer.contains(m[1]))
          edges.emplace(std::pair(from, m[1].str()), (fs::path(base) / relative).generic_string());
    }
  return edges;
}

TEST(Layering, EveryModuleHasALayer) {
  const fs::path src = fs::path(SIGNORINI_TEST_DATA_DIR) / ".." / "src" / "signorini";
  for (const auto& entry : fs::directory_iterator(src)) {
    if (!entry.is_directory()) continue;
    EXPECT_TRUE(kLayer.contains(entry.path().filename().string()))
        << entry.path().filename() << ": give the new module a layer here";
  }
}

TEST(Layering, ModulesIncludeLowerLayersOnly) {
  const auto edges = module_edges();
  ASSERT_GT(edges.size(), 20U);  // (the source tree was found)
  std::set<std::pair<std::string, std::string>> violations;
  for (const auto& [edge, file] : edges)
    if (kLayer.at(edge.second) >= kLayer.at(edge.first)) {
      violations.insert(edge);
      EXPECT_TRUE(kKnownViolations.contains(edge))
          << file << ": " << edge.first << " (layer " << kLayer.at(edge.first) << ") includes "
          << edge.second << " (layer " << kLayer.at(edge.second) << ")";
    }
  for (const auto& edge : kKnownViolations)
    EXPECT_TRUE(violations.contains(edge)) << edge.first << " no longer includes " << edge.second
                                           << ": delete the edge from kKnownViolations";
}

}  // namespace
}  // namespace signorini

// examples/pressed_block.toml from the command line: a prescribed displacement, a normal pressure
// and two contact boundaries with obstacles of their own. Uzawa-GNM and classical Uzawa solve the
// same discrete problem; semismooth Newton, which needs one normal displacement per node, refuses
// the corner that both boundaries share (its two constraints act along the cylinder's and the
// wall's normals); contact.csv and summary.json name both boundaries.

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "app/contact_csv_rows.hpp"
#include "app/tool_run.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

struct Solved {
  nlohmann::json summary;
  std::vector<double> pressure;
  std::map<std::string, int> nodes, touching;  // per contact boundary
};

Solved solve(const testing::TemporaryFolder& dir, const std::string& method,
             const std::string& extra = "") {
  const std::string example = SIGNORINI_EXAMPLES_DIR "/pressed_block.toml";
  const fs::path out = dir / method;
  const ToolRun r = run_tool(dir, "solve " + quoted(example) + " -q --set " +
                                      quoted("solver.method=\"" + method + "\"") + " " + extra +
                                      " -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  Solved s;
  std::ifstream js(out / "summary.json");
  s.summary = nlohmann::json::parse(js);
  for (const testing::ContactCsvRow& row : testing::contact_csv_rows(out / "contact.csv")) {
    s.pressure.push_back(row.pressure);
    s.nodes[row.boundary] += 1;
    s.touching[row.boundary] += row.pressure > 0.0 ? 1 : 0;
  }
  return s;
}

TEST(PressedBlock, TwoMethodsAgreeOnBothContactBoundaries) {
  const testing::TemporaryFolder dir;
  const Solved gnm = solve(dir, "uzawa_gnm");
  // Classical Uzawa's own rule stops it where the pressures still differ by 2e-5 of the largest;
  // with the change of l below 1e-12 it agrees.
  const Solved classical = solve(dir, "classical_uzawa", "--set solver.uzawa_tolerance=1e-12");
  // Semismooth Newton says why it cannot, in one line (exit status 2).
  const ToolRun refused =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/pressed_block.toml") +
                        " -q --set 'solver.method=\"semismooth_newton\"' -o " +
                        quoted((dir / "ssn").string()));
  EXPECT_EQ(refused.status, 2);
  EXPECT_NE(refused.err.find("is in two contact boundaries, each with its own normal: this "
                             "method needs one normal displacement per node; use "
                             "solver.method = \"uzawa_gnm\""),
            std::string::npos)
      << refused.err;
  EXPECT_FALSE(fs::exists(dir / "ssn" / "summary.json"));
  const Solved& ssn = gnm;  // (the reference below)
  for (const Solved* s : {&gnm, &classical}) {
    EXPECT_TRUE(s->summary["converged"].get<bool>());
    EXPECT_LT(s->summary["resultants"]["relative_balance"].get<double>(), 1e-10);
    // 32 + 1 and 16 + 1 cells' ends plus the mid-edge nodes of the quad9 cells.
    EXPECT_EQ(s->nodes.at("bottom"), 65);
    EXPECT_EQ(s->nodes.at("right"), 33);
    EXPECT_GT(s->touching.at("bottom"), 0);
    EXPECT_GT(s->touching.at("right"), 0);
  }
  // The pressures of classical Uzawa and Uzawa-GNM agree to 1e-8 of the largest.
  double peak = 0.0;
  for (const double p : ssn.pressure) peak = std::max(peak, p);
  ASSERT_EQ(gnm.pressure.size(), ssn.pressure.size());
  ASSERT_EQ(classical.pressure.size(), ssn.pressure.size());
  for (std::size_t j = 0; j < ssn.pressure.size(); ++j) {
    EXPECT_NEAR(classical.pressure[j], ssn.pressure[j], 1e-8 * peak) << j;
  }
  // The plate's reaction, and the two obstacles' force together, balance the pressure on top.
  const auto& r = ssn.summary["resultants"];
  ASSERT_EQ(r["reactions"].size(), 1U);
  EXPECT_EQ(r["reactions"][0]["boundary"], "left");
  EXPECT_NEAR(r["applied"][1].get<double>(), -5.0 * 2.0, 1e-12);  // p times the top's length
  EXPECT_LT(r["contact"][0].get<double>(), 0.0);                  // the wall pushes back
  EXPECT_GT(r["contact"][1].get<double>(), 0.0);                  // the cylinder holds it up
  // The settings as given: a displacement, a pressure, two contact tables.
  const auto& problem = ssn.summary["problem"];
  EXPECT_EQ(problem["displacement"][0]["x"], "0.001");
  EXPECT_EQ(problem["pressure"][0]["p"], "5.0");
  ASSERT_TRUE(problem["contact"].is_array());
  EXPECT_EQ(problem["contact"][0]["obstacle"], "disc");
  EXPECT_EQ(problem["contact"][1]["obstacle"], "plane");
}

}  // namespace
}  // namespace signorini

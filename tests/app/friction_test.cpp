// examples/paper_coulomb.toml from the command line: Coulomb friction through the problem file,
// contact.csv's friction columns checked against the law node by node (|t| <= mu p, at the bound
// where sliding), summary.json's counts and resultants, and mu = 0 against the frictionless tool
// run (a different path: the condensed one).

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/tool_run.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

struct Row {
  double x = 0.0, pressure = 0.0, tangential = 0.0;
  std::string state;
};

struct ToolResult {
  nlohmann::json summary;
  std::vector<Row> rows;
};

// Solves `example` (examples/paper_coulomb.toml by default) with the extra arguments into
// dir/name, and reads summary.json and contact.csv (friction's columns where it has them).
ToolResult solve(const testing::TemporaryFolder& dir, const std::string& name,
                 const std::string& extra,
                 const std::string& example = SIGNORINI_EXAMPLES_DIR "/paper_coulomb.toml") {
  const fs::path out = dir / name;
  const ToolRun r =
      run_tool(dir, "solve " + quoted(example) + " -q " + extra + " -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 0) << r.err;
  ToolResult run;
  std::ifstream js(out / "summary.json");
  run.summary = nlohmann::json::parse(js);
  std::istringstream csv(testing::read_text(out / "contact.csv"));
  std::string line;
  std::getline(csv, line);
  const bool friction = line.find(",tangential,slip,state") != std::string::npos;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    Row row{std::stod(f.at(0)), std::stod(f.at(4)), 0.0, ""};
    if (friction) {
      row.tangential = std::stod(f.at(10));
      row.state = f.at(12);
    }
    run.rows.push_back(row);
  }
  return run;
}

TEST(FrictionTool, CoulombExampleMeetsTheLawNodeByNode) {
  const testing::TemporaryFolder dir;
  const ToolResult run = solve(dir, "coulomb", "");
  const nlohmann::json& s = run.summary;
  ASSERT_TRUE(s["converged"].get<bool>()) << s["message"];
  EXPECT_EQ(s["friction"]["law"], "coulomb");
  EXPECT_EQ(s["path"], "condensed_direct");  // 2D friction: condensed onto the contact dofs
  EXPECT_LT(s["kkt"]["friction_bound"].get<double>(), 1e-7);
  EXPECT_LT(s["kkt"]["slip"].get<double>(), 1e-7);
  // The tangential contact forces are in the resultants: the body is in balance.
  EXPECT_LT(s["resultants"]["relative_balance"].get<double>(), 1e-10);
  EXPECT_LT(s["resultants"]["contact"][0].get<double>(), -0.1);  // friction holds it back
  int sticking = 0, sliding = 0;
  double peak = 0.0;
  for (const Row& r : run.rows) peak = std::max(peak, r.pressure);
  for (const Row& r : run.rows) {
    EXPECT_LE(std::abs(r.tangential), 1.0 * r.pressure + 1e-7 * peak) << "x = " << r.x;
    if (r.state == "sliding") {
      ++sliding;
      EXPECT_NEAR(std::abs(r.tangential), r.pressure, 1e-7 * peak) << "x = " << r.x;
    } else if (r.state == "sticking") {
      ++sticking;
      EXPECT_LT(std::abs(r.tangential), r.pressure) << "x = " << r.x;
    } else {
      EXPECT_EQ(r.state, "separated");
      EXPECT_EQ(r.pressure, 0.0);
    }
  }
  EXPECT_EQ(s["friction"]["sticking"].get<int>(), sticking);
  EXPECT_EQ(s["friction"]["sliding"].get<int>(), sliding);
  EXPECT_GT(sticking, 5);  // a stick zone and a slip zone at mu = 1
  EXPECT_GT(sliding, 5);
}

// The three methods from the tool on the same discrete problem: the pressures and tangential
// tractions agree to 1e-8 of the peak pressure.
TEST(FrictionTool, ThreeMethodsAgree) {
  const testing::TemporaryFolder dir;
  const std::string small = "--set mesh.nx=60 --set mesh.ny=20 --set solver.uzawa_tolerance=1e-12 ";
  const ToolResult gnm = solve(dir, "gnm", small);
  const ToolResult ssn =
      solve(dir, "ssn", small + "--set " + quoted("solver.method=\"semismooth_newton\""));
  const ToolResult classical =
      solve(dir, "classical", small + "--set " + quoted("solver.method=\"classical_uzawa\""));
  double peak = 0.0;
  for (const ToolResult* r : {&gnm, &ssn, &classical}) {
    EXPECT_TRUE(r->summary["converged"].get<bool>()) << r->summary["message"];
    ASSERT_EQ(r->rows.size(), gnm.rows.size());
  }
  for (const Row& r : gnm.rows) peak = std::max(peak, r.pressure);
  EXPECT_EQ(ssn.summary["method"], "semismooth_newton");
  for (std::size_t j = 0; j < gnm.rows.size(); ++j)
    for (const ToolResult* r : {&ssn, &classical}) {
      EXPECT_NEAR(r->rows[j].pressure, gnm.rows[j].pressure, 1e-8 * peak) << j;
      EXPECT_NEAR(r->rows[j].tangential, gnm.rows[j].tangential, 1e-8 * peak) << j;
    }
}

TEST(FrictionTool, ZeroFrictionIsTheFrictionlessRun) {
  const testing::TemporaryFolder dir;
  const ToolResult zero = solve(dir, "zero", "--set contact.mu=0");
  EXPECT_TRUE(zero.summary["converged"].get<bool>());
  const ToolResult frictionless = solve(dir, "frictionless", "--set mesh.nx=120 --set mesh.ny=40",
                                        SIGNORINI_EXAMPLES_DIR "/paper.toml");
  ASSERT_EQ(zero.rows.size(), frictionless.rows.size());
  double peak = 0.0;
  for (const Row& r : frictionless.rows) peak = std::max(peak, r.pressure);
  for (std::size_t j = 0; j < zero.rows.size(); ++j) {
    EXPECT_NEAR(zero.rows[j].pressure, frictionless.rows[j].pressure, 1e-8 * peak) << j;
    EXPECT_EQ(zero.rows[j].tangential, 0.0);
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// [loading] from the command line: a file per step, the .pvd series, the history in
// summary.json, and the last step's results as the run's.
TEST(FrictionTool, LoadingHistoryWritesEachStep) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "steps_run";
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/paper_coulomb.toml") +
                        " -q --set mesh.nx=60 --set mesh.ny=20 --set " +
                        quoted("loading.factors=[0.5, 1.0, 0.5]") + " -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  for (const char* f : {"steps/solution_0001.vtu", "steps/solution_0003.vtu",
                        "steps/contact_0002.csv", "solution.pvd", "contact.csv"})
    EXPECT_TRUE(fs::exists(out / f)) << f;
  EXPECT_FALSE(fs::exists(out / "steps/solution_0004.vtu"));
  const std::string pvd = testing::read_text(out / "solution.pvd");
  EXPECT_NE(pvd.find("timestep=\"3\" part=\"0\" file=\"steps/solution_0003.vtu\""),
            std::string::npos);
  std::ifstream js(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(js);
  ASSERT_EQ(s["load_steps"].size(), 3U);
  EXPECT_EQ(s["load_steps"][1]["factor"].get<double>(), 1.0);
  EXPECT_EQ(s["problem"]["loading"]["factors"].size(), 3U);
  // The run's contact.csv is the last step's.
  EXPECT_EQ(testing::read_text(out / "contact.csv"),
            testing::read_text(out / "steps/contact_0003.csv"));
  // Back at half the load after the full one: the body's balance holds at that factor.
  EXPECT_LT(s["resultants"]["relative_balance"].get<double>(), 1e-10);
  EXPECT_NEAR(s["resultants"]["applied"][1].get<double>(), -0.5 * 2.0, 1e-12);
}

}  // namespace
}  // namespace signorini

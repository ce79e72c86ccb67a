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

namespace signorini {
namespace {

// contact.csv's columns by name: every row's values of those whose names start with `prefix`
// (pressure; tangential, or tangential_x, _y and _z in 3D), and the states.
struct Columns {
  std::vector<std::vector<double>> values;  // per row: the chosen columns' values
  std::vector<std::string> states;
};

Columns read_columns(const fs::path& csv_path, const std::vector<std::string>& prefixes) {
  std::istringstream csv(testing::read_text(csv_path));
  std::string line;
  std::getline(csv, line);
  std::vector<std::string> header;
  std::istringstream names(line);
  for (std::string f; std::getline(names, f, ',');) header.push_back(f);
  std::vector<std::size_t> chosen;
  std::size_t state = header.size();
  for (std::size_t k = 0; k < header.size(); ++k) {
    if (header[k] == "state") state = k;
    for (const std::string& p : prefixes)
      if (header[k].rfind(p, 0) == 0) chosen.push_back(k);
  }
  Columns out;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    std::vector<double> row;
    for (const std::size_t k : chosen) row.push_back(std::stod(f.at(k)));
    out.values.push_back(std::move(row));
    out.states.push_back(state < f.size() ? f[state] : "");
  }
  return out;
}

// The friction issue's check: the three methods agree to 1e-8 on every friction example, in 2D
// and 3D, loading histories included (each step's contact.csv): the pressures and tangential
// tractions to 1e-8 of the peak pressure, and every node's state.
TEST(FrictionTool, ThreeMethodsAgreeOnEveryFrictionExample) {
  const testing::TemporaryFolder dir;
  const std::string tight = " --set solver.uzawa_tolerance=1e-12";
  const std::vector<std::pair<std::string, std::string>> examples = {
      {"paper_coulomb.toml", "--set mesh.nx=60 --set mesh.ny=20" + tight},
      {"ssnv128.toml", tight},
      // (classical Uzawa's change of l at 1e-12 leaves its pressures 1.2e-8 of the peak off
      // here; at 1e-13, closer)
      {"cattaneo_mindlin.toml", " --set solver.uzawa_tolerance=1e-13"},
      {"box_on_sphere.toml", "--set " + quoted("contact.friction=\"coulomb\"") +
                                 " --set contact.mu=0.2 --set mesh.nx=6 --set mesh.ny=6" + tight}};
  for (const auto& [example, extra] : examples) {
    SCOPED_TRACE(example);
    std::vector<fs::path> outs;
    for (const char* method : {"uzawa_gnm", "semismooth_newton", "classical_uzawa"}) {
      const fs::path out = dir / (example + "_" + method);
      const ToolRun r = run_tool(
          dir, "solve " + quoted(std::string(SIGNORINI_EXAMPLES_DIR "/") + example) + " -q " +
                   extra + " --set " + quoted(std::string("solver.method=\"") + method + "\"") +
                   " -o " + quoted(out.string()));
      ASSERT_EQ(r.status, 0) << method << ": " << r.err;
      outs.push_back(out);
    }
    // The run's contact.csv and, for a loading history, each step's.
    std::vector<fs::path> files = {"contact.csv"};
    if (fs::exists(outs[0] / "steps"))
      for (const auto& e : fs::directory_iterator(outs[0] / "steps"))
        if (e.path().extension() == ".csv")
          files.push_back(fs::path("steps") / e.path().filename());
    for (const fs::path& file : files) {
      SCOPED_TRACE(file.string());
      const Columns pressure = read_columns(outs[0] / file, {"pressure"});
      double peak = 0.0;
      for (const auto& row : pressure.values) peak = std::max(peak, row.at(0));
      ASSERT_GT(peak, 0.0);
      const Columns gnm = read_columns(outs[0] / file, {"pressure", "tangential"});
      ASSERT_GE(gnm.values.at(0).size(), 2U);
      for (std::size_t m = 1; m < outs.size(); ++m) {
        const Columns other = read_columns(outs[m] / file, {"pressure", "tangential"});
        ASSERT_EQ(other.values.size(), gnm.values.size());
        double worst = 0.0;
        for (std::size_t j = 0; j < gnm.values.size(); ++j)
          for (std::size_t k = 0; k < gnm.values[j].size(); ++k)
            worst = std::max(worst, std::abs(other.values[j][k] - gnm.values[j][k]));
        EXPECT_LE(worst, 1e-8 * peak) << outs[m].filename();
        EXPECT_EQ(other.states, gnm.states) << outs[m].filename();
      }
    }
  }
}

}  // namespace
}  // namespace signorini

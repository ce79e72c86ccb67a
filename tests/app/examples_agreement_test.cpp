// Every example on a Gmsh mesh, solved by the three methods on the same discrete problem: the
// paper's Uzawa-GNM, semismooth Newton and classical Uzawa (to a change of l below 1e-12, its own
// rule stopping it earlier) give the same contact pressures and normal displacements to 1e-8 of
// the largest, with small KKT residuals; and the augmentation parameter r of Uzawa-GNM changes
// the iterations, not the solution (a small r converges slowly, so its run stops at a change of l
// below 1e-11: at the default 1e-8 it stops 2.5e-8 of the largest pressure short).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>

#include "app/contact_csv_rows.hpp"
#include "app/tool_run.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

struct ContactColumns {
  std::vector<double> u_n, pressure;
};

ContactColumns solve(const testing::TemporaryFolder& dir, const std::string& example,
                     const std::string& name, const std::string& settings) {
  const fs::path out = dir / (example + "_" + name);
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/" + example + ".toml") + " -q " +
                        settings + " -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 0) << example << " " << name << ": " << r.err;
  std::ifstream js(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(js);
  EXPECT_TRUE(j["converged"].get<bool>()) << example << " " << name;
  EXPECT_LT(j["kkt"]["equilibrium"].get<double>(), 1e-8) << example << " " << name;
  ContactColumns c;
  for (const testing::ContactCsvRow& row : testing::contact_csv_rows(out / "contact.csv")) {
    c.u_n.push_back(row.u_n);
    c.pressure.push_back(row.pressure);
  }
  return c;
}

double largest(const std::vector<double>& v) {
  double m = 0.0;
  for (const double x : v) m = std::max(m, std::abs(x));
  return m;
}

TEST(ExamplesAgree, ThreeMethodsAndTwoValuesOfR) {
  const testing::TemporaryFolder dir;
  // Measured: the largest differences are 1.6e-9 of the largest pressure (classical Uzawa on
  // paper_gmsh, 16,502 steps) and below 1e-12 between the others.
  for (const char* example : {"hertz", "hertz_p2", "disc_between_planes", "paper_gmsh"}) {
    SCOPED_TRACE(example);
    const ContactColumns gnm = solve(dir, example, "gnm", "");
    const double p = largest(gnm.pressure), u = largest(gnm.u_n);
    ASSERT_GT(p, 0.0);
    const std::vector<std::pair<std::string, std::string>> others = {
        {"ssn", "--set " + quoted("solver.method=\"semismooth_newton\"")},
        {"classical", "--set " + quoted("solver.method=\"classical_uzawa\"") +
                          " --set solver.uzawa_tolerance=1e-12"},
        {"small_r", "--set solver.r=1e5 --set solver.uzawa_tolerance=1e-11"},
        {"large_r", "--set solver.r=1e9"}};
    for (const auto& [name, settings] : others) {
      SCOPED_TRACE(name);
      const ContactColumns c = solve(dir, example, name, settings);
      ASSERT_EQ(c.pressure.size(), gnm.pressure.size());
      for (std::size_t j = 0; j < c.pressure.size(); ++j) {
        EXPECT_NEAR(c.pressure[j], gnm.pressure[j], 1e-8 * p) << j;
        EXPECT_NEAR(c.u_n[j], gnm.u_n[j], 1e-8 * u) << j;
      }
    }
  }
}

}  // namespace
}  // namespace signorini

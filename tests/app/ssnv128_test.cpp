// Code_Aster's validation case SSNV128 (examples/ssnv128.toml): a plate pressed onto a rigid
// base with Coulomb friction (mu = 1), its loads ramped in five steps. The case's reference
// horizontal displacements at five points of the contact face, with its tolerance of 5 %; this
// mesh (32 x 32 bilinear cells) reaches them within 3 % (measured: 0.02 % to 2.7 %).

#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/tool_run.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;

TEST(Ssnv128, HorizontalDisplacementsAlongTheContactFace) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "ssnv128";
  const testing::ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/ssnv128.toml") + " -q -o " +
                        quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream js(out / "summary.json");
  const nlohmann::json s = nlohmann::json::parse(js);
  ASSERT_EQ(s["load_steps"].size(), 5U);
  for (const nlohmann::json& step : s["load_steps"]) EXPECT_TRUE(step["converged"].get<bool>());
  EXPECT_EQ(s["friction"]["law"], "coulomb");
  EXPECT_GT(s["friction"]["sliding"].get<int>(), 0);
  EXPECT_GT(s["friction"]["sticking"].get<int>(), 0);
  // x (m) -> the reference u_x (m) of points A to E.
  const std::map<double, double> reference = {
      {0.0, 2.86e-5}, {0.00125, 2.72e-5}, {0.005, 2.28e-5}, {0.0075, 1.98e-5}, {0.01125, 1.50e-5}};
  std::istringstream csv(testing::read_text(out / "contact.csv"));
  std::string line;
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("x,y,u_n,u_t,", 0), 0U) << line;
  int found = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    const double x = std::stod(f.at(0)), u_t = std::stod(f.at(3));  // tau = +x on the base
    for (const auto& [at, u_ref] : reference)
      if (std::abs(x - at) < 1e-9) {
        ++found;
        EXPECT_NEAR(u_t, u_ref, 0.03 * u_ref) << "x = " << x;
      }
  }
  EXPECT_EQ(found, 5);
}

}  // namespace
}  // namespace signorini

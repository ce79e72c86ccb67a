// `signorini bench --problem FILE` (app/problem_bench.hpp): a problem file's contact solve and
// whole process against one linear solve of the same discrete problem, in the same run.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"

namespace signorini {
namespace {

using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

TEST(BenchProblem, TimesAFileAgainstOneLinearSolve) {
  const testing::TemporaryFolder dir;
  const std::string json = (dir / "bench.json").string();
  const ToolRun r =
      run_tool(dir, "bench --problem " + quoted(SIGNORINI_EXAMPLES_DIR "/pressed_block.toml") +
                        " --repeats 1 --json " + quoted(json));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(r.out, "pressed_block.toml: 4290 unknowns, 98 contact nodes; uzawa_gnm");
  EXPECT_CONTAINS(r.out, "one linear solve (analyse, factorise, solve)");
  EXPECT_CONTAINS(r.out, "whole process (signorini solve, from outside)");
  std::ifstream in(json);
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_TRUE(j["converged"].get<bool>());
  EXPECT_EQ(j["n_dofs"], 4290);
  for (const char* key : {"linear_solve", "contact_solve", "model", "whole_process"})
    EXPECT_GT(j["seconds"][key].get<double>(), 0.0) << key;
  // The whole process includes a contact solve, start-up and output: never less than the solve.
  EXPECT_GT(j["seconds"]["whole_process"].get<double>(),
            j["seconds"]["contact_solve"].get<double>());
  EXPECT_DOUBLE_EQ(
      j["contact_over_linear"].get<double>(),
      j["seconds"]["contact_solve"].get<double>() / j["seconds"]["linear_solve"].get<double>());
}

TEST(BenchProblem, OtherBenchOptionsAreRefused) {
  const testing::TemporaryFolder dir;
  const ToolRun r = run_tool(
      dir, "bench --problem " + quoted(SIGNORINI_EXAMPLES_DIR "/pressed_block.toml") + " --larger");
  EXPECT_EQ(r.status, 2);
  EXPECT_CONTAINS(r.err, "--problem times one problem file: it takes --repeats and --json only");
  const ToolRun missing = run_tool(dir, "bench --problem /no/such.toml");
  EXPECT_EQ(missing.status, 2);
  EXPECT_CONTAINS(missing.err, "cannot read '/no/such.toml'");
}

}  // namespace
}  // namespace signorini

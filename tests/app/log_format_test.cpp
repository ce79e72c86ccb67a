// What `signorini solve` prints, by output kind: plain lines when stdout is not a terminal,
// one JSON object per line with --log-format json, nothing with --quiet (docs/output.md).

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"

namespace signorini {
namespace {

using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

const std::string kSmall = quoted(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");

std::vector<nlohmann::json> json_lines(const std::string& text) {
  std::vector<nlohmann::json> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    EXPECT_NO_THROW(out.push_back(nlohmann::json::parse(line))) << line;
    EXPECT_TRUE(out.back().is_object() && out.back().contains("event")) << line;
  }
  return out;
}

TEST(LogFormat, PlainLinesWhenNotATerminal) {
  const testing::TemporaryFolder dir;
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -o " + quoted((dir / "out").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  // No status line: nothing that only a terminal understands.
  EXPECT_EQ(r.out.find('\r'), std::string::npos);
  EXPECT_EQ(r.out.find('\033'), std::string::npos);
  // Every GNM iteration and every Uzawa step has its line.
  EXPECT_CONTAINS(r.out, "  uzawa 1  gnm 7  active ");
  for (int k = 1; k <= 6; ++k)
    EXPECT_CONTAINS(r.out, "uzawa " + std::to_string(k) + ": ||dl||/||l|| = ");
}

TEST(LogFormat, JsonIsOneObjectPerLine) {
  const testing::TemporaryFolder dir;
  const ToolRun r =
      run_tool(dir, "solve " + kSmall + " --log-format json -o " + quoted((dir / "out").string()));
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  const std::vector<nlohmann::json> events = json_lines(r.out);
  std::vector<std::string> kinds;
  int outer = 0, inner = 0;
  for (const auto& e : events) {
    const std::string kind = e["event"];
    if (kind == "iteration") {
      (e["level"] == "outer" ? outer : inner) += 1;
      for (const char* key : {"outer", "inner", "active", "residual", "armijo"})
        EXPECT_TRUE(e.contains(key)) << key;
    } else {
      kinds.push_back(kind);
    }
  }
  EXPECT_EQ(outer, 6);      // Table 1, 60 x 20: 6 Uzawa steps
  EXPECT_GE(inner, 7 + 5);  // 7 GNM iterations at the first step, at least one later
  EXPECT_EQ(kinds, std::vector<std::string>(
                       {"settings", "phase", "model", "phase", "summary", "phase", "results"}));
  const auto& summary = *std::find_if(events.begin(), events.end(),
                                      [](const auto& e) { return e["event"] == "summary"; });
  EXPECT_EQ(summary["converged"], true);
  EXPECT_EQ(summary["uzawa_iterations"], 6);
  EXPECT_NEAR(summary["M"].get<double>(), -6.700472e-05, 1e-11);
  EXPECT_EQ(events.back()["files"].size(), 4U);
  EXPECT_EQ(events[0]["toml"].get<std::string>().rfind("name = \"paper_small\"", 0), 0U);
}

TEST(LogFormat, JsonReportsErrorsToo) {
  const testing::TemporaryFolder dir;
  const ToolRun r = run_tool(dir, "solve " + kSmall + " --log-format json --set mesh.nx=0 -o " +
                                      quoted((dir / "out").string()));
  EXPECT_EQ(r.status, 2);
  const std::vector<nlohmann::json> events = json_lines(r.out);
  ASSERT_EQ(events.size(), 1U);
  EXPECT_EQ(events[0]["event"], "error");
  EXPECT_EQ(events[0]["status"], 2);
  EXPECT_EQ("signorini: error: " + events[0]["message"].get<std::string>() + "\n", r.err);
}

TEST(LogFormat, QuietPrintsNothing) {
  const testing::TemporaryFolder dir;
  for (const char* format : {"text", "json"}) {
    const ToolRun r = run_tool(dir, "solve " + kSmall + " -q --log-format " + format + " -o " +
                                        quoted((dir / "out").string()));
    EXPECT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.out, "") << format;
    EXPECT_EQ(r.err, "") << format;
  }
}

}  // namespace
}  // namespace signorini

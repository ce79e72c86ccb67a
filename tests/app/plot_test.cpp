// `signorini plot` and `signorini solve --plot`: the figures are written as PNG and SVG, and a
// missing Python or matplotlib is a one-line error with exit status 2 (docs/output.md).

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>

#include "app/tool_run.hpp"
#include "io/expect_contains.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

using testing::count_lines;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

const std::string kSmall = quoted(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");

const std::vector<std::string> kFigures = {"contact_displacement.png", "contact_displacement.svg",
                                           "contact_pressure.png",     "contact_pressure.svg",
                                           "deformed_von_mises.png",   "deformed_von_mises.svg",
                                           "convergence.png",          "convergence.svg"};

// The tool prefers /usr/bin/python3; the figures need its matplotlib (scripts/setup.sh installs
// python3-matplotlib). Without it only the error paths can be tested.
bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, numpy' > /dev/null 2>&1") == 0;
}

// A module folder whose `matplotlib` cannot be imported, as on a machine without it.
std::string without_matplotlib(const testing::TemporaryFolder& dir) {
  fs::create_directories(dir / "fake" / "matplotlib");
  std::ofstream(dir / "fake" / "matplotlib" / "__init__.py")
      << "raise ImportError('No module named matplotlib (simulated)')\n";
  return "PYTHONPATH=" + quoted((dir / "fake").string());
}

TEST(Plot, SolveWithPlotWritesEveryFigure) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " --plot -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  std::string listed;
  for (const std::string& f : kFigures) {
    listed += (listed.empty() ? "" : ", ") + out.string() + "/" + f;
    const std::string contents = testing::read_text(out / f);
    if (f.ends_with(".png"))
      EXPECT_EQ(contents.rfind("\x89PNG\r\n\x1a\n", 0), 0U) << f;
    else
      EXPECT_CONTAINS(contents, "<svg");
  }
  EXPECT_CONTAINS(r.out, "figures: " + listed + "\n");
  // Text stays text in the SVG: titles with the problem and mesh, axes with units.
  const std::string pressure = testing::read_text(out / "contact_pressure.svg");
  EXPECT_CONTAINS(pressure, "paper_small: 60 × 20 mesh");
  EXPECT_CONTAINS(pressure, "contact pressure (MPa)");
  EXPECT_CONTAINS(pressure, "x (m)");
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"), "von Mises stress (MPa)");
  EXPECT_CONTAINS(testing::read_text(out / "convergence.svg"), "GNM iterations");
  // No temporary file is left behind.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 4U + kFigures.size());
}

TEST(Plot, PlotCommandWithAGivenMagnification) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  ASSERT_EQ(run_tool(dir, "solve " + kSmall + " -q -o " + quoted(out.string())).status, 0);
  ToolRun r = run_tool(dir, "plot " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  // The automatic magnification of the paper's figure: 1000.
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"),
                  "displacements magnified s = 1000 times");
  r = run_tool(dir, "plot " + quoted(out.string()) + " --scale 250");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"),
                  "displacements magnified s = 250 times");
}

TEST(Plot, FolderWithoutResults) {
  const testing::TemporaryFolder dir;
  fs::create_directories(dir / "empty");
  const ToolRun r = run_tool(dir, "plot " + quoted((dir / "empty").string()));
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: '" + (dir / "empty" / "summary.json").string() +
                       "' not found: is '" + (dir / "empty").string() +
                       "' the output folder of signorini solve?\n");
}

TEST(Plot, MissingMatplotlibIsExitStatus2BeforeTheSolve) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -q --plot -o " + quoted(out.string()),
                             without_matplotlib(dir));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "signorini: error: plotting needs numpy and matplotlib for ");
  EXPECT_CONTAINS(r.err, "apt-get install python3-matplotlib\n");
  EXPECT_FALSE(fs::exists(out));  // found before the solve: nothing written
  const ToolRun p = run_tool(dir, "plot " + quoted(dir.path().string()), without_matplotlib(dir));
  EXPECT_EQ(p.status, 2);
  EXPECT_EQ(p.err, r.err);
}

TEST(Plot, MissingPythonIsExitStatus2) {
  const testing::TemporaryFolder dir;
  const ToolRun r =
      run_tool(dir, "plot " + quoted(dir.path().string()), "SIGNORINI_PYTHON=/no/such/python3");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err,
            "signorini: error: plotting: SIGNORINI_PYTHON = '/no/such/python3' is not an "
            "executable file: expected a Python 3 interpreter with numpy and matplotlib\n");
}

}  // namespace
}  // namespace signorini

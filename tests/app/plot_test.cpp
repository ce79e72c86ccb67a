// `signorini plot` and `signorini solve --plot`: the figures are written as PNG (SVG and PDF on
// request), and a missing Python or matplotlib or an unknown format is a one-line error with exit
// status 2 (docs/output.md). The tests that read the figures' text ask for SVG, where text stays
// text.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>
#include <regex>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"
#include "problem/ball_on_block.hpp"
#include "signorini/signorini.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

using testing::count_lines;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

const std::string kSmall = quoted(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");

const std::vector<std::string> kFigureNames = {"contact_displacement", "contact_pressure",
                                               "deformed_von_mises", "convergence"};

// The tool prefers /usr/bin/python3; the figures need its matplotlib (scripts/setup.sh installs
// python3-matplotlib). Without it only the error paths can be tested.
bool have_matplotlib() {
  return std::system("/usr/bin/python3 -c 'import matplotlib, numpy' > /dev/null 2>&1") == 0;
}

// A module folder that makes `matplotlib` impossible to find, as on a machine without it: its
// sitecustomize (run at the interpreter's start) puts a finder first that refuses it. (A fake
// package that fails when imported is not enough: the plot script's --check only looks for the
// package, it does not import it.)
std::string without_matplotlib(const testing::TemporaryFolder& dir) {
  fs::create_directories(dir / "fake");
  std::ofstream(dir / "fake" / "sitecustomize.py")
      << "import sys\n"
         "class NoMatplotlib:\n"
         "    @staticmethod\n"
         "    def find_spec(name, path=None, target=None):\n"
         "        if name == 'matplotlib' or name.startswith('matplotlib.'):\n"
         "            raise ModuleNotFoundError(\n"
         "                f\"No module named '{name}' (simulated)\", name=name)\n"
         "        return None\n"
         "sys.meta_path.insert(0, NoMatplotlib)\n";
  return "PYTHONPATH=" + quoted((dir / "fake").string());
}

// Solves paper_small into dir/out (with the --set options `sets`, already quoted).
fs::path solve_small(const testing::TemporaryFolder& dir, const std::string& sets = "") {
  const fs::path out = dir / "out";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " -q -o " + quoted(out.string()) + sets);
  EXPECT_EQ(r.status, 0) << r.err;
  return out;
}

// Sets summary["problem"]["units"] of the results in `out` (a string or null; with `erase`, the
// key is removed), as the solver writes it from the problem file's `units` setting.
void set_units(const fs::path& out, const nlohmann::json& units, bool erase = false) {
  const fs::path path = out / "summary.json";
  nlohmann::json summary = nlohmann::json::parse(testing::read_text(path));
  if (erase)
    summary["problem"].erase("units");
  else
    summary["problem"]["units"] = units;
  std::ofstream(path) << summary.dump(1);
}

// The limits of the main axes of a figure, in the units of its data: the plot script writes them
// into the description of the SVG file ("axes: x from X0 to X1, y from Y0 to Y1").
struct Limits {
  double x0, x1, y0, y1;
};

std::optional<Limits> axes_limits(const std::string& svg) {
  const std::size_t at = svg.find("<dc:description>");
  if (at == std::string::npos) return std::nullopt;
  const std::string text = svg.substr(at, svg.find("</dc:description>", at) - at);
  static const std::regex pattern(
      R"(axes: x from ([-+.0-9eE]+) to ([-+.0-9eE]+), y from ([-+.0-9eE]+) to ([-+.0-9eE]+))");
  std::smatch m;
  if (!std::regex_search(text, m, pattern)) return std::nullopt;
  return Limits{std::stod(m[1]), std::stod(m[2]), std::stod(m[3]), std::stod(m[4])};
}

// The text of an SVG figure without its embedded raster images: their base64 data may contain
// any three letters ("MPa" too).
std::string svg_text(const fs::path& file) {
  std::string svg = testing::read_text(file);
  for (std::size_t at = svg.find("base64,"); at != std::string::npos;
       at = svg.find("base64,", at + 7)) {
    const std::size_t end = svg.find('"', at);
    if (end == std::string::npos) break;
    svg.erase(at + 7, end - at - 7);
  }
  return svg;
}

const std::vector<std::string> kSvgFigures = {"contact_displacement.svg", "contact_pressure.svg",
                                              "deformed_von_mises.svg", "convergence.svg"};

// The text chunks (tEXt: keyword, a zero byte, Latin-1 text) of a PNG file, by keyword; after
// checking the signature and that each chunk lies within the file.
std::map<std::string, std::string> png_text(const fs::path& file) {
  const std::string png = testing::read_text(file);
  std::map<std::string, std::string> text;
  EXPECT_EQ(png.rfind("\x89PNG\r\n\x1a\n", 0), 0U) << file;
  std::size_t at = 8;
  while (at + 12 <= png.size()) {
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i) length = length << 8 | static_cast<unsigned char>(png[at + i]);
    const std::string kind = png.substr(at + 4, 4);
    if (at + 12 + length > png.size()) {
      ADD_FAILURE() << file << ": chunk " << kind << " runs past the end";
      break;
    }
    if (kind == "tEXt") {
      const std::string data = png.substr(at + 8, length);
      const std::size_t zero = data.find('\0');
      if (zero != std::string::npos) text[data.substr(0, zero)] = data.substr(zero + 1);
    }
    at += 12 + length;
    if (kind == "IEND") break;
  }
  EXPECT_EQ(at, png.size()) << file << ": not ended by IEND";
  return text;
}

TEST(Plot, SolveWithPlotWritesEveryFigure) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r = run_tool(dir, "solve " + kSmall + " --plot -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  // PNG only by default; each with its name and the limits of its axes.
  std::string listed;
  for (const std::string& name : kFigureNames) {
    listed += (listed.empty() ? "" : ", ") + out.string() + "/" + name + ".png";
    const std::map<std::string, std::string> text = png_text(out / (name + ".png"));
    EXPECT_EQ(text.count("Title") ? text.at("Title") : "", name);
    EXPECT_TRUE(axes_limits("<dc:description>" +
                            (text.count("Description") ? text.at("Description") : "") +
                            "</dc:description>"))
        << name;
  }
  EXPECT_CONTAINS(r.out, "figures: " + listed + "\n");
  // No temporary file is left behind.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 4U + kFigureNames.size());
}

TEST(Plot, EveryFormatOnRequest) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r =
      run_tool(dir, "solve " + kSmall + " --plot --plot-format 'svg, PNG,pdf,svg' -o " +
                        quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_EQ(r.err, "");
  std::string listed;
  for (const std::string& name : kFigureNames)
    for (const std::string format : {"svg", "png", "pdf"}) {
      const std::string f = name + "." + format;
      listed += (listed.empty() ? "" : ", ") + out.string() + "/" + f;
      const std::string contents = testing::read_text(out / f);
      if (format == "svg") {
        EXPECT_CONTAINS(contents, "<svg");
      } else {
        EXPECT_EQ(contents.rfind(format == "png" ? "\x89PNG\r\n\x1a\n" : "%PDF-", 0), 0U) << f;
      }
    }
  EXPECT_CONTAINS(r.out, "figures: " + listed + "\n");
  // Text stays text in the SVG: titles with the problem and mesh, axis labels (their units:
  // UnitLabelsComeFromTheUnitsSetting).
  const std::string pressure = testing::read_text(out / "contact_pressure.svg");
  EXPECT_CONTAINS(pressure, "paper_small: 60 × 20 mesh");
  EXPECT_CONTAINS(pressure, ">contact pressure");
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"), ">von Mises stress");
  EXPECT_CONTAINS(testing::read_text(out / "convergence.svg"), "GNM iterations");
  // No temporary file is left behind.
  std::size_t entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(out)) ++entries;
  EXPECT_EQ(entries, 4U + 3 * kFigureNames.size());
}

TEST(Plot, UnknownFormatIsExitStatus2BeforeTheSolve) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const std::string expected =
      "signorini: error: --format png,jpg: 'jpg' is not a format of the figures; expected png, "
      "svg or pdf, or several separated by commas (png,svg)\n";
  const ToolRun r = run_tool(
      dir, "solve " + kSmall + " -q --plot --plot-format png,jpg -o " + quoted(out.string()));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, expected);
  EXPECT_FALSE(fs::exists(out));  // found before the solve: nothing written
  const ToolRun p = run_tool(dir, "plot " + quoted(dir.path().string()) + " --format png,jpg");
  EXPECT_EQ(p.status, 2);
  EXPECT_EQ(p.err, expected);
}

TEST(Plot, PlotCommandWithAGivenMagnification) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  ASSERT_EQ(run_tool(dir, "solve " + kSmall + " -q -o " + quoted(out.string())).status, 0);
  ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  // The automatic magnification of the paper's figure: 1000.
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"),
                  "displacements magnified s = 1000 times");
  r = run_tool(dir, "plot " + quoted(out.string()) + " --scale 250 --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"),
                  "displacements magnified s = 250 times");
}

TEST(Plot, UnitLabelsComeFromTheUnitsSetting) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = solve_small(dir);
  // mm and N: stresses in N/mm^2 = MPa, forces per thickness in N/mm.
  set_units(out, "mm-N");
  ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "");
  std::string pressure = testing::read_text(out / "contact_pressure.svg");
  EXPECT_CONTAINS(pressure, ">x (mm)</text>");
  EXPECT_CONTAINS(pressure, ">contact pressure (MPa)</text>");
  EXPECT_CONTAINS(pressure, " N/mm</text>");  // the total contact force
  EXPECT_CONTAINS(pressure, " mm)</text>");   // where the body touches, in the title
  EXPECT_CONTAINS(testing::read_text(out / "contact_displacement.svg"),
                  ">displacement (10⁻⁴ mm)</text>");
  const std::string deformed = testing::read_text(out / "deformed_von_mises.svg");
  EXPECT_CONTAINS(deformed, ">von Mises stress (MPa)</text>");
  EXPECT_CONTAINS(deformed, ">y (mm)</text>");

  // m and Pa: forces per thickness in N/m.
  set_units(out, "m-Pa");
  r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  pressure = testing::read_text(out / "contact_pressure.svg");
  EXPECT_CONTAINS(pressure, ">contact pressure (Pa)</text>");
  EXPECT_CONTAINS(pressure, " N/m</text>");
  EXPECT_CONTAINS(pressure, ">x (m)</text>");

  // A setting the script does not know: a warning, and no units.
  set_units(out, "furlongs");
  r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "signorini: warning: units = \"furlongs\" in summary.json is not one of");
  EXPECT_CONTAINS(testing::read_text(out / "contact_pressure.svg"), ">contact pressure</text>");
}

TEST(Plot, NoUnitsWithoutTheUnitsSetting) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = solve_small(dir);
  for (const bool erase : {true, false}) {
    SCOPED_TRACE(erase ? "no units key" : "units null");
    set_units(out, nullptr, erase);
    const ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
    ASSERT_EQ(r.status, 0) << r.err;
    EXPECT_EQ(r.err, "");
    for (const std::string& f : kSvgFigures) {
      const std::string svg = svg_text(out / f);
      for (const char* unit : {"MPa", "MN/m", "(m)", " m)", "(mm)", "N/mm", " Pa"})
        EXPECT_EQ(svg.find(unit), std::string::npos) << f << " has '" << unit << "'";
    }
    const std::string pressure = testing::read_text(out / "contact_pressure.svg");
    EXPECT_CONTAINS(pressure, ">contact pressure</text>");
    EXPECT_CONTAINS(pressure, ">x</text>");
    EXPECT_CONTAINS(testing::read_text(out / "contact_displacement.svg"),
                    ">displacement (×10⁻⁴)</text>");
    EXPECT_CONTAINS(testing::read_text(out / "deformed_von_mises.svg"), ">von Mises stress</text>");
  }
}

// A curved foundation (a cylinder of radius 3 touching the body at x = 0.4): its gap is up to
// 1.5 m, thousands of times the displacements. The axes stay at the body, the foundation is drawn
// at its true place, and the displacements keep their axis.
TEST(Plot, CurvedFoundationKeepsTheAxesAtTheBody) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = solve_small(dir, " --set " + quoted("contact.gap=3 - sqrt(9 - (x-0.4)^2)"));
  const ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;

  const std::string deformed = testing::read_text(out / "deformed_von_mises.svg");
  const std::optional<Limits> body = axes_limits(deformed);
  ASSERT_TRUE(body) << "no axis limits in deformed_von_mises.svg";
  // The body (0, 3) x (0, 1), deformed with s = 1000 (up to 0.19 m), and the foundation at most
  // 10 % of the body's size (0.3 m) below it, plus a margin of 0.12 m.
  EXPECT_GT(body->x0, -0.2);
  EXPECT_LT(body->x1, 3.3);
  EXPECT_GT(body->y0, -0.5);
  EXPECT_LT(body->y0, -0.3);  // the foundation, curving away below the body, is in the picture
  EXPECT_GT(body->y1, 1.1);
  EXPECT_LT(body->y1, 1.4);
  EXPECT_CONTAINS(deformed, ">rigid foundation at its true place x + g·ν (not magnified)</text>");
  EXPECT_CONTAINS(deformed,
                  ">foundation with the gap magnified 1000 times: where the magnified "
                  "body touches it</text>");

  const std::optional<Limits> along =
      axes_limits(testing::read_text(out / "contact_displacement.svg"));
  ASSERT_TRUE(along) << "no axis limits in contact_displacement.svg";
  // The displacements (about -2e-4 to 6e-5 m) set the y axis, not the gap (up to 1.5 m).
  EXPECT_GT(along->y0, -5e-4);
  EXPECT_LT(along->y0, -1.5e-4);
  EXPECT_LT(along->y1, 5e-4);
  EXPECT_GT(along->y1, 5e-5);
  EXPECT_CONTAINS(testing::read_text(out / "contact_displacement.svg"),
                  ">gap g (the bound: uₙ ≤ g), partly off the axis</text>");
}

// g = 0 (the paper) draws the foundation along y = 0 under the body as it always did; an
// interference (g < 0: the foundation 1 micrometre inside the body) looks the same.
TEST(Plot, FlatFoundations) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  for (const std::string gap : {"0", "-1e-6"}) {
    SCOPED_TRACE("gap " + gap);
    const testing::TemporaryFolder dir;
    const fs::path out = solve_small(dir, " --set " + quoted("contact.gap=" + gap));
    const ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
    ASSERT_EQ(r.status, 0) << r.err;
    const std::string deformed = testing::read_text(out / "deformed_von_mises.svg");
    const std::optional<Limits> body = axes_limits(deformed);
    ASSERT_TRUE(body);
    EXPECT_NEAR(body->x0, -0.12, 0.01);
    EXPECT_NEAR(body->y0, -0.12, 0.02);
    EXPECT_GT(body->y1, 1.1);
    EXPECT_LT(body->y1, 1.4);
    EXPECT_CONTAINS(deformed, gap == "0" ? ">rigid foundation</text>"
                                         : ">rigid foundation at its true place x + g·ν "
                                           "(not magnified)</text>");
    EXPECT_EQ(deformed.find("gap magnified"), std::string::npos);  // no second line
    EXPECT_CONTAINS(deformed, "displacements magnified s = 1000 times");
  }
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

// A 3D problem (results written through the library, as the tool writes them): the pressure map,
// the pressure through the centre of the contact zone with Hertz's profile for the rigid sphere
// (its a and p0 from the computed contact force, checked here against the formula), and the
// convergence; the tool lists the 3D figures. --hertz-radius overrides the sphere's radius.
TEST(Plot, ThreeDimensionalResultsWithHertzsProfile) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  ProblemSpec spec = testing::ball_on_block(12, 4e-3);
  spec.units = "m-MPa";
  const double E = spec.elasticity.material.E, nu = spec.elasticity.material.nu;
  const double R = spec.contacts[0].obstacle.radius;
  const Model model = build_model(spec);
  const ContactResult result = solve_contact(model.problem, spec.solver);
  ASSERT_TRUE(result.summary.converged());
  const fs::path out = dir / "out";
  write_results(out, result, model, spec);

  const ToolRun r = run_tool(dir, "plot " + quoted(out.string()) + " --format svg");
  ASSERT_EQ(r.status, 0) << r.err;
  const std::vector<std::string> names = {"contact_pressure_map", "contact_pressure",
                                          "convergence"};
  std::string listed;
  for (const std::string& name : names) {
    EXPECT_TRUE(fs::exists(out / (name + ".svg"))) << name;
    listed += (listed.empty() ? "" : ", ") + (out / (name + ".svg")).string();
  }
  EXPECT_CONTAINS(r.out, "figures: " + listed + "\n");
  EXPECT_FALSE(fs::exists(out / "deformed_von_mises.svg"));  // 2D only

  // The map is zoomed onto the contact zone around (0.5, 0.5), about 0.1 m in radius.
  const std::optional<Limits> map =
      axes_limits(testing::read_text(out / "contact_pressure_map.svg"));
  ASSERT_TRUE(map);
  EXPECT_LT(map->x0, 0.45);
  EXPECT_GT(map->x0, 0.2);
  EXPECT_GT(map->x1, 0.55);
  EXPECT_LT(map->x1, 0.8);

  // Hertz: a = (3 F R / (4 E*))^(1/3), p0 = 3 F / (2 pi a^2) with the computed force.
  const double F = result.summary.contact_force;
  const double a = std::cbrt(3.0 * F * R / (4.0 * E / (1.0 - nu * nu)));
  const double p0 = 3.0 * F / (2.0 * std::numbers::pi * a * a);
  const auto hertz_of = [](const std::string& svg) -> std::pair<double, double> {
    static const std::regex pattern(R"(hertz: a ([-+.0-9eE]+), p0 ([-+.0-9eE]+))");
    std::smatch m;
    if (!std::regex_search(svg, m, pattern)) return {0.0, 0.0};
    return {std::stod(m[1]), std::stod(m[2])};
  };
  const std::string profile = testing::read_text(out / "contact_pressure.svg");
  const auto [a_drawn, p0_drawn] = hertz_of(profile);
  EXPECT_NEAR(a_drawn, a, 1e-5 * a);
  EXPECT_NEAR(p0_drawn, p0, 1e-5 * p0);
  // The computed peak is Hertz's within this coarse mesh's accuracy, and the zone as wide.
  EXPECT_NEAR(result.l.maxCoeff(), p0, 0.15 * p0);

  const ToolRun other =
      run_tool(dir, "plot " + quoted(out.string()) + " --format svg --hertz-radius 4 --symmetry 2");
  ASSERT_EQ(other.status, 0) << other.err;
  // Half of a body: twice the force.
  EXPECT_NEAR(hertz_of(testing::read_text(out / "contact_pressure.svg")).first,
              std::cbrt(3.0 * (2.0 * F) * 4.0 / (4.0 * E / (1.0 - nu * nu))), 1e-5 * a);
  EXPECT_EQ(run_tool(dir, "plot " + quoted(out.string()) + " --hertz-radius -1").status, 2);
  EXPECT_EQ(run_tool(dir, "plot " + quoted(out.string()) + " --symmetry 0").status, 2);
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// With friction (2D) a fifth figure: the pressure, the tangential traction and the slip along
// the contact boundary, listed by the tool, with its axes' limits: the traction axis reaches the
// peak pressure of contact.csv.
TEST(Plot, FrictionAddsTheFrictionFigure) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/paper_coulomb.toml") +
                        " -q --set mesh.nx=60 --set mesh.ny=20 --plot -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  const std::map<std::string, std::string> text = png_text(out / "contact_friction.png");
  EXPECT_EQ(text.count("Title") ? text.at("Title") : "", "contact_friction");
  const std::string description = text.count("Description") ? text.at("Description") : "";
  EXPECT_TRUE(axes_limits("<dc:description>" + description + "</dc:description>")) << description;
  const ToolRun listed = run_tool(dir, "plot " + quoted(out.string()));
  ASSERT_EQ(listed.status, 0) << listed.err;
  EXPECT_CONTAINS(listed.out, out.string() + "/contact_friction.png");
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// A loading history: --plot-steps draws the contact figure of the steps asked for (from
// steps/contact_NNNN.csv), the tool lists them, and a step that is not there is refused with
// exit status 2. In 3D with friction the friction map is drawn too.
TEST(Plot, LoadStepsAndTheFrictionMap) {
  if (!have_matplotlib()) GTEST_SKIP() << "/usr/bin/python3 has no matplotlib";
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/cattaneo_mindlin.toml") +
                        " --plot --plot-steps 2,4 -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.out << r.err;
  for (const char* name : {"contact_friction_step_0002", "contact_friction_step_0004"}) {
    const fs::path png = out / (std::string(name) + ".png");
    ASSERT_TRUE(fs::exists(png)) << png;
    const std::map<std::string, std::string> text = png_text(png);
    EXPECT_EQ(text.count("Title") ? text.at("Title") : "", name);
    EXPECT_CONTAINS(r.out, png.string());
  }
  EXPECT_FALSE(fs::exists(out / "contact_friction_step_0001.png"));
  const ToolRun bad = run_tool(dir, "plot " + quoted(out.string()) + " --steps 9");
  EXPECT_EQ(bad.status, 2);
  EXPECT_CONTAINS(bad.err, "step 9 is not one of the history's, 1 to 4");

  const fs::path out3 = dir / "out3";
  const ToolRun three =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/box_on_sphere.toml") +
                        " -q --set 'contact.friction=\"coulomb\"' --set contact.mu=0.2 --set "
                        "loading.steps=2 --plot --plot-steps all -o " +
                        quoted(out3.string()));
  ASSERT_EQ(three.status, 0) << three.out << three.err;
  EXPECT_TRUE(fs::exists(out3 / "contact_friction_map.png"));
  EXPECT_TRUE(fs::exists(out3 / "contact_friction_map_step_0001.png"));
  EXPECT_TRUE(fs::exists(out3 / "contact_friction_map_step_0002.png"));
}

}  // namespace
}  // namespace signorini

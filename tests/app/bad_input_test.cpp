// Every class of bad input, through the tool: exit status 2, one line on stderr that names the
// file and the key (or line) and says what was expected, and nothing written. docs/output.md
// lists the classes.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "app/tool_run.hpp"
#include "expect_contains.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

using testing::count_lines;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

const std::string kFile = SIGNORINI_EXAMPLES_DIR "/paper_small.toml";
const std::string kError = "signorini: error: ";

// `signorini check` on the small example with overrides: the same reading and model building as a
// solve, without the solve.
ToolRun check(const testing::TemporaryFolder& dir, const std::vector<std::string>& overrides) {
  std::string arguments = "check " + quoted(kFile);
  for (const std::string& o : overrides) arguments += " --set " + quoted(o);
  return run_tool(dir, arguments);
}

// Status 2, a single line on stderr, and that line.
std::string bad_input_line(const ToolRun& r) {
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_EQ(r.out, "");
  return r.err;
}

// The small example with `line` removed (it must be there).
fs::path example_without(const testing::TemporaryFolder& dir, const std::string& line) {
  std::string text = testing::read_text(kFile);
  const auto pos = text.find(line + "\n");
  if (pos == std::string::npos) throw std::logic_error("paper_small.toml has no line " + line);
  text.erase(pos, line.size() + 1);
  const fs::path file = dir / "edited.toml";
  std::ofstream(file) << text;
  return file;
}

// The small example with `line` replaced by `replacement` (the line must be there).
fs::path example_with(const testing::TemporaryFolder& dir, const std::string& line,
                      const std::string& replacement) {
  std::string text = testing::read_text(kFile);
  const auto pos = text.find(line + "\n");
  if (pos == std::string::npos) throw std::logic_error("paper_small.toml has no line " + line);
  text.replace(pos, line.size(), replacement);
  const fs::path file = dir / "edited.toml";
  std::ofstream(file) << text;
  return file;
}

// The 1-based line of the small example that `line` is on.
std::size_t line_number(const std::string& line) {
  const std::string text = testing::read_text(kFile);
  const auto pos = text.find(line + "\n");
  return static_cast<std::size_t>(
             std::count(text.begin(), text.begin() + static_cast<long>(pos), '\n')) +
         1;
}

TEST(BadInput, MalformedToml) {
  const testing::TemporaryFolder dir;
  std::ofstream(dir / "bad.toml") << "[mesh\nnx = 1\n";
  const std::string err =
      bad_input_line(run_tool(dir, "check " + quoted((dir / "bad.toml").string())));
  EXPECT_EQ(err.rfind(kError + (dir / "bad.toml").string() + ":1:6: TOML syntax error: ", 0), 0U)
      << err;
}

TEST(BadInput, MissingRequiredKey) {
  const testing::TemporaryFolder dir;
  const fs::path file = example_without(dir, "nx = 60");
  EXPECT_EQ(bad_input_line(run_tool(dir, "check " + quoted(file.string()))),
            kError + file.string() + ": missing required key 'mesh.nx' (integer >= 1)\n");
}

TEST(BadInput, UnknownKey) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(
      bad_input_line(check(dir, {"mesh.nxx=3"})),
      kError + kFile + ": unknown key 'mesh.nxx' (did you mean 'mesh.nx'?), given by --set\n");
}

TEST(BadInput, WrongType) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"mesh.nx=\"6\""})),
            kError + kFile + ": key 'mesh.nx' must be an integer, got string\n");
  EXPECT_EQ(bad_input_line(check(dir, {"solver.method=uzawa"})),
            kError + kFile +
                ": key 'solver.method' must be \"uzawa_gnm\", \"classical_uzawa\" or "
                "\"semismooth_newton\", got 'uzawa' (did you mean 'uzawa_gnm'?)\n");
}

TEST(BadInput, NonPositiveYoungsModulus) {
  const testing::TemporaryFolder dir;
  for (const char* e : {"material.E=0", "material.E=-210000"}) {
    const std::string err = bad_input_line(check(dir, {e}));
    EXPECT_EQ(err.rfind(kError + kFile + ": material.E = ", 0), 0U) << err;
    EXPECT_CONTAINS(err, ": expected a positive modulus\n");
  }
}

TEST(BadInput, PoissonRatioOutsideItsRange) {
  const testing::TemporaryFolder dir;
  for (const char* nu : {"material.nu=0.5", "material.nu=-1", "material.nu=0.7"}) {
    const std::string err = bad_input_line(check(dir, {nu}));
    EXPECT_EQ(err.rfind(kError + kFile + ": material.nu = ", 0), 0U) << err;
    EXPECT_CONTAINS(err, ": expected a Poisson ratio in (-1, 0.5)\n");
  }
}

TEST(BadInput, NearlyIncompressibleMaterialIsAWarning) {
  const testing::TemporaryFolder dir;
  const ToolRun r = check(dir, {"material.nu=0.495"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "signorini: warning: " + kFile +
                       ": material.nu = 0.495 >= 0.45: nearly incompressible, and linear elements "
                       "(quad4) lock: displacements come out too small and stresses near the "
                       "contact oscillate; use quadratic ones (mesh.cell = \"quad9\" or "
                       "\"tri6\") or check against a finer mesh\n");
  // A solve warns as well, even with --quiet, and still solves.
  const ToolRun s = run_tool(dir, "solve " + quoted(kFile) + " -q --set material.nu=0.495 -o " +
                                      quoted((dir / "out").string()));
  EXPECT_EQ(s.status, 0) << s.err;
  EXPECT_EQ(s.err, r.err);
  EXPECT_TRUE(fs::exists(dir / "out" / "summary.json"));
}

// A Gmsh mesh's cells are known once it is read: the warning names them and says how to mesh
// the geometry with second-order cells (mesh.cell does not apply to a Gmsh mesh); second-order
// cells get no warning.
TEST(BadInput, NearlyIncompressibleMaterialOnAGmshMesh) {
  const testing::TemporaryFolder dir;
  const std::string linear = SIGNORINI_EXAMPLES_DIR "/hertz.toml";
  const ToolRun r = run_tool(dir, "check " + quoted(linear) + " --set material.nu=0.495");
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(count_lines(r.err), 1U) << r.err;
  EXPECT_CONTAINS(r.err, "signorini: warning: " + linear +
                             ": material.nu = 0.495 >= 0.45: nearly "
                             "incompressible, and the first-order cells of '");
  EXPECT_CONTAINS(r.err, "hertz.msh' (tri3) lock");
  EXPECT_CONTAINS(r.err, "Mesh.ElementOrder = 2");
  EXPECT_EQ(r.err.find("quad4"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("mesh.cell"), std::string::npos) << r.err;
  const ToolRun q = run_tool(
      dir, "check " + quoted(SIGNORINI_EXAMPLES_DIR "/hertz_p2.toml") + " --set material.nu=0.495");
  EXPECT_EQ(q.status, 0) << q.err;
  EXPECT_EQ(q.err, "");
}

TEST(BadInput, MeshSizeBelowOne) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"mesh.nx=0"})),
            kError + kFile + ": key 'mesh.nx' = 0: expected an integer >= 1\n");
  EXPECT_EQ(bad_input_line(check(dir, {"mesh.ny=-2"})),
            kError + kFile + ": key 'mesh.ny' = -2: expected an integer >= 1\n");
}

TEST(BadInput, MeshTooLargeForThisMachine) {
  // Refused from an estimate, before any memory is allocated (which would take minutes or end
  // with the out-of-memory killer).
  const testing::TemporaryFolder dir;
  for (const char* n : {"mesh.nx=100000000", "mesh.nx=9223372036854775807"}) {
    const std::string err = bad_input_line(check(dir, {n}));
    EXPECT_EQ(err.rfind(kError + kFile + ": mesh ", 0), 0U) << err;
    EXPECT_CONTAINS(err, "GB of memory with the cholmod solver, more than this machine's ");
    EXPECT_CONTAINS(err, ": use a smaller mesh.nx, mesh.ny\n");
  }
}

TEST(BadInput, ExpressionThatDoesNotParse) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"traction.1.p=[0, \"1 +\"]"})),
            kError + kFile +
                ": traction[1].p[1]: cannot parse expression '1 +': Unexpected end of expression "
                "at position 4\n");
}

TEST(BadInput, ExpressionWithAnUnknownVariable) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"contact.gap=2*t"})),
            kError + kFile +
                ": contact.gap: cannot parse expression '2*t': unknown name 't' at position 2; "
                "the variables are x, y, z and the constants pi and e; functions: sqrt, abs, exp, "
                "log (natural), log10, sin, cos, tan, atan, min, max, sign and c ? a : b\n");
}

TEST(BadInput, ExpressionThatIsNotFiniteWhereItIsUsed) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"contact.gap=sqrt(x - 1)"})),
            kError + kFile +
                ": contact.gap = 'sqrt(x - 1)' is NaN at x = (0, 0): expected finite values "
                "everywhere it is used\n");
  EXPECT_CONTAINS(bad_input_line(check(dir, {"traction.0.p=[0, \"sqrt(2 - x)\"]"})),
                  ": traction[0].p[1] = 'sqrt(2 - x)' is NaN at x = (3, ");
  EXPECT_CONTAINS(bad_input_line(check(dir, {"body_force.f=[\"1/0\", 0]"})),
                  ": body_force.f[0] = '1/0' is infinite at x = (");
}

TEST(BadInput, BoundaryNameThatDoesNotExist) {
  const testing::TemporaryFolder dir;
  for (const char* key : {"contact.boundary", "clamp.0.boundary", "traction.0.boundary"})
    EXPECT_EQ(
        bad_input_line(check(dir, {std::string(key) + "=floor"})),
        kError + kFile + ": mesh has no boundary part 'floor' (it has: bottom, left, right, top)\n")
        << key;
}

TEST(BadInput, ContactBoundaryOnTheClampedBoundary) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"contact.boundary=left"})),
            kError + kFile +
                ": contact.boundary = 'left': no contact node can move towards the obstacle "
                "(each is clamped in its normal direction or faces away from the obstacle): "
                "expected a part that faces the obstacle and is not wholly clamped\n");
}

TEST(BadInput, NoClampedBoundary) {
  const testing::TemporaryFolder dir;
  std::string text = testing::read_text(kFile);
  text.erase(text.find("[[clamp]]\nboundary = \"left\"\n"), 28);
  std::ofstream(dir / "unclamped.toml") << text;
  const fs::path file = dir / "unclamped.toml";
  EXPECT_EQ(bad_input_line(run_tool(dir, "check " + quoted(file.string()))),
            kError + file.string() +
                ": missing required key 'clamp' (a [[clamp]] section with the boundary where u = "
                "0, or a [[displacement]] section; at least one)\n");
  EXPECT_EQ(
      bad_input_line(check(dir, {"clamp.0.components=[]"})),
      kError + kFile + ": key 'clamp[0].components' must list at least one of \"x\", \"y\"\n");
}

TEST(BadInput, OutputFolderThatCannotBeWritten) {
  const testing::TemporaryFolder dir;
  std::ofstream(dir / "file") << "x\n";
  const fs::path out = dir / "file" / "below";
  EXPECT_EQ(
      bad_input_line(run_tool(dir, "solve " + quoted(kFile) + " -q -o " + quoted(out.string()))),
      kError + "cannot create output folder '" + out.string() + "': Not a directory\n");
  EXPECT_EQ(testing::read_text(dir / "file"), "x\n");
}

TEST(BadInput, BadCommandLineOptions) {
  const testing::TemporaryFolder dir;
  const std::string out = quoted((dir / "out").string());
  EXPECT_EQ(bad_input_line(run_tool(dir, "solve " + quoted(kFile) + " --log-format xml -o " + out)),
            kError + "--log-format 'xml': expected \"text\" or \"json\"\n");
  EXPECT_CONTAINS(bad_input_line(run_tool(dir, "solve " + quoted(kFile) + " --scale -1 -o " + out)),
                  "--scale");
  EXPECT_FALSE(fs::exists(dir / "out"));
}

TEST(BadInput, AFailedRunLeavesNoFileAndKeepsEarlierResults) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "out";
  ASSERT_EQ(run_tool(dir, "solve " + quoted(kFile) + " -q -o " + quoted(out.string())).status, 0);
  std::map<std::string, std::string> before;
  for (const auto& e : fs::directory_iterator(out))
    before[e.path().filename().string()] = testing::read_text(e.path());
  EXPECT_EQ(before.size(), 4U);
  // Bad input found early, and a numerical failure found late (a singular stiffness).
  for (const char* o : {"material.E=-1", "clamp.0.components=[\"x\"]"}) {
    const ToolRun r = run_tool(
        dir, "solve " + quoted(kFile) + " -q --set " + quoted(o) + " -o " + quoted(out.string()));
    EXPECT_NE(r.status, 0) << o;
    std::map<std::string, std::string> after;
    for (const auto& e : fs::directory_iterator(out))
      after[e.path().filename().string()] = testing::read_text(e.path());
    EXPECT_EQ(after, before) << o;
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// What a new user writes first, each answered in the problem file's terms with its line.
TEST(BadInput, NumberWithAUnitAndFormulasWithoutQuotes) {
  const testing::TemporaryFolder dir;
  const auto run = [&](const fs::path& file) {
    return bad_input_line(run_tool(dir, "check " + quoted(file.string())));
  };
  const std::string at_e = kError + (dir / "edited.toml").string() + ":" +
                           std::to_string(line_number("E = 21.19e4")) + ": ";
  EXPECT_EQ(run(example_with(dir, "E = 21.19e4", "E = 21.19e4 MPa")),
            at_e +
                "key 'material.E' = 21.19e4 MPa: a number cannot carry a unit; write E = 21.19e4 "
                "(the numbers of a problem are in one consistent set of units, which the "
                "top-level key units = \"m-MPa\" (or \"mm-N\", \"m-Pa\", ...) names for the "
                "labels)\n");
  const std::string at_p = kError + (dir / "edited.toml").string() + ":" +
                           std::to_string(line_number("p = [0, 1]")) + ": ";
  EXPECT_EQ(run(example_with(dir, "p = [0, 1]", "p = [0, 1 - y/2]")),
            at_p +
                "key 'traction[0].p' = [0, 1 - y/2]: formulas in an array must be quoted strings, "
                "as p = [0, \"1 - y/2\"]\n");
  const std::string at_gap = kError + (dir / "edited.toml").string() + ":" +
                             std::to_string(line_number("boundary = \"bottom\"")) + ": ";
  EXPECT_EQ(run(example_with(dir, "boundary = \"bottom\"", "gap = 1e-3*(x - 1.5)^2")),
            at_gap +
                "key 'contact.gap' = 1e-3*(x - 1.5)^2: a formula or a name must be a quoted "
                "string, as gap = \"1e-3*(x - 1.5)^2\"\n");
}

TEST(BadInput, KeysInTheWrongPlaceOrByAnotherName) {
  const testing::TemporaryFolder dir;
  const auto run = [&](const fs::path& file) {
    return bad_input_line(run_tool(dir, "check " + quoted(file.string())));
  };
  const std::string at = kError + (dir / "edited.toml").string() + ":";
  EXPECT_EQ(run(example_with(dir, "E = 21.19e4", "Young = 21.19e4")),
            at + std::to_string(line_number("E = 21.19e4")) +
                ": unknown key 'material.Young' (did you mean 'material.E'?)\n");
  EXPECT_EQ(run(example_with(dir, "nu = 0.277", "poisson_ratio = 0.277")),
            at + std::to_string(line_number("nu = 0.277")) +
                ": unknown key 'material.poisson_ratio' (did you mean 'material.nu'?)\n");
  EXPECT_EQ(run(example_with(dir, "name = \"paper_small\"", "nx = 60")),
            at + std::to_string(line_number("name = \"paper_small\"")) +
                ": unknown key 'nx' (did you mean 'mesh.nx'? it belongs in the [mesh] "
                "section)\n");
  EXPECT_EQ(bad_input_line(check(dir, {"units=mm-n"})),
            kError + kFile +
                ": key 'units' = 'mm-n': expected one of \"m-Pa\", \"m-kPa\", \"m-MPa\", "
                "\"m-GPa\", \"mm-MPa\", \"mm-N\", \"m-N\" (labels only; or leave it out) (did "
                "you mean 'mm-N'?)\n");
}

TEST(BadInput, FreeRigidMotionsAreNamed) {
  const testing::TemporaryFolder dir;
  // Held in x only on the left: free to slide along y.
  EXPECT_CONTAINS(bad_input_line(check(dir, {"clamp.0.components=[\"x\"]"})),
                  "the clamps leave a rigid motion free (translation in y): ");
  // A roller on top (y held), frictionless contact below: free to slide along x, which the
  // contact cannot hold; the load of the top moves to the left edge.
  EXPECT_CONTAINS(bad_input_line(check(dir, {"clamp.0.boundary=top", "clamp.0.components=[\"y\"]",
                                             "traction.1.boundary=left"})),
                  "the clamps leave a rigid motion free (translation in x): ");
}

TEST(BadInput, TractionOnTheContactBoundary) {
  const testing::TemporaryFolder dir;
  EXPECT_EQ(bad_input_line(check(dir, {"traction.0.boundary=bottom"})),
            kError + kFile +
                ": traction[0].boundary = 'bottom' is a contact boundary (contact.boundary): a "
                "boundary part is either loaded or in contact with the foundation; load another "
                "part\n");
}

TEST(BadInput, PointLoadsAndRanges) {
  const testing::TemporaryFolder dir;
  EXPECT_CONTAINS(bad_input_line(check(dir, {"point_load.x=1"})), "point_load");
  EXPECT_CONTAINS(bad_input_line(check(dir, {"traction.1.x_range=[2, 1]"})),
                  ": key 'traction[1].x_range' = [2.0, 1.0]: expected [lower, upper] with lower < "
                  "upper\n");
  EXPECT_CONTAINS(bad_input_line(check(dir, {"traction.1.x_range=[1]"})),
                  "key 'traction[1].x_range' must have 2 entries (lower and upper), got 1");
}

TEST(BadInput, DiscontinuousLoadFormulaIsAWarning) {
  const testing::TemporaryFolder dir;
  const ToolRun r = check(dir, {"traction.1.p=[0, \"abs(x - 2.0) < 0.002 ? -25 : 0\"]"});
  EXPECT_EQ(r.status, 0) << r.err;
  EXPECT_EQ(r.err, "signorini: warning: " + kFile +
                       ": traction[1].p[1] = 'abs(x - 2.0) < 0.002 ? -25 : 0' switches value "
                       "inside the boundary: Gauss quadrature samples it, so the load can be lost "
                       "or overcounted; for a load on part of a boundary give x_range/y_range "
                       "instead (integrated exactly), and check the applied load in the "
                       "summary\n");
}

}  // namespace
}  // namespace signorini

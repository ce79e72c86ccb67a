// Problem files: the paper's example reads into the paper's spec, defaults are filled in,
// overrides work, and every class of mistake gives a one-line message naming file and key.

#include "signorini/input/problem_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <map>

#include "expect_contains.hpp"
#include "input/option_values.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/input/toml_emitter.hpp"
#include "signorini/interface/obstacle_parameters.hpp"
#include "signorini/problem/model.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

// The paper's benchmark on a 6 x 2 mesh, every section present.
const std::string kBase = R"toml(
name = "base"
[mesh]
type = "rectangle"
origin = [0.0, 0.0]
length = 3.0
height = 1.0
nx = 6
ny = 2
[material]
E = 21.19e4
nu = 0.277
plane_model = "plane_strain"
[fem]
gauss_points = 2
boundary_gauss_points = 2
[[clamp]]
boundary = "left"
components = ["x", "y"]
[[traction]]
boundary = "right"
p = ["0", "1"]
[[traction]]
boundary = "top"
p = ["0", "-2/3*(3 - x)"]
[contact]
boundary = "bottom"
gap = "0"
[solver]
method = "uzawa_gnm"
r = 1e8
[solver.linear]
type = "cholmod"
)toml";

// kBase with one line replaced (the line must be there, so that a test cannot go stale).
std::string with(const std::string& line, const std::string& replacement) {
  std::string text = kBase;
  const auto pos = text.find("\n" + line + "\n");
  if (pos == std::string::npos) throw std::logic_error("kBase has no line '" + line + "'");
  text.replace(pos + 1, line.size(), replacement);
  return text;
}
std::string without(const std::string& line) {
  return with(line, "");
}

std::string error_of(const std::string& text, const std::vector<std::string>& overrides = {}) {
  try {
    parse_problem_string(text, "test.toml", overrides);
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "not one line: " << m;
    return m;
  }
  return "no error";
}

TEST(ProblemFile, BaseParses) {
  const LoadedProblem p = parse_problem_string(kBase, "base.toml");
  EXPECT_EQ(p.path, "base.toml");
  EXPECT_EQ(p.spec.name, "base");
  EXPECT_EQ(p.spec.mesh.nx, 6);
  EXPECT_EQ(p.spec.tractions.size(), 2U);
}

TEST(ProblemFile, PaperExampleIsThePapersBenchmark) {
  const LoadedProblem p = read_problem_file(SIGNORINI_EXAMPLES_DIR "/paper.toml");
  const ProblemSpec expected = paper_benchmark(480, 160);
  const ProblemSpec& s = p.spec;
  EXPECT_EQ(s.name, "paper");
  EXPECT_EQ(s.mesh.x0, expected.mesh.x0);
  EXPECT_EQ(s.mesh.y0, expected.mesh.y0);
  EXPECT_EQ(s.mesh.length, expected.mesh.length);
  EXPECT_EQ(s.mesh.height, expected.mesh.height);
  EXPECT_EQ(s.mesh.nx, 480);
  EXPECT_EQ(s.mesh.ny, 160);
  EXPECT_EQ(s.elasticity.material.E, 21.19e4);
  EXPECT_EQ(s.elasticity.material.nu, 0.277);
  EXPECT_EQ(s.elasticity.plane_model, PlaneModel::PlaneStrain);
  EXPECT_EQ(s.elasticity.gauss_points, 2);
  EXPECT_EQ(s.boundary_gauss_points, 2);
  ASSERT_EQ(s.clamps.size(), 1U);
  EXPECT_EQ(s.clamps[0].boundary, "left");
  EXPECT_TRUE(s.clamps[0].components[0]);
  EXPECT_TRUE(s.clamps[0].components[1]);
  ASSERT_EQ(s.tractions.size(), expected.tractions.size());
  for (std::size_t i = 0; i < s.tractions.size(); ++i) {
    EXPECT_EQ(s.tractions[i].boundary, expected.tractions[i].boundary);
    for (const double x : {0.0, 0.7, 1.5, 3.0}) {
      const Point at(x, 1.0, 0.0);
      const Eigen::Vector3d got = s.tractions[i].p(at);
      const Eigen::Vector3d want = expected.tractions[i].p(at);
      EXPECT_NEAR(got(0), want(0), 1e-15);
      EXPECT_NEAR(got(1), want(1), 1e-15) << "traction " << i << " at x = " << x;
    }
  }
  EXPECT_FALSE(static_cast<bool>(s.body_force));
  EXPECT_EQ(s.contacts[0].boundary, "bottom");
  EXPECT_EQ(s.contacts[0].gap(Point(1.0, 0.0, 0.0)), 0.0);
  EXPECT_EQ(s.solver.method, ContactMethod::UzawaGnm);
  EXPECT_EQ(s.solver.r, 1e8);
  EXPECT_EQ(s.solver.uzawa_tolerance, 1e-8);
  EXPECT_EQ(s.solver.gnm_tolerance, 1e-10);
  EXPECT_EQ(s.solver.armijo_sigma, 1e-4);
  EXPECT_EQ(s.solver.linear.type, LinearSolverType::Cholmod);
  EXPECT_TRUE(s.solver.schur_complement);
}

TEST(ProblemFile, SmallPaperExampleBuildsTheTable1Model) {
  const LoadedProblem p = read_problem_file(SIGNORINI_EXAMPLES_DIR "/paper_small.toml");
  EXPECT_EQ(p.spec.name, "paper_small");
  const Model m = build_model(p.spec);
  EXPECT_EQ(m.dofs.num_dofs(), 2562);  // the paper's n_p for 60 x 20
  EXPECT_EQ(m.problem.contact.size(), 61);
}

TEST(ProblemFile, DefaultsAreFilledIn) {
  const std::string minimal = R"toml(
[mesh]
length = 2
height = 1
nx = 4
ny = 2
[material]
E = 1000
nu = 0.3
[[clamp]]
boundary = "left"
[contact]
boundary = "bottom"
)toml";
  const LoadedProblem p = parse_problem_string(minimal, "some/folder/minimal.toml");
  const ProblemSpec& s = p.spec;
  EXPECT_EQ(s.name, "minimal");  // the file stem
  EXPECT_EQ(s.mesh.x0, 0.0);
  EXPECT_EQ(s.mesh.y0, 0.0);
  EXPECT_EQ(s.mesh.length, 2.0);  // an integer where a float is expected
  EXPECT_EQ(s.elasticity.material.E, 1000.0);
  EXPECT_EQ(s.elasticity.plane_model, PlaneModel::PlaneStrain);
  EXPECT_EQ(s.elasticity.gauss_points, 2);
  EXPECT_EQ(s.boundary_gauss_points, 2);
  EXPECT_TRUE(s.clamps[0].components[0] && s.clamps[0].components[1]);
  EXPECT_TRUE(s.tractions.empty());
  EXPECT_EQ(s.contacts[0].gap(Point(1.0, 0.0, 0.0)), 0.0);
  const ContactSolverOptions defaults;
  EXPECT_EQ(s.solver.method, defaults.method);
  EXPECT_FALSE(s.solver.r.has_value());  // automatic (method.md section 7)
  EXPECT_EQ(s.solver.auto_r_factor, 10.0);
  EXPECT_EQ(s.solver.kkt_tolerance, 1e-6);
  EXPECT_TRUE(s.units.empty());
  EXPECT_TRUE(s.point_loads.empty());
  EXPECT_EQ(s.solver.max_uzawa_iterations, defaults.max_uzawa_iterations);
  EXPECT_EQ(s.solver.linear.type, defaults.linear.type);
  EXPECT_EQ(s.solver.linear.cg_tolerance, defaults.linear.cg_tolerance);
  // The effective settings spell out the defaults.
  EXPECT_CONTAINS(p.effective_toml, "plane_model = \"plane_strain\"");
  EXPECT_CONTAINS(p.effective_toml, "max_uzawa_iterations = 1000");
  EXPECT_CONTAINS(p.effective_toml, "components = [\"x\", \"y\"]");
  EXPECT_CONTAINS(p.effective_toml, "gap = \"0\"");
  EXPECT_CONTAINS(p.effective_toml, "r = \"auto\"");
}

TEST(ProblemFile, EveryOptionIsRead) {
  std::string text = kBase;
  text.replace(text.find("[solver]\n"), 9, R"toml([solver]
uzawa_tolerance = 1e-9
max_uzawa_iterations = 50
gnm_tolerance = 1e-11
max_gnm_iterations = 20
armijo_sigma = 1e-3
max_armijo_halvings = 30
classical_step = 0.5
max_classical_iterations = 1000
max_newton_iterations = 40
schur_complement = false
)toml");
  text.replace(text.find("type = \"cholmod\""), 16,
               "type = \"cg\"\ncg_tolerance = 1e-12\ncg_max_iterations = 500\n"
               "preconditioner = \"multigrid\"\ncoarsening = \"aggregation\"\n"
               "chebyshev_degree = 3");
  text += "[body_force]\nf = [0, \"-9.81e-3*y\"]\n";
  const ContactSolverOptions o = parse_problem_string(text, "t.toml").spec.solver;
  EXPECT_EQ(o.uzawa_tolerance, 1e-9);
  EXPECT_EQ(o.max_uzawa_iterations, 50);
  EXPECT_EQ(o.gnm_tolerance, 1e-11);
  EXPECT_EQ(o.max_gnm_iterations, 20);
  EXPECT_EQ(o.armijo_sigma, 1e-3);
  EXPECT_EQ(o.max_armijo_halvings, 30);
  EXPECT_EQ(o.classical_step, 0.5);
  EXPECT_EQ(o.max_classical_iterations, 1000);
  EXPECT_EQ(o.max_newton_iterations, 40);
  EXPECT_FALSE(o.schur_complement);
  EXPECT_EQ(o.linear.type, LinearSolverType::ConjugateGradient);
  EXPECT_EQ(o.linear.cg_tolerance, 1e-12);
  EXPECT_EQ(o.linear.cg_max_iterations, 500);
  EXPECT_EQ(o.linear.preconditioner, PreconditionerType::Multigrid);
  EXPECT_EQ(o.linear.coarsening, MultigridCoarsening::Aggregation);
  EXPECT_EQ(o.linear.chebyshev_degree, 3);
  const ProblemSpec s = parse_problem_string(text, "t.toml").spec;
  ASSERT_TRUE(static_cast<bool>(s.body_force));
  EXPECT_DOUBLE_EQ(s.body_force(Point(0.0, 2.0, 0.0))(1), -2 * 9.81e-3);
}

TEST(ProblemFile, ClampComponentsAndOrigin) {
  std::string text = with("components = [\"x\", \"y\"]", "components = [\"y\"]");
  text = text.replace(text.find("origin = [0.0, 0.0]"), 19, "origin = [1, -0.5]");
  const ProblemSpec s = parse_problem_string(text, "t.toml").spec;
  EXPECT_FALSE(s.clamps[0].components[0]);
  EXPECT_TRUE(s.clamps[0].components[1]);
  EXPECT_EQ(s.mesh.x0, 1.0);
  EXPECT_EQ(s.mesh.y0, -0.5);
}

TEST(ProblemFile, UnitsRangesPointLoadsAndAutomaticR) {
  std::string text = with("name = \"base\"", "name = \"base\"\nunits = \"mm-N\"");
  text = text.replace(text.find("p = [\"0\", \"1\"]"), 14,
                      "p = [\"0\", \"1\"]\nx_range = [0.5, 2]\ny_range = [-1, 1.5]");
  text = text.replace(text.find("r = 1e8"), 7,
                      "r = \"auto\"\nauto_r_factor = 30\nkkt_tolerance = 1e-8");
  text += "[[point_load]]\nat = [1, 1]\nforce = [0.5, -2]\nboundary = \"top\"\n";
  const LoadedProblem p = parse_problem_string(text, "t.toml");
  const ProblemSpec& s = p.spec;
  EXPECT_EQ(s.units, "mm-N");
  EXPECT_EQ(s.tractions[0].region.lower[0], 0.5);
  EXPECT_EQ(s.tractions[0].region.upper[0], 2.0);
  EXPECT_EQ(s.tractions[0].region.lower[1], -1.0);
  EXPECT_EQ(s.tractions[0].region.upper[1], 1.5);
  EXPECT_TRUE(s.tractions[1].region.unbounded());
  ASSERT_EQ(s.point_loads.size(), 1U);
  EXPECT_EQ(s.point_loads[0].at, Point(1.0, 1.0, 0.0));
  EXPECT_EQ(s.point_loads[0].force, Eigen::Vector3d(0.5, -2.0, 0.0));
  EXPECT_EQ(s.point_loads[0].boundary, "top");
  EXPECT_FALSE(s.solver.r.has_value());
  EXPECT_EQ(s.solver.auto_r_factor, 30.0);
  EXPECT_EQ(s.solver.kkt_tolerance, 1e-8);
  // The effective settings say all of it, and read back to the same.
  const LoadedProblem again = parse_problem_string(p.effective_toml, "effective.toml");
  EXPECT_EQ(again.effective_toml, p.effective_toml);
  EXPECT_CONTAINS(p.effective_toml, "units = \"mm-N\"");
  EXPECT_CONTAINS(p.effective_toml, "x_range = [0.5, 2.0]");
  EXPECT_CONTAINS(p.effective_toml, "[[point_load]]");
  EXPECT_EQ(error_of(with("r = 1e8", "r = \"automatic\"")),
            "test.toml:31: key 'solver.r' must be a positive number or \"auto\", got 'automatic'");
}

// The problem read again from its effective settings, which must be the same text and give the
// same value for every option of the tables (compared through them: a new option is covered).
LoadedProblem read_back(const LoadedProblem& p) {
  LoadedProblem again = parse_problem_string(p.effective_toml, "effective.toml");
  EXPECT_EQ(again.effective_toml, p.effective_toml);
  const auto values = option_values(p.spec);
  const auto values_again = option_values(again.spec);
  EXPECT_EQ(values.size(), values_again.size());
  for (std::size_t i = 0; i < std::min(values.size(), values_again.size()); ++i) {
    EXPECT_EQ(values_again[i].first, values[i].first);
    EXPECT_TRUE(values_again[i].second == values[i].second)
        << values[i].first << " = " << toml_value_text(values[i].second) << " read back as "
        << toml_value_text(values_again[i].second);
  }
  return again;
}

// Every option away from its default, given by --set (each key through the same reader and
// checks as in a file), reads back from the effective settings to the same values, compared
// option by option through the option tables: a new option is covered without a change here.
TEST(ProblemFile, EffectiveSettingsRoundTripEveryOption) {
  std::vector<std::string> overrides;
  std::map<std::string, OptionValue> wanted;
  for (const OptionTableInfo* table : problem_schema())
    for (const OptionInfo& o : table->options) {
      const std::string key = table->full_key(o.key);
      // The kind of mesh stays a rectangle, and the keys of a Gmsh mesh out (the file would
      // have to exist): tests/app/gmsh_mesh_test.cpp reads those; the box's own keys are
      // ProblemFile3D.EffectiveSettingsRoundTrip's.
      if (key == "mesh.type" || o.condition == "type = \"gmsh\"" || o.condition == "type = \"box\"")
        continue;
      const std::optional<OptionValue> v = testing::other_value(o, key);
      if (!v) continue;
      overrides.push_back(key + "=" + toml_value_text(*v));
      wanted[key] = *v;
    }
  ASSERT_GE(wanted.size(), 25U);
  std::string text = kBase + "[body_force]\nf = [0, \"-9.81e-3*y\"]\n";
  text = text.replace(text.find("p = [\"0\", \"1\"]"), 14,
                      "p = [\"0\", \"1\"]\nx_range = [0.5, 2]\ny_range = [-1, 1.5]");
  text += "[[point_load]]\nat = [1, 1]\nforce = [0.5, -2]\nboundary = \"top\"\n";
  const LoadedProblem p = parse_problem_string(text, "every.toml", overrides);
  for (const auto& [key, value] : option_values(p.spec)) {
    if (wanted.contains(key)) {
      EXPECT_TRUE(value == wanted[key]) << key << " was not set by --set";
    }
  }

  const LoadedProblem again = read_back(p);
  // The sections of formulas and lists, which their own readers read.
  const ProblemSpec& s = p.spec;
  const ProblemSpec& a = again.spec;
  EXPECT_EQ(a.units, s.units);
  ASSERT_EQ(a.clamps.size(), s.clamps.size());
  EXPECT_EQ(a.clamps[0].boundary, s.clamps[0].boundary);
  EXPECT_EQ(a.clamps[0].components, s.clamps[0].components);
  ASSERT_EQ(a.tractions.size(), s.tractions.size());
  for (std::size_t i = 0; i < s.tractions.size(); ++i) {
    EXPECT_EQ(a.tractions[i].boundary, s.tractions[i].boundary);
    EXPECT_EQ(a.tractions[i].description, s.tractions[i].description);
    EXPECT_EQ(a.tractions[i].region.lower, s.tractions[i].region.lower);
    EXPECT_EQ(a.tractions[i].region.upper, s.tractions[i].region.upper);
  }
  ASSERT_EQ(a.point_loads.size(), 1U);
  EXPECT_EQ(a.point_loads[0].at, s.point_loads[0].at);
  EXPECT_EQ(a.point_loads[0].force, s.point_loads[0].force);
  EXPECT_EQ(a.point_loads[0].boundary, s.point_loads[0].boundary);
  EXPECT_EQ(a.body_force_description, s.body_force_description);
  EXPECT_EQ(a.contacts[0].boundary, s.contacts[0].boundary);
  EXPECT_EQ(a.contacts[0].description, s.contacts[0].description);
}

// Errors, one class at a time --------------------------------------------------------------

TEST(ProblemFileErrors, SyntaxErrorGivesLineAndColumn) {
  const std::string m = error_of(with("nx = 6", "nx = = 6"));
  EXPECT_EQ(m.rfind("test.toml:8:6: TOML syntax error: ", 0), 0U) << m;  // line 1 is empty
  EXPECT_CONTAINS(m, ": TOML syntax error: ");
  EXPECT_EQ(error_of("[mesh]\nlength = 3.0\nlength = 4.0\n").rfind("test.toml:3:", 0), 0U);
  // Found by tests/fuzz: toml++ 3.3.0 asserts on a table header cut short by a line break (in a
  // build with assertions); the library the tool links reports it.
  EXPECT_EQ(error_of("a = 1\n[[\n"),
            "test.toml:2:3: TOML syntax error: Error while parsing key: expected bare key "
            "starting character or string delimiter, saw '\\n'");
  // Found by tests/fuzz: toml++ 3.3.0 classifies some non-ASCII code points through a table that
  // reaches __builtin_unreachable() (marzer/tomlplusplus#190); compiled, it answers "not
  // whitespace", which is right. Here is what that gives, where it matters.
  EXPECT_EQ(error_of("a = 1\u00e9\n"),
            "test.toml:1:6: TOML syntax error: Error while parsing decimal integer: expected "
            "digit, saw '\u00e9'");
  EXPECT_EQ(error_of("a = 21.1\u01db40\n"),
            "test.toml:1:9: TOML syntax error: Error while parsing floating-point: expected "
            "decimal digit, saw '\u01db'");
  std::string multiline_name = kBase;
  multiline_name.replace(multiline_name.find("name = \"base\""), 13,
                         "name = \"\"\"\\\n   \u00a7 x\"\"\"");
  EXPECT_EQ(parse_problem_string(multiline_name, "t.toml").spec.name, "\u00a7 x");
}

TEST(ProblemFileErrors, UnknownKeySuggestsTheKnownOne) {
  EXPECT_EQ(
      error_of(with("r = 1e8", "uzawa_tol = 1e-8")),
      "test.toml:31: unknown key 'solver.uzawa_tol' (did you mean 'solver.uzawa_tolerance'?)");
  EXPECT_EQ(error_of(with("nx = 6", "nxx = 6")),
            "test.toml:8: unknown key 'mesh.nxx' (did you mean 'mesh.nx'?)");
  EXPECT_EQ(error_of(with("[solver]", "[solvers]")),
            "test.toml:29: unknown key 'solvers' (did you mean 'solver'?)");
  EXPECT_EQ(error_of(with("components = [\"x\", \"y\"]", "component = [\"x\"]")),
            "test.toml:19: unknown key 'clamp[0].component' (did you mean 'clamp[0].components'?)");
  EXPECT_EQ(error_of(with("type = \"cholmod\"", "typ = \"cholmod\"")),
            "test.toml:33: unknown key 'solver.linear.typ' (did you mean 'solver.linear.type'?)");
  EXPECT_EQ(error_of(with("r = 1e8", "colour = 1")), "test.toml:31: unknown key 'solver.colour'");
}

TEST(ProblemFileErrors, MissingRequiredKey) {
  EXPECT_EQ(error_of(without("nx = 6")),
            "test.toml: missing required key 'mesh.nx' (integer >= 1)");
  EXPECT_CONTAINS(error_of(without("E = 21.19e4")), "test.toml: missing required key 'material.E'");
  EXPECT_CONTAINS(error_of(with("[contact]", "[other]")), "unknown key 'other'");
  std::string no_contact = kBase;
  no_contact.erase(no_contact.find("[contact]"),
                   no_contact.find("[solver]") - no_contact.find("[contact]"));
  EXPECT_CONTAINS(error_of(no_contact), "test.toml: missing required key 'contact'");
  std::string no_clamp = kBase;
  no_clamp.erase(no_clamp.find("[[clamp]]"),
                 no_clamp.find("[[traction]]") - no_clamp.find("[[clamp]]"));
  EXPECT_CONTAINS(error_of(no_clamp), "test.toml: missing required key 'clamp'");
  EXPECT_CONTAINS(error_of(without("boundary = \"bottom\"")),
                  "missing required key 'contact.boundary'");
}

TEST(ProblemFileErrors, WrongType) {
  EXPECT_EQ(error_of(with("nx = 6", "nx = \"6\"")),
            "test.toml:8: key 'mesh.nx' must be an integer, got string");
  EXPECT_EQ(error_of(with("nx = 6", "nx = 6.0")),
            "test.toml:8: key 'mesh.nx' must be an integer, got float");
  EXPECT_EQ(error_of(with("E = 21.19e4", "E = \"21.19e4\"")),
            "test.toml:11: key 'material.E' must be a number, got string");
  EXPECT_EQ(error_of(with("r = 1e8", "r = true")),
            "test.toml:31: key 'solver.r' must be a number, got boolean");
  EXPECT_EQ(error_of(with("r = 1e8", "schur_complement = 1")),
            "test.toml:31: key 'solver.schur_complement' must be true or false, got integer");
  EXPECT_CONTAINS(error_of(with("[[clamp]]", "[clamp]")), "key 'clamp' must be an array of tables");
  EXPECT_CONTAINS(error_of(with("p = [\"0\", \"1\"]", "p = \"1\"")),
                  "key 'traction[0].p' must be an array of 2 expressions");
  EXPECT_CONTAINS(error_of(with("p = [\"0\", \"1\"]", "p = [\"0\", \"1\", \"2\"]")),
                  "key 'traction[0].p' must have 2 entries");
  EXPECT_CONTAINS(error_of(with("p = [\"0\", \"1\"]", "p = [\"0\", true]")),
                  "key 'traction[0].p[1]' must be an expression");
}

TEST(ProblemFileErrors, BadEnumListsTheChoices) {
  EXPECT_EQ(error_of(with("method = \"uzawa_gnm\"", "method = \"uzawa\"")),
            "test.toml:30: key 'solver.method' must be \"uzawa_gnm\", \"classical_uzawa\" or "
            "\"semismooth_newton\", got 'uzawa' (did you mean 'uzawa_gnm'?)");
  EXPECT_CONTAINS(
      error_of(with("plane_model = \"plane_strain\"", "plane_model = \"plane-strain\"")),
      "(did you mean 'plane_strain'?)");
  EXPECT_EQ(error_of(with("type = \"cholmod\"", "type = \"lu\"")),
            "test.toml:33: key 'solver.linear.type' must be " +
                enum_choices(kLinearSolverTypeNames) + ", got 'lu'");
  EXPECT_EQ(error_of(with("type = \"cholmod\"", "type = \"cg\"\ncoarsening = \"smoothed\"")),
            "test.toml:34: key 'solver.linear.coarsening' must be \"auto\", \"geometric\" or "
            "\"aggregation\", got 'smoothed'");
  EXPECT_CONTAINS(error_of(with("type = \"rectangle\"", "type = \"disk\"")),
                  "key 'mesh.type' must be \"rectangle\"");
  EXPECT_CONTAINS(error_of(with("components = [\"x\", \"y\"]", "components = [\"z\"]")),
                  "key 'clamp[0].components[0]' must be \"x\" or \"y\", got 'z'");
}

TEST(ProblemFileErrors, OutOfRangeValues) {
  const std::string e_zero = error_of(with("E = 21.19e4", "E = 0"));
  EXPECT_EQ(e_zero.rfind("test.toml: material.E = ", 0), 0U) << e_zero;
  EXPECT_CONTAINS(e_zero, "positive");
  EXPECT_CONTAINS(error_of(with("E = 21.19e4", "E = -5.0")), "test.toml: material.E = ");
  const std::string nu = error_of(with("nu = 0.277", "nu = 0.5"));
  EXPECT_EQ(nu.rfind("test.toml: material.nu = ", 0), 0U) << nu;
  EXPECT_CONTAINS(nu, "(-1, 0.5)");
  EXPECT_EQ(error_of(with("nx = 6", "nx = 0")),
            "test.toml:8: key 'mesh.nx' = 0: expected an integer >= 1");
  EXPECT_EQ(error_of(kBase, {"mesh.nx=0"}),  // a --set value has no line
            "test.toml: key 'mesh.nx' = 0: expected an integer >= 1");
  EXPECT_CONTAINS(error_of(with("ny = 2", "ny = -3")), "key 'mesh.ny' = -3");
  EXPECT_CONTAINS(error_of(with("length = 3.0", "length = 0")), "key 'mesh.length' = 0.0");
  EXPECT_CONTAINS(error_of(with("gauss_points = 2", "gauss_points = 9")),
                  "test.toml:15: key 'fem.gauss_points' = 9: expected an integer in [1, 5]");
  EXPECT_EQ(error_of(with("r = 1e8", "r = -1")),
            "test.toml:31: key 'solver.r' = -1.0: expected a positive number or \"auto\"");
  EXPECT_EQ(error_of(with("r = 1e8", "max_uzawa_iterations = 0")),
            "test.toml:31: key 'solver.max_uzawa_iterations' = 0: expected an integer >= 1");
  EXPECT_EQ(error_of(with("type = \"cholmod\"", "cg_tolerance = 1.5")),
            "test.toml:33: key 'solver.linear.cg_tolerance' = 1.5: expected a number in (0, 1)");
  EXPECT_EQ(error_of(kBase, {"solver.armijo_sigma=0.5"}),
            "test.toml: key 'solver.armijo_sigma' = 0.5: expected a number in (0, 0.5)");
  EXPECT_CONTAINS(error_of(with("r = 1e8", "max_uzawa_iterations = 10000000000")),
                  "key 'solver.max_uzawa_iterations' = 10000000000");
}

TEST(ProblemFileErrors, MeshTooLargeForThisMachine) {
  const std::string m = error_of(with("nx = 6", "nx = 10000000000"), {"mesh.ny=10000000"});
  EXPECT_CONTAINS(m, "test.toml: mesh 10000000000x10000000 has ");
  EXPECT_CONTAINS(m, "GB of memory");
  EXPECT_CONTAINS(m, "use a smaller mesh");
}

TEST(ProblemFileErrors, ExpressionErrorsNameFileAndKey) {
  EXPECT_CONTAINS(error_of(with("p = [\"0\", \"-2/3*(3 - x)\"]", "p = [\"0\", \"-2/3*(3 - t)\"]")),
                  "test.toml: traction[1].p[1]: cannot parse expression '-2/3*(3 - t)'");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "gap = \"0.1*(x\"")),
                  "test.toml: contact.gap: cannot parse expression '0.1*(x'");
}

// A formula that parses but gives NaN or infinity where the model uses it: build_model() reports
// it with the key and the formula.
std::string model_error_of(const std::string& text) {
  const LoadedProblem p = parse_problem_string(text, "t.toml");
  try {
    build_model(p.spec);
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_EQ(m.find('\n'), std::string::npos) << "not one line: " << m;
    return m;
  }
  return "no error";
}

TEST(ProblemFileErrors, NonFiniteExpressionsNameKeyAndFormula) {
  EXPECT_EQ(model_error_of(with("gap = \"0\"", "gap = \"sqrt(x - 1)\"")),
            "contact.gap = 'sqrt(x - 1)' is NaN at x = (0, 0): expected finite values everywhere "
            "it is used");
  // sqrt(2 - x) is NaN on the right edge (x = 3), where this traction acts.
  EXPECT_CONTAINS(model_error_of(with("p = [\"0\", \"1\"]", "p = [\"0\", \"sqrt(2 - x)\"]")),
                  "traction[0].p[1] = 'sqrt(2 - x)' is NaN at x = (3, ");
  EXPECT_CONTAINS(model_error_of(with("p = [\"0\", \"1\"]", "p = [\"1/0\", \"1\"]")),
                  "traction[0].p[0] = '1/0' is infinite at x = (3, ");
  EXPECT_CONTAINS(model_error_of(kBase + "[body_force]\nf = [\"log(x - 1)\", 0]\n"),
                  "body_force.f[0] = 'log(x - 1)' is NaN at x = (");
  // Finite where it is used: 1/(x - 3) on the top edge only misses x = 3 by the Gauss points.
  EXPECT_EQ(model_error_of(with("p = [\"0\", \"-2/3*(3 - x)\"]", "p = [\"0\", \"1/(x - 3)\"]")),
            "no error");
}

TEST(ProblemFileWarnings, NearlyIncompressibleMaterial) {
  EXPECT_TRUE(parse_problem_string(kBase, "t.toml").warnings.empty());
  EXPECT_TRUE(parse_problem_string(with("nu = 0.277", "nu = 0.449"), "t.toml").warnings.empty());
  // From 0.45 on, bilinear elements lock visibly (at 0.49 the stress under a contact peak
  // overshoots the contact pressure by some 70 %): say so, and what will avoid it.
  for (const char* nu : {"0.45", "0.495"}) {
    const LoadedProblem p =
        parse_problem_string(with("nu = 0.277", std::string("nu = ") + nu), "t.toml");
    ASSERT_EQ(p.warnings.size(), 1U);
    EXPECT_EQ(p.warnings[0], std::string("t.toml: material.nu = ") + nu +
                                 " >= 0.45: nearly incompressible, and linear elements (quad4) "
                                 "lock: displacements come out too small and stresses near the "
                                 "contact oscillate; use quadratic ones (mesh.cell = \"quad9\" "
                                 "or \"tri6\") or check against a finer mesh");
    EXPECT_EQ(p.spec.elasticity.material.nu, std::stod(nu));  // a warning, not an error
  }
}

TEST(ProblemFileErrors, FileThatCannotBeRead) {
  try {
    read_problem_file("/no/such/problem.toml");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot read '/no/such/problem.toml': No such file or directory");
  }
  const testing::TemporaryFolder dir;
  EXPECT_THROW(read_problem_file(dir.path().string()), InputError);
}

TEST(ProblemFileErrors, UnknownBoundaryIsFoundByBuildModel) {
  const LoadedProblem p =
      parse_problem_string(with("boundary = \"bottom\"", "boundary = \"floor\""), "t.toml");
  EXPECT_THROW(build_model(p.spec), InputError);
}

// Overrides --------------------------------------------------------------------------------

TEST(ProblemFileOverrides, ReplaceValues) {
  const LoadedProblem p = parse_problem_string(
      kBase, "t.toml",
      {"mesh.nx=480", "mesh.ny = 160", "solver.method=semismooth_newton", "solver.r=1e6",
       "material.E=1000", "name=renamed", "contact.gap=0.01*x"});
  EXPECT_EQ(p.spec.mesh.nx, 480);
  EXPECT_EQ(p.spec.mesh.ny, 160);
  EXPECT_EQ(p.spec.solver.method, ContactMethod::SemismoothNewton);
  EXPECT_EQ(p.spec.solver.r, 1e6);
  EXPECT_EQ(p.spec.elasticity.material.E, 1000.0);
  EXPECT_EQ(p.spec.name, "renamed");
  EXPECT_DOUBLE_EQ(p.spec.contacts[0].gap(Point(2.0, 0.0, 0.0)), 0.02);
  EXPECT_CONTAINS(p.effective_toml, "nx = 480\n");
  EXPECT_CONTAINS(p.effective_toml, "method = \"semismooth_newton\"\n");
}

TEST(ProblemFileOverrides, QuotedStringsArraysAndLaterWins) {
  const LoadedProblem p =
      parse_problem_string(kBase, "t.toml",
                           {"solver.method=\"classical_uzawa\"", "traction.1.p=[\"0\", \"-1\"]",
                            "clamp.0.components=[\"x\"]", "mesh.nx=10", "mesh.nx=12"});
  EXPECT_EQ(p.spec.solver.method, ContactMethod::ClassicalUzawa);
  EXPECT_EQ(p.spec.tractions[1].p(Point(1.0, 1.0, 0.0))(1), -1.0);
  EXPECT_TRUE(p.spec.clamps[0].components[0]);
  EXPECT_FALSE(p.spec.clamps[0].components[1]);
  EXPECT_EQ(p.spec.mesh.nx, 12);
}

TEST(ProblemFileOverrides, CreateMissingTables) {
  std::string text = kBase;
  text.erase(text.find("[solver]"));  // no [solver] nor [solver.linear]
  const LoadedProblem p =
      parse_problem_string(text, "t.toml", {"solver.linear.type=cg", "body_force.f=[0, -1]"});
  EXPECT_EQ(p.spec.solver.linear.type, LinearSolverType::ConjugateGradient);
  ASSERT_TRUE(static_cast<bool>(p.spec.body_force));
  EXPECT_EQ(p.spec.body_force(Point(0.0, 0.0, 0.0))(1), -1.0);
}

TEST(ProblemFileOverrides, Errors) {
  EXPECT_EQ(error_of(kBase, {"solver.uzawa_tol=1e-9"}),
            "test.toml: unknown key 'solver.uzawa_tol' (did you mean 'solver.uzawa_tolerance'?), "
            "given by --set");
  EXPECT_CONTAINS(error_of(kBase, {"mesh.nx"}), "--set 'mesh.nx': expected key=value");
  EXPECT_CONTAINS(error_of(kBase, {"=3"}), "expected key=value");
  EXPECT_CONTAINS(error_of(kBase, {"mesh..nx=3"}), "empty part in key");
  EXPECT_CONTAINS(error_of(kBase, {"mesh.nx.a=3"}), "'mesh.nx' is an integer, not a table");
  EXPECT_CONTAINS(error_of(kBase, {"traction.5.p=[0, 1]"}), "'traction' has no table entry 5");
  EXPECT_CONTAINS(error_of(kBase, {"traction.p=[0, 1]"}), "'traction' is an array");
  EXPECT_EQ(error_of(kBase, {"mesh.nx=abc"}),
            "test.toml: key 'mesh.nx' must be an integer, got string");
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// 3D problems ------------------------------------------------------------------------------

// A box on a rigid half-space, every 3D key present (lines as numbered in the messages below).
const std::string kBox = R"toml(
name = "box"
[mesh]
type = "box"
origin = [0.0, 0.0, 0.0]
length = 1.0
width = 1.0
height = 0.5
nx = 2
ny = 2
nz = 1
cell = "hex8"
[material]
E = 1000.0
nu = 0.3
[[clamp]]
boundary = "xmin"
components = ["x"]
[[clamp]]
boundary = "ymin"
components = ["y"]
[[displacement]]
boundary = "zmax"
z = "-0.001*(1 + x)"
[[traction]]
boundary = "xmax"
p = [0, 0, "-0.1*z"]
[[point_load]]
at = [1, 1, 0.5]
force = [0, 0, -0.01]
[body_force]
f = [0, 0, -0.01]
[contact]
boundary = "zmin"
obstacle = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.0, 0.0, 1.0]
)toml";

// `text` with `old` (which it must have) replaced.
std::string replaced(std::string text, const std::string& old, const std::string& replacement) {
  const auto pos = text.find(old);
  if (pos == std::string::npos) throw std::logic_error("no '" + old + "' in the text");
  return text.replace(pos, old.size(), replacement);
}

std::string box_with(const std::string& line, const std::string& replacement) {
  std::string text = kBox;
  const auto pos = text.find("\n" + line + "\n");
  if (pos == std::string::npos) throw std::logic_error("kBox has no line '" + line + "'");
  text.replace(pos + 1, line.size(), replacement);
  return text;
}

TEST(ProblemFile3D, BoxReadsIntoTheLibrarySpec) {
  const LoadedProblem p = parse_problem_string(
      box_with("origin = [0.0, 0.0, 0.0]", "origin = [1, -2, 0.5]"), "box.toml");
  const ProblemSpec& s = p.spec;
  EXPECT_EQ(s.mesh_type, MeshType::Box);
  EXPECT_EQ(s.box.x0, 1.0);
  EXPECT_EQ(s.box.y0, -2.0);
  EXPECT_EQ(s.box.z0, 0.5);
  EXPECT_EQ(s.box.length, 1.0);
  EXPECT_EQ(s.box.width, 1.0);
  EXPECT_EQ(s.box.height, 0.5);
  EXPECT_EQ(s.box.nx, 2);
  EXPECT_EQ(s.box.ny, 2);
  EXPECT_EQ(s.box.nz, 1);
  EXPECT_EQ(s.box.cell, CellType::Hex8);
  // The rectangle's fields are left as they were.
  EXPECT_EQ(s.mesh.nx, RectangleMeshOptions{}.nx);
  ASSERT_EQ(s.clamps.size(), 2U);
  EXPECT_EQ(s.clamps[0].components, (std::array<bool, 3>{true, false, false}));
  EXPECT_EQ(s.clamps[1].components, (std::array<bool, 3>{false, true, false}));
  ASSERT_EQ(s.displacements.size(), 1U);
  EXPECT_FALSE(s.displacements[0].values[0]);
  EXPECT_FALSE(s.displacements[0].values[1]);
  EXPECT_DOUBLE_EQ(s.displacements[0].values[2](Point(1.0, 0.0, 0.5)), -0.002);
  EXPECT_EQ(s.tractions[0].p(Point(1.0, 0.5, 0.5)), Eigen::Vector3d(0.0, 0.0, -0.05));
  EXPECT_EQ(s.point_loads[0].at, Point(1.0, 1.0, 0.5));
  EXPECT_EQ(s.point_loads[0].force, Eigen::Vector3d(0.0, 0.0, -0.01));
  EXPECT_EQ(s.body_force(Point(0.0, 0.0, 0.0)), Eigen::Vector3d(0.0, 0.0, -0.01));
  EXPECT_EQ(s.contacts[0].obstacle.shape, ObstacleShape::Plane);
  EXPECT_EQ(s.contacts[0].obstacle.normal, Eigen::Vector3d(0.0, 0.0, 1.0));
  const Model m = build_model(s);
  EXPECT_EQ(m.mesh.dim(), 3);
  EXPECT_EQ(m.dofs.num_dofs(), 3 * 3 * 3 * 2);
  EXPECT_EQ(m.problem.contact.size(), 9);
}

TEST(ProblemFile3D, BoxDefaultsAndOverrides) {
  // No origin and no cell: the box's own defaults (BoxMeshOptions), not the rectangle's.
  const std::string text =
      replaced(box_with("origin = [0.0, 0.0, 0.0]", ""), "cell = \"hex8\"", "");
  const BoxMeshOptions defaults;
  LoadedProblem p = parse_problem_string(text, "box.toml");
  EXPECT_EQ(p.spec.box.cell, defaults.cell);
  EXPECT_EQ(p.spec.box.z0, defaults.z0);
  EXPECT_CONTAINS(p.effective_toml, "origin = [0.0, 0.0, 0.0]\n");
  EXPECT_CONTAINS(p.effective_toml, "cell = \"hex8\"\n");
  // --set reaches every key of the box.
  p = parse_problem_string(kBox, "box.toml",
                           {"mesh.nz=3", "mesh.origin=[1, 2, 3]", "mesh.cell=tet10", "mesh.width=2",
                            "contact.normal=[0, 1, 1]"});
  EXPECT_EQ(p.spec.box.nz, 3);
  EXPECT_EQ(p.spec.box.z0, 3.0);
  EXPECT_EQ(p.spec.box.cell, CellType::Tet10);
  EXPECT_EQ(p.spec.box.width, 2.0);
  EXPECT_EQ(p.spec.contacts[0].obstacle.normal, Eigen::Vector3d(0.0, 1.0, 1.0));
  EXPECT_CONTAINS(p.effective_toml, "nz = 3\n");
  EXPECT_CONTAINS(p.effective_toml, "origin = [1.0, 2.0, 3.0]\n");
  EXPECT_EQ(build_model(p.spec).dofs.num_dofs(), 3 * 5 * 5 * 7);  // tet10: the half-step lattice
  // A box has no plane model: the effective settings leave it out.
  EXPECT_EQ(p.effective_toml.find("plane_model"), std::string::npos);
}

// The effective settings of a 3D problem read back to the same problem: every option of the box
// away from its default, and every section of formulas and lists with three components.
TEST(ProblemFile3D, EffectiveSettingsRoundTrip) {
  std::string text = replaced(kBox, "obstacle = \"plane\"",
                              "obstacle = \"cylinder\"\ncentre = [0.5, 0, -2]\naxis = [0, 1, 0]\n"
                              "radius = 2\ninside = false");
  text = replaced(text, "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n", "");
  text += "[[pressure]]\nboundary = \"ymax\"\np = \"1 + z\"\n";
  const LoadedProblem p = parse_problem_string(
      text, "box.toml",
      {"mesh.origin=[0.5, -0.5, 1]", "mesh.length=2", "mesh.width=1.5", "mesh.height=0.75",
       "mesh.nx=3", "mesh.ny=4", "mesh.nz=2", "mesh.cell=\"hex27\"",
       "clamp.0.components=[\"x\", \"z\"]", "displacement.0.y=0.001"});
  const LoadedProblem again = read_back(p);
  const ProblemSpec& s = p.spec;
  const ProblemSpec& a = again.spec;
  EXPECT_EQ(a.box.x0, 0.5);
  EXPECT_EQ(a.box.z0, 1.0);
  EXPECT_EQ(a.box.cell, CellType::Hex27);
  ASSERT_EQ(a.clamps.size(), s.clamps.size());
  for (std::size_t i = 0; i < s.clamps.size(); ++i)
    EXPECT_EQ(a.clamps[i].components, s.clamps[i].components) << i;
  EXPECT_EQ(a.clamps[0].components, (std::array<bool, 3>{true, false, true}));
  EXPECT_EQ(displacement_values(a.displacements[0]), displacement_values(s.displacements[0]));
  EXPECT_EQ(a.tractions[0].description, s.tractions[0].description);
  EXPECT_EQ(a.point_loads[0].at, s.point_loads[0].at);
  EXPECT_EQ(a.point_loads[0].force, s.point_loads[0].force);
  EXPECT_EQ(a.body_force_description, s.body_force_description);
  EXPECT_EQ(pressure_values(a.pressures[0]), pressure_values(s.pressures[0]));
  EXPECT_EQ(contact_values(a.contacts[0], a.contacts[0].description, 3),
            contact_values(s.contacts[0], s.contacts[0].description, 3));
  EXPECT_EQ(a.contacts[0].obstacle.axis, Eigen::Vector3d(0.0, 1.0, 0.0));
  EXPECT_CONTAINS(p.effective_toml, "components = [\"x\", \"z\"]\n");
  EXPECT_CONTAINS(p.effective_toml, "at = [1.0, 1.0, 0.5]\n");
  EXPECT_CONTAINS(p.effective_toml, "axis = [0.0, 1.0, 0.0]\n");
}

// Every obstacle shape is read and written from its row of the shapes' table
// (interface/obstacle_parameters.hpp): a problem file made from the row's keys reads into the
// fields the row names and writes back the same keys in the same order; the reference lists
// each key, and a key of another shape is refused naming the shapes that have it.
TEST(ProblemFile3D, EveryObstacleShapeIsReadAndWrittenFromItsRow) {
  const std::string plane =
      "obstacle = \"plane\"\npoint = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n";
  for (const ObstacleShapeRow& row : obstacle_shapes()) {
    const std::string name(enum_to_string(kObstacleShapeNames, row.shape));
    SCOPED_TRACE(name);
    if (row.shape == ObstacleShape::Gap) continue;  // (the paper's formula: its own tests)
    std::string section = "obstacle = \"" + name + "\"\n";
    for (const ObstacleParameter& p : row.parameters) switch (p.kind) {
        case ObstacleParameterKind::Formula:
          break;
        case ObstacleParameterKind::Position:
          section += std::string(p.key) + " = [0.25, 0.5, -3.0]\n";
          break;
        case ObstacleParameterKind::Direction:
        case ObstacleParameterKind::Axis:
          section += std::string(p.key) + " = [0.0, 1.0, 2.0]\n";
          break;
        case ObstacleParameterKind::Positive:
          section += std::string(p.key) + " = 2.5\n";
          break;
        case ObstacleParameterKind::Flag:
          section += std::string(p.key) + " = true\n";
          break;
      }
    const LoadedProblem loaded = parse_problem_string(replaced(kBox, plane, section), "box.toml");
    const ContactSpec& c = loaded.spec.contacts.at(0);
    EXPECT_EQ(c.obstacle.shape, row.shape);
    std::vector<std::string> written;
    for (const auto& [key, value] : contact_values(c, c.description, 3)) written.push_back(key);
    std::vector<std::string> expected{"boundary", "obstacle"};
    for (const ObstacleParameter& p : row.parameters) {
      expected.emplace_back(p.key);
      const auto& keys = contact_options().options;
      EXPECT_TRUE(std::any_of(keys.begin(), keys.end(), [&](const OptionInfo& o) {
        return o.key == p.key;
      })) << p.key;
      if (p.vector != nullptr) {
        EXPECT_EQ(c.obstacle.*p.vector, p.kind == ObstacleParameterKind::Position
                                            ? Eigen::Vector3d(0.25, 0.5, -3.0)
                                            : Eigen::Vector3d(0.0, 1.0, 2.0));
      }
      if (p.number != nullptr) {
        EXPECT_EQ(c.obstacle.*p.number, 2.5);
      }
      if (p.flag != nullptr) {
        EXPECT_TRUE(c.obstacle.*p.flag);
      }
    }
    EXPECT_EQ(written, expected);
    // A key that this shape lacks and another has.
    for (const ObstacleShapeRow& other : obstacle_shapes())
      for (const ObstacleParameter& p : other.parameters)
        if (std::none_of(
                row.parameters.begin(), row.parameters.end(),
                [&](const ObstacleParameter& q) { return std::string_view(q.key) == p.key; })) {
          const std::string with_other =
              replaced(kBox, plane, section + std::string(p.key) + " = 1\n");
          EXPECT_CONTAINS(error_of(with_other),
                          "contact." + std::string(p.key) + " applies with obstacle = ");
        }
  }
}

// Each 3D example reads back from its effective settings to the same settings, and a Gmsh
// volume mesh with them: the settings say the dimension by their points.
TEST(ProblemFile3D, ExamplesRoundTrip) {
  for (const char* name : {"box_on_plane", "box_on_sphere", "box_on_cylinder", "hertz_sphere"}) {
    SCOPED_TRACE(name);
    const LoadedProblem p =
        read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/" + name + ".toml");
    const LoadedProblem again = parse_problem_string(p.effective_toml, p.path);
    EXPECT_EQ(again.effective_toml, p.effective_toml);
    EXPECT_EQ(option_values(again.spec), option_values(p.spec));
    EXPECT_EQ(build_model(again.spec).dofs.num_dofs(), build_model(p.spec).dofs.num_dofs());
  }
}

// contact.surface_normal: three formulas in 3D, written back as given, a formula that does not
// parse refused in one line naming the key, and the dimension it implies checked like any key's.
TEST(ProblemFile3D, SurfaceNormal) {
  const LoadedProblem p =
      read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/hertz_sphere.toml");
  ASSERT_TRUE(static_cast<bool>(p.spec.contacts[0].surface_normal));
  EXPECT_EQ(p.spec.contacts[0].surface_normal(Point(0.5, 0.25, 0.125)),
            Eigen::Vector3d(0.5, 0.25, 0.125 - 1.0));
  EXPECT_CONTAINS(p.effective_toml, "surface_normal = [\"x\", \"y\", \"z - 1\"]\n");
  const std::string box =
      "[mesh]\ntype = \"box\"\nlength = 1\nwidth = 1\nheight = 1\nnx = 2\nny = 2\nnz = "
      "2\n[material]\nE = 1\nnu = 0.3\n[[clamp]]\nboundary = "
      "\"zmax\"\n[contact]\nboundary = \"zmin\"\n";
  EXPECT_CONTAINS(error_of(box + "surface_normal = [\"0\", \"0\", \"-1 +\"]\n"),
                  "contact.surface_normal[2]");
  EXPECT_CONTAINS(error_of(box + "surface_normal = [\"0\", \"-1\"]\n"), "contact.surface_normal");
  const LoadedProblem flat =
      parse_problem_string(box + "surface_normal = [\"0\", \"0\", \"-2\"]\n", "box.toml");
  const Model m = build_model(flat.spec);
  EXPECT_EQ(m.problem.contact.normals.col(0), Eigen::Vector3d(0.0, 0.0, -1.0));
}

// A Gmsh volume mesh from a problem file: the keys' three components are checked against the
// mesh when it is read.
TEST(ProblemFile3D, GmshVolumeMesh) {
  const std::string mesh = SIGNORINI_EXAMPLES_DIR "/gmsh/hertz_sphere_coarse.msh";
  const std::string text = "[mesh]\ntype = \"gmsh\"\nfile = \"" + mesh +
                           "\"\n[material]\nE = 1\nnu = 0.3\n[[clamp]]\nboundary = \"top\"\n"
                           "[contact]\nboundary = \"contact\"\n";
  const LoadedProblem p = parse_problem_string(text, "ball.toml");
  EXPECT_EQ(p.spec.implied_dimension.dimension, 0);  // nothing said: the mesh decides
  // A clamp of every component, written so that it holds z too once the mesh is 3D.
  EXPECT_EQ(p.effective_toml.find("components"), std::string::npos) << p.effective_toml;
  EXPECT_EQ(build_model(p.spec).mesh.dim(), 3);
  EXPECT_EQ(build_model(parse_problem_string(p.effective_toml, "again.toml").spec).dofs.num_free(),
            build_model(p.spec).dofs.num_free());
  // Keys that disagree with each other are refused when the file is read, naming both (the
  // tractions are read before the point loads).
  const std::string both = text +
                           "[[point_load]]\nat = [0, 0, 1]\nforce = [0, 0, -1]\n"
                           "[[traction]]\nboundary = \"xsym\"\np = [1, 0]\n";
  EXPECT_EQ(error_of(both),
            "test.toml:12: key 'point_load[0].at' gives 3 components (3D problems only), but "
            "traction[0].p gives 2 components (2D problems only): expected 2 components (x, y)");
  // Keys that disagree with the mesh, when the model is built.
  const LoadedProblem flat =
      parse_problem_string(text + "[[point_load]]\nat = [0, 0]\nforce = [0, -1]\n", "t.toml");
  try {
    (void)build_model(flat.spec);
    FAIL() << "2D points on a 3D mesh were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "point_load[0].at gives 2 components (2D problems only), but "
              "the mesh '" +
                  mesh + "' is 3D: expected 3 components (x, y, z)");
  }
}

TEST(ProblemFile3DErrors, BoxKeys) {
  EXPECT_EQ(error_of(box_with("origin = [0.0, 0.0, 0.0]", "origin = [0.0, 0.0]")),
            "test.toml:5: key 'mesh.origin' must have 3 entries (x0, y0, z0), got 2");
  EXPECT_EQ(error_of(with("origin = [0.0, 0.0]", "origin = [0.0, 0.0, 0.0]")),
            "test.toml:5: key 'mesh.origin' must have 2 entries (x0, y0), got 3");
  EXPECT_EQ(error_of(box_with("nz = 1", "nz = 0")),
            "test.toml:11: key 'mesh.nz' = 0: expected an integer >= 1");
  EXPECT_EQ(error_of(kBox, {"mesh.nz=-2"}),
            "test.toml: key 'mesh.nz' = -2: expected an integer >= 1");
  EXPECT_EQ(error_of(box_with("width = 1.0", "width = 0")),
            "test.toml:7: key 'mesh.width' = 0.0: expected a positive number");
  EXPECT_EQ(error_of(box_with("nz = 1", "")),
            "test.toml: missing required key 'mesh.nz' (integer >= 1)");
  EXPECT_EQ(error_of(box_with("width = 1.0", "")),
            "test.toml: missing required key 'mesh.width' (number > 0)");
  EXPECT_CONTAINS(
      error_of(box_with("cell = \"hex8\"", "cell = \"hex20\"")),
      "test.toml:12: key 'mesh.cell' must be \"quad4\", \"quad8\", \"quad9\", \"tri3\", "
      "\"tri6\", \"hex8\", \"hex27\", \"tet4\" or \"tet10\", got 'hex20'");
  EXPECT_EQ(error_of(box_with("cell = \"hex8\"", "cell = \"quad4\"")),
            "test.toml:12: key 'mesh.cell' = \"quad4\" is a 2D cell: with type = \"box\" expected "
            "\"hex8\", \"hex27\", \"tet4\" or \"tet10\"");
  EXPECT_EQ(error_of(kBase, {"mesh.cell=hex8"}),
            "test.toml: key 'mesh.cell' = \"hex8\" is a 3D cell: with type = \"rectangle\" "
            "expected \"quad4\", \"quad8\", \"quad9\", \"tri3\" or \"tri6\"");
  EXPECT_EQ(error_of(with("nx = 6", "nx = 6\nnz = 2")),
            "test.toml:9: mesh.nz applies with type = \"box\" only; remove it");
  EXPECT_EQ(error_of(with("nx = 6", "nx = 6\nwidth = 2.0")),
            "test.toml:9: mesh.width applies with type = \"box\" only; remove it");
  EXPECT_EQ(error_of(box_with("nu = 0.3", "nu = 0.3\nplane_model = \"plane_stress\"")),
            "test.toml:16: material.plane_model applies with a 2D problem (type = \"rectangle\", "
            "or \"gmsh\" with a 2D mesh) only; remove it");
}

TEST(ProblemFile3DErrors, PointsAndVectorsHaveThreeComponents) {
  EXPECT_EQ(error_of(box_with("p = [0, 0, \"-0.1*z\"]", "p = [0, 0]")),
            "test.toml: key 'traction[0].p' must have 3 entries (x, y and z components), got 2");
  EXPECT_EQ(error_of(box_with("f = [0, 0, -0.01]", "f = [0, -0.01]")),
            "test.toml: key 'body_force.f' must have 3 entries (x, y and z components), got 2");
  EXPECT_EQ(error_of(box_with("at = [1, 1, 0.5]", "at = [1, 1]")),
            "test.toml:29: key 'point_load[0].at' must have 3 entries (x, y and z), got 2");
  EXPECT_EQ(error_of(box_with("force = [0, 0, -0.01]", "force = [0, 0, -0.01, 0]")),
            "test.toml:30: key 'point_load[0].force' must have 3 entries (x, y and z), got 4");
  EXPECT_EQ(error_of(box_with("point = [0.0, 0.0, 0.0]", "point = [0.0, 0.0]")),
            "test.toml:36: key 'contact.point' must have 3 entries (x, y and z), got 2");
  EXPECT_EQ(error_of(box_with("normal = [0.0, 0.0, 1.0]", "normal = [0, 0, 0]")),
            "test.toml:37: contact.normal = [0, 0, 0]: expected a non-zero vector pointing from "
            "the obstacle towards the body");
  EXPECT_EQ(error_of(replaced(box_with("obstacle = \"plane\"",
                                       "obstacle = \"disc\"\ncentre = [0, 0]\nradius = 1"),
                              "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n", "")),
            "test.toml:36: key 'contact.centre' must have 3 entries (x, y and z), got 2");
  // In 2D, as before: a third component is an error.
  EXPECT_EQ(error_of(kBase + "[[point_load]]\nat = [1, 1, 0]\nforce = [0, -1]\n"),
            "test.toml:35: key 'point_load[0].at' must have 2 entries (x and y), got 3");
}

TEST(ProblemFile3DErrors, Cylinder) {
  const std::string cylinder =
      "obstacle = \"cylinder\"\ncentre = [0.5, 0, -2]\naxis = [0, 1, 0]\nradius = 2";
  const std::string text = replaced(box_with("obstacle = \"plane\"", cylinder),
                                    "point = [0.0, 0.0, 0.0]\nnormal = [0.0, 0.0, 1.0]\n", "");
  EXPECT_EQ(parse_problem_string(text, "t.toml").spec.contacts[0].obstacle.shape,
            ObstacleShape::Cylinder);
  const auto cylinder_with = [&](const std::string& line, const std::string& replacement) {
    return replaced(text, line, replacement);
  };
  EXPECT_EQ(error_of(cylinder_with("axis = [0, 1, 0]", "axis = [0, 0, 0]")),
            "test.toml:37: contact.axis = [0, 0, 0]: expected a non-zero vector along the "
            "cylinder's axis");
  EXPECT_EQ(error_of(cylinder_with("axis = [0, 1, 0]", "axis = [0, 1]")),
            "test.toml:37: key 'contact.axis' must have 3 entries (x, y and z), got 2");
  EXPECT_EQ(error_of(cylinder_with("axis = [0, 1, 0]\n", "")),
            "test.toml: missing required key 'contact.axis' ([ax, ay, az]: the direction of the "
            "cylinder's axis)");
  EXPECT_EQ(error_of(cylinder_with("radius = 2", "radius = 0")),
            "test.toml:38: key 'contact.radius' = 0.0: expected a positive number");
  EXPECT_EQ(error_of(cylinder_with("centre = [0.5, 0, -2]", "centre = [0.5, 0]")),
            "test.toml:36: key 'contact.centre' must have 3 entries (x, y and z), got 2");
}

TEST(ProblemFile3DErrors, TwoDimensionalKeysAreRefusedIn3D) {
  EXPECT_EQ(
      error_of(box_with("p = [0, 0, \"-0.1*z\"]", "p = [0, 0, \"-0.1*z\"]\nx_range = [0, 1]")),
      "test.toml:28: key 'traction[0].x_range' gives a coordinate range (2D problems only), "
      "but the mesh is 3D (mesh.type = \"box\"): expected no range (not supported on 3D "
      "boundary parts yet): make the loaded part a boundary part of its own");
  EXPECT_EQ(error_of(box_with("z = \"-0.001*(1 + x)\"", "normal = -0.001")),
            "test.toml:24: key 'displacement[0].normal' gives a normal displacement (2D problems "
            "only), but the mesh is 3D (mesh.type = \"box\"): expected the components x, y and z "
            "(a normal displacement is not supported in 3D yet)");
  EXPECT_EQ(error_of(box_with("components = [\"x\"]", "components = [\"x\", \"w\"]")),
            "test.toml: key 'clamp[0].components[1]' must be \"x\", \"y\" or \"z\", got 'w'");
  // And the 3D keys in 2D.
  EXPECT_EQ(error_of(kBase + "[[displacement]]\nboundary = \"top\"\nz = 0.1\n"),
            "test.toml:36: key 'displacement[0].z' gives component z (3D problems only), but the "
            "mesh is 2D (mesh.type = \"rectangle\"): expected x and y only");
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// Friction keys of [contact] (docs/problem-format.md): the law, its parameter, and the keys of
// the other laws refused.
TEST(ProblemFileFriction, ReadsTheLawAndItsParameter) {
  const ProblemSpec tresca =
      parse_problem_string(with("gap = \"0\"", "friction = \"tresca\"\nslip_bound = \"0.1 + x\""),
                           "test.toml")
          .spec;
  ASSERT_EQ(tresca.contacts.size(), 1U);
  EXPECT_EQ(tresca.contacts[0].friction, FrictionModel::Tresca);
  EXPECT_DOUBLE_EQ(tresca.contacts[0].slip_bound(Point(2.0, 0.0, 0.0)), 2.1);
  const ProblemSpec coulomb =
      parse_problem_string(with("gap = \"0\"", "friction = \"coulomb\"\nmu = 0.25"), "test.toml")
          .spec;
  EXPECT_EQ(coulomb.contacts[0].friction, FrictionModel::Coulomb);
  EXPECT_EQ(coulomb.contacts[0].mu, 0.25);
  EXPECT_EQ(parse_problem_string(kBase, "test.toml").spec.contacts[0].friction,
            FrictionModel::None);
}

TEST(ProblemFileFriction, BadFrictionInputGetsOneLineNamingTheKey) {
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "friction = \"stick\"")),
                  "contact.friction = \"stick\": expected");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "friction = \"coulomb\"")), "contact.mu");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "friction = \"coulomb\"\nmu = -0.1")), "contact.mu");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "friction = \"tresca\"")), "contact.slip_bound");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "friction = \"tresca\"\nmu = 0.3")),
                  "contact.mu applies with friction = \"coulomb\" only");
  EXPECT_CONTAINS(error_of(with("gap = \"0\"", "slip_bound = \"1\"")),
                  "contact.slip_bound applies with friction = \"tresca\" only");
  // A negative bound is found where it is evaluated, at a contact node.
  const ProblemSpec negative =
      parse_problem_string(with("gap = \"0\"", "friction = \"tresca\"\nslip_bound = \"1 - x\""),
                           "test.toml")
          .spec;
  try {
    static_cast<void>(build_model(negative));
    ADD_FAILURE() << "a negative slip bound was accepted";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(std::string(e.what()), "contact.slip_bound = \"1 - x\" is -");
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

TEST(ProblemFileLoading, StepsAndFactors) {
  EXPECT_TRUE(parse_problem_string(kBase, "t.toml").spec.load_factors.empty());
  const std::vector<double> four = {0.25, 0.5, 0.75, 1.0};
  EXPECT_EQ(parse_problem_string(kBase + "[loading]\nsteps = 4\n", "t.toml").spec.load_factors,
            four);
  const std::vector<double> table = {0.5, 1.0, 0.0};
  EXPECT_EQ(parse_problem_string(kBase + "[loading]\nfactors = [0.5, 1, 0]\n", "t.toml")
                .spec.load_factors,
            table);
  // As an override too, and echoed in the effective settings.
  const LoadedProblem set = parse_problem_string(kBase, "t.toml", {"loading.steps=2"});
  EXPECT_EQ(set.spec.load_factors, (std::vector<double>{0.5, 1.0}));
  EXPECT_CONTAINS(set.effective_toml, "[loading]");
}

TEST(ProblemFileLoading, BadLoadingGetsOneLineNamingTheKey) {
  EXPECT_CONTAINS(error_of(kBase + "[loading]\nsteps = 0\n"), "loading.steps");
  EXPECT_CONTAINS(error_of(kBase + "[loading]\nfactors = [0.5, -1]\n"), "loading.factors[1]");
  EXPECT_CONTAINS(error_of(kBase + "[loading]\nfactors = []\n"), "loading.factors");
  EXPECT_CONTAINS(error_of(kBase + "[loading]\nsteps = 2\nfactors = [1]\n"), "give one of them");
  EXPECT_CONTAINS(error_of(kBase + "[loading]\n"), "loading.steps");
  EXPECT_CONTAINS(error_of(kBase + "[loading]\nstep = 3\n"), "loading");
}

// kBase with the right end's traction given `factors` of its own.
std::string with_own_factors(const std::string& factors) {
  std::string text = kBase;
  const std::string p = "p = [\"0\", \"1\"]\n";
  text.replace(text.find(p), p.size(), p + "factors = " + factors + "\n");
  return text;
}

TEST(ProblemFileLoading, EntriesWithFactorsOfTheirOwn) {
  const std::string body = "[body_force]\nf = [\"0\", \"-1\"]\nfactors = [1, 0.5]\n";
  const std::string more =
      "[[point_load]]\nat = [1.5, 1.0]\nforce = [0, -1]\nfactors = [0, 1]\n"
      "[[pressure]]\nboundary = \"top\"\np = 2\nfactors = [3, 0]\n"
      "[[displacement]]\nboundary = \"right\"\nx = 1e-6\nfactors = [0, -1]\n";
  const LoadedProblem loaded = parse_problem_string(
      with_own_factors("[0, 2.5]") + body + more + "[loading]\nsteps = 2\n", "t.toml");
  const ProblemSpec& spec = loaded.spec;
  EXPECT_EQ(spec.tractions[0].factors, (std::vector<double>{0.0, 2.5}));
  EXPECT_TRUE(spec.tractions[1].factors.empty());
  EXPECT_EQ(spec.body_force_factors, (std::vector<double>{1.0, 0.5}));
  EXPECT_EQ(spec.point_loads[0].factors, (std::vector<double>{0.0, 1.0}));
  EXPECT_EQ(spec.pressures[0].factors, (std::vector<double>{3.0, 0.0}));
  EXPECT_EQ(spec.displacements[0].factors, (std::vector<double>{0.0, -1.0}));
  // The effective settings keep them: read again, they give the same.
  const ProblemSpec again = parse_problem_string(loaded.effective_toml, "effective.toml").spec;
  EXPECT_EQ(again.tractions[0].factors, spec.tractions[0].factors);
  EXPECT_EQ(again.body_force_factors, spec.body_force_factors);
  EXPECT_EQ(again.point_loads[0].factors, spec.point_loads[0].factors);
  EXPECT_EQ(again.pressures[0].factors, spec.pressures[0].factors);
  EXPECT_EQ(again.displacements[0].factors, spec.displacements[0].factors);
}

TEST(ProblemFileLoading, BadOwnFactorsGetOneLineNamingTheKey) {
  EXPECT_CONTAINS(error_of(with_own_factors("[0, 1]")), "traction[0].factors");
  EXPECT_CONTAINS(error_of(with_own_factors("[0, 1]")), "[loading]");
  EXPECT_CONTAINS(error_of(with_own_factors("[0, 1]") + "[loading]\nsteps = 3\n"),
                  "traction[0].factors: expected 3 load factors, one per step of [loading], got 2");
  EXPECT_CONTAINS(error_of(with_own_factors("[0, \"a\"]") + "[loading]\nsteps = 2\n"),
                  "traction[0].factors[1]");
  EXPECT_CONTAINS(error_of(with_own_factors("[]") + "[loading]\nsteps = 2\n"),
                  "traction[0].factors");
  EXPECT_CONTAINS(error_of(with_own_factors("0.5") + "[loading]\nsteps = 2\n"),
                  "traction[0].factors");
  EXPECT_CONTAINS(error_of(kBase + "[body_force]\nf = [\"0\", \"-1\"]\nfactors = [1]\n"
                                   "[loading]\nsteps = 2\n"),
                  "body_force.factors: expected 2");
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// [[clamp]] at: one pinned node, the nearest to the point (on the boundary, where one is named).
TEST(ProblemFileClamp, AtPinsTheNearestNode) {
  const std::string text =
      with("[[clamp]]\nboundary = \"left\"\ncomponents = [\"x\", \"y\"]",
           "[[clamp]]\nboundary = \"left\"\ncomponents = [\"x\"]\n[[clamp]]\nat = [0.1, 0.05]\n"
           "components = [\"y\"]");
  const LoadedProblem loaded = parse_problem_string(text, "t.toml");
  ASSERT_EQ(loaded.spec.clamps.size(), 2U);
  ASSERT_TRUE(loaded.spec.clamps[1].at.has_value());
  EXPECT_CONTAINS(loaded.effective_toml, "at = [0.1, 0.05]");
  const Model model = build_model(loaded.spec);
  // The node at the origin (nearest to (0.1, 0.05) on this 6 x 2 mesh of (0, 3) x (0, 1)).
  EXPECT_TRUE(model.dofs.is_clamped(0, 1));
  EXPECT_FALSE(model.dofs.is_clamped(1, 1));
  ASSERT_EQ(model.clamped_parts.size(), 2U);
  EXPECT_EQ(model.clamped_parts[1].boundary, "at (0.1, 0.05)");
  EXPECT_EQ(model.clamped_parts[1].dofs.size(), 1U);
  EXPECT_CONTAINS(error_of(with("[[clamp]]\nboundary = \"left\"\ncomponents = [\"x\", \"y\"]",
                                "[[clamp]]\ncomponents = [\"x\", \"y\"]")),
                  "clamp[0].boundary");
}

}  // namespace
}  // namespace signorini

// The option tables (core/option_table.hpp, input/problem_schema.hpp): defaults come from the
// structs, words of ranges, validate() naming keys as the file spells them, every option settable
// and range-checked through --set, and the generated key tables of docs/problem-format.md.

#include "signorini/core/option_table.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <limits>
#include <sstream>

#include "expect_contains.hpp"
#include "input/option_values.hpp"
#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/option_docs.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/input/toml_emitter.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {
namespace {

const std::string kProblem = R"toml(
[mesh]
length = 3.0
height = 1.0
nx = 6
ny = 2
[material]
E = 21.19e4
nu = 0.277
[[clamp]]
boundary = "left"
[contact]
boundary = "bottom"
)toml";

std::string error_of(const std::vector<std::string>& overrides) {
  try {
    parse_problem_string(kProblem, "t.toml", overrides);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

std::string validate_error(const ContactSolverOptions& o) {
  try {
    validate(o);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Options, DefaultsComeFromDefaultConstructedStructs) {
  const ContactSolverOptions solver;
  const OptionTable<ContactSolverOptions>& t = contact_solver_option_table();
  for (std::size_t i = 0; i < t.options.size(); ++i) {
    ASSERT_TRUE(t.options[i].default_value.has_value()) << t.options[i].key;
    EXPECT_TRUE(*t.options[i].default_value == t.getter(i)(solver)) << t.options[i].key;
  }
  EXPECT_TRUE(*t.find("max_uzawa_iterations")->default_value == OptionValue(std::int64_t{1000}));
  EXPECT_TRUE(*t.find("r")->default_value == OptionValue(std::monostate{}));  // automatic
  EXPECT_TRUE(*t.find("method")->default_value == OptionValue(std::string("uzawa_gnm")));
  EXPECT_TRUE(*linear_solver_option_table().find("cg_tolerance")->default_value ==
              OptionValue(LinearSolverOptions{}.cg_tolerance));
  EXPECT_TRUE(*fem_options().find("gauss_points")->default_value == OptionValue(std::int64_t{2}));
  EXPECT_EQ(linear_solver_option_table().find("chebyshev_degree")->integer_bits, 32);
  EXPECT_EQ(mesh_options().find("nx")->integer_bits, 64);
}

TEST(Options, WordsOfKindsAndRanges) {
  const auto& solver = contact_solver_option_table();
  EXPECT_EQ(expected_words(*solver.find("uzawa_tolerance")), "a positive number");
  EXPECT_EQ(expected_words(*solver.find("kkt_tolerance")), "a number in (0, 1)");
  EXPECT_EQ(expected_words(*solver.find("max_uzawa_iterations")), "an integer >= 1");
  EXPECT_EQ(expected_words(*solver.find("max_gnm_iterations")), "an integer >= 0 (0: automatic)");
  EXPECT_EQ(expected_words(*solver.find("classical_step")), "a number >= 0 (0: automatic)");
  EXPECT_EQ(expected_words(*solver.find("r")), "a positive number or \"auto\"");
  EXPECT_EQ(expected_words(*solver.find("method")),
            "\"uzawa_gnm\", \"classical_uzawa\" or \"semismooth_newton\"");
  EXPECT_EQ(type_words(*solver.find("armijo_sigma")), "number in (0, 0.5)");
  EXPECT_EQ(type_words(*solver.find("r"), true), "number > 0 or `\"auto\"`");
  EXPECT_EQ(type_words(*solver.find("device"), true), "`\"cpu\"` or `\"cuda\"`");
  EXPECT_EQ(type_words(*solver.find("schur_complement")), "boolean");
  EXPECT_EQ(type_words(*linear_solver_option_table().find("chebyshev_degree")),
            "integer in [1, 50]");
  EXPECT_EQ(type_words(*mesh_options().find("origin")),
            "array of 2 numbers (rectangle) or 3 (box)");
  EXPECT_EQ(expected_words(*mesh_options().find("origin")),
            "an array of 2 numbers (rectangle) or 3 (box)");
  EXPECT_FALSE(positive().contains(0.0));
  EXPECT_FALSE(positive().contains(std::numeric_limits<double>::infinity()));
  EXPECT_FALSE(at_least(0.0).contains(std::nan("")));
  EXPECT_TRUE(closed_interval(1, 5).contains(5.0));
  EXPECT_FALSE(open_interval(-1, 0.5).contains(0.5));
}

TEST(Options, ValidateNamesTheKeyAsTheFileSpellsIt) {
  ContactSolverOptions o;
  o.kkt_tolerance = 2.0;
  EXPECT_EQ(validate_error(o), "solver.kkt_tolerance = 2: expected a number in (0, 1)");
  o = {};
  o.r = -1.0;
  EXPECT_EQ(validate_error(o), "solver.r = -1: expected a positive number or \"auto\"");
  o = {};
  o.max_newton_iterations = -1;
  EXPECT_EQ(validate_error(o),
            "solver.max_newton_iterations = -1: expected an integer >= 0 (0: automatic)");
  o = {};
  o.max_uzawa_iterations = 0;
  EXPECT_EQ(validate_error(o), "solver.max_uzawa_iterations = 0: expected an integer >= 1");
  o = {};
  o.linear.cg_max_iterations = -1;
  EXPECT_EQ(validate_error(o),
            "solver.linear.cg_max_iterations = -1: expected an integer >= 0 (0: automatic)");
  o = {};
  o.uzawa_tolerance = std::nan("");
  EXPECT_EQ(validate_error(o), "solver.uzawa_tolerance = nan: expected a positive number");
  EXPECT_EQ(validate_error(ContactSolverOptions{}), "no error");
}

// Every option of every table, set by --set to a value other than its default, is read (the
// reader knows every key the tables declare, with the kind they declare).
TEST(Options, EveryOptionCanBeSet) {
  int count = 0;
  for (const OptionTableInfo* table : problem_schema())
    for (const OptionInfo& o : table->options) {
      const std::string key = table->full_key(o.key);
      // mesh.type = "gmsh" needs a file, and the keys of a Gmsh mesh apply to it alone (read by
      // tests/app/gmsh_mesh_test.cpp); here the mesh stays a rectangle, but for the box's own
      // keys, set on a box.
      if (key == "mesh.type" || o.condition == "type = \"gmsh\"") continue;
      const std::optional<OptionValue> v = testing::other_value(o, key);
      if (!v) continue;
      const std::vector<std::string> box = {"mesh.type=\"box\"", "mesh.width=1", "mesh.nz=1",
                                            "mesh.cell=\"hex8\""};
      std::vector<std::string> overrides =
          o.condition == "type = \"box\"" ? box : std::vector<std::string>{};
      overrides.push_back(key + "=" + toml_value_text(*v));
      EXPECT_EQ(error_of(overrides), "no error") << key;
      ++count;
    }
  EXPECT_GE(count, 25);
  EXPECT_EQ(error_of({"mesh.type=\"box\"", "mesh.width=1", "mesh.nz=1", "mesh.cell=\"tet10\"",
                      "mesh.origin=[1, 2, 3]"}),
            "no error");
  // An option where it does not apply is refused with its condition.
  EXPECT_EQ(error_of({"mesh.file=\"x.msh\""}),
            "t.toml: mesh.file applies with type = \"gmsh\" only; remove it");
}

// A value out of an option's range is refused by the reader, naming the key and the range the
// table declares (the material's, by the library's validate(), in its own words).
TEST(Options, EveryRangeIsCheckedByTheReader) {
  int count = 0;
  for (const OptionTableInfo* table : problem_schema())
    for (const OptionInfo& o : table->options) {
      if (o.kind != OptionKind::Number && o.kind != OptionKind::Integer) continue;
      const std::string key = table->full_key(o.key);
      const double outside = o.range.lower ? *o.range.lower - 1.0 : *o.range.upper + 1.0;
      const std::string value = o.kind == OptionKind::Integer
                                    ? std::to_string(static_cast<long long>(outside))
                                    : toml_float(outside);
      // The box's own keys on a box (whose other keys the rectangle's file has, but these).
      std::vector<std::string> overrides;
      if (o.condition == "type = \"box\"")
        overrides = {"mesh.type=\"box\"", "mesh.width=1", "mesh.nz=1", "mesh.cell=\"hex8\""};
      overrides.push_back(key + "=" + value);
      const std::string m = error_of(overrides);
      if (table->path == "material") {
        EXPECT_EQ(m.rfind("t.toml: " + key + " = ", 0), 0U) << m;
      } else {
        EXPECT_EQ(m, "t.toml: key '" + key + "' = " + value + ": expected " + expected_words(o));
      }
      ++count;
    }
  EXPECT_GE(count, 20);
  EXPECT_EQ(error_of({"solver.max_gnm_iterations=4294967296"}),
            "t.toml: key 'solver.max_gnm_iterations' = 4294967296: expected an integer that fits "
            "in 32 bits");
}

TEST(Options, UnknownKeysAndSuggestionsComeFromTheTables) {
  EXPECT_EQ(error_of({"solver.linear.chebyshev=3"}),
            "t.toml: unknown key 'solver.linear.chebyshev' (did you mean "
            "'solver.linear.chebyshev_degree'?), given by --set");
  EXPECT_EQ(error_of({"material.youngs_modulus=3"}),
            "t.toml: unknown key 'material.youngs_modulus' (did you mean 'material.E'?), given "
            "by --set");
  EXPECT_EQ(error_of({"contact.clearance=0.1"}),
            "t.toml: unknown key 'contact.clearance' (did you mean 'contact.gap'?), given by "
            "--set");
  EXPECT_EQ(error_of({"gauss_points=3"}),
            "t.toml: unknown key 'gauss_points' (did you mean 'fem.gauss_points'? it belongs in "
            "the [fem] section), given by --set");
  EXPECT_EQ(error_of({"solver.x_range=[0, 1]"}),
            "t.toml: unknown key 'solver.x_range' (did you mean 'traction.x_range'? it belongs "
            "in the [[traction]] section), given by --set");
}

TEST(Options, MarkdownTable) {
  const std::string md = option_table_markdown(contact_solver_option_table());
  EXPECT_EQ(md.rfind("| key | type | default | meaning |\n|---|---|---|---|\n", 0), 0U) << md;
  EXPECT_CONTAINS(md, "| `kkt_tolerance` | number in (0, 1) | `1e-6` | ");
  EXPECT_CONTAINS(md, "| `r` | number > 0 or `\"auto\"` | `\"auto\"` | ");
  EXPECT_CONTAINS(md, "| `max_classical_iterations` | integer >= 1 | `200000` | ");
  EXPECT_CONTAINS(md, "| `schur_complement` | boolean | `true` | ");
  EXPECT_CONTAINS(md, "\\|\\|l^k - l^(k-1)\\|\\|");  // '|' escaped in a cell
  const std::string mesh = option_table_markdown(mesh_options());
  EXPECT_CONTAINS(mesh, "| key | type | unit | default | meaning |");
  EXPECT_CONTAINS(mesh,
                  "| `origin` | array of 2 numbers (rectangle) or 3 (box) | L | `[0.0, 0.0]` or "
                  "`[0.0, 0.0, 0.0]` | ");
  EXPECT_CONTAINS(mesh,
                  "| `nx` | integer >= 1 | | required with type = \"rectangle\" or \"box\" | cells "
                  "along x |");
  EXPECT_CONTAINS(mesh,
                  "| `nz` | integer >= 1 | | required with type = \"box\" | box: cells "
                  "along z |");
  EXPECT_EQ(section_title(clamp_options()), "[[clamp]]");
  EXPECT_EQ(section_title(top_level_options()), "top level");
  EXPECT_THROW((void)with_generated_option_tables("no markers"), InputError);
}

// docs/problem-format.md lists the keys as the tables declare them. To regenerate its tables
// after a change to a table:
//   SIGNORINI_UPDATE_DOCS=1 build/release/tests/signorini_tests --gtest_filter='Docs.*'
TEST(Docs, ProblemFormatKeyTablesAreGenerated) {
  const std::string path = SIGNORINI_EXAMPLES_DIR "/../docs/problem-format.md";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::ostringstream text;
  text << in.rdbuf();
  const std::string current = text.str();
  const std::string generated = with_generated_option_tables(current);
  if (generated == current) return;
  const char* update = std::getenv("SIGNORINI_UPDATE_DOCS");
  if (update != nullptr && std::string(update) == "1") {
    std::ofstream(path, std::ios::binary) << generated;
    std::cout << "rewrote the option tables of " << path << "\n";
    return;
  }
  // The first line that differs, as a hint of what changed.
  std::istringstream a(current), b(generated);
  std::string line_a, line_b;
  int number = 0;
  while (true) {
    ++number;
    const bool more_a = static_cast<bool>(std::getline(a, line_a));
    const bool more_b = static_cast<bool>(std::getline(b, line_b));
    if (!more_a && !more_b) break;
    if (!more_a || !more_b || line_a != line_b) break;
  }
  ADD_FAILURE() << path << " differs from the option tables at line " << number
                << ":\n  docs:      " << line_a << "\n  generated: " << line_b
                << "\nRegenerate the docs' tables with\n  SIGNORINI_UPDATE_DOCS=1 "
                   "build/release/tests/signorini_tests --gtest_filter='Docs.*'\n(or the "
                   "signorini_tests of your build folder).";
}

}  // namespace
}  // namespace signorini

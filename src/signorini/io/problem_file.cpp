#include "signorini/io/problem_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>

#include "signorini/core/error.hpp"
#include "signorini/io/expression.hpp"
#include "signorini/io/suggestion.hpp"
#include "signorini/io/toml_emitter.hpp"
#include "signorini/problem/unit_system.hpp"

namespace signorini {

namespace {

// Messages from other libraries (toml++, muParser) may span lines; ours are one line each.
std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

// The names a user sees in "must be an integer, got string".
const char* type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

// Expressions may be written as TOML numbers ("p = [0, 1]"); muParser gets their text.
std::optional<std::string> expression_text(const toml::node& n) {
  if (const auto* s = n.as_string()) return s->get();
  if (const auto* i = n.as_integer()) return std::to_string(i->get());
  if (const auto* f = n.as_floating_point()) return toml_float(f->get());
  return std::nullopt;
}

// Every key of a problem file, by table ("clamp" stands for each [[clamp]] entry): one list that
// check_keys() holds each table to and that a misplaced key is looked up in.
const std::vector<std::pair<std::string, std::vector<std::string>>>& schema() {
  static const std::vector<std::pair<std::string, std::vector<std::string>>> tables = {
      {"",
       {"name", "units", "mesh", "material", "fem", "clamp", "traction", "point_load", "body_force",
        "contact", "solver"}},
      {"mesh", {"type", "origin", "length", "height", "nx", "ny"}},
      {"material", {"E", "nu", "plane_model"}},
      {"fem", {"gauss_points", "boundary_gauss_points"}},
      {"clamp", {"boundary", "components"}},
      {"traction", {"boundary", "p", "x_range", "y_range"}},
      {"point_load", {"at", "force", "boundary"}},
      {"body_force", {"f"}},
      {"contact", {"boundary", "gap"}},
      {"solver",
       {"method", "r", "auto_r_factor", "kkt_tolerance", "uzawa_tolerance", "max_uzawa_iterations",
        "gnm_tolerance", "max_gnm_iterations", "armijo_sigma", "max_armijo_halvings",
        "classical_step", "max_classical_iterations", "max_newton_iterations", "schur_complement",
        "device", "linear"}},
      {"solver.linear",
       {"type", "cg_tolerance", "cg_max_iterations", "preconditioner", "coarsening",
        "chebyshev_degree"}},
  };
  return tables;
}

// "clamp[2]" -> "clamp": the schema's name of a table path.
std::string schema_path(const std::string& path) {
  const auto bracket = path.find('[');
  return bracket == std::string::npos ? path : path.substr(0, bracket);
}

const std::vector<std::string>& known_keys(const std::string& path) {
  for (const auto& [table, keys] : schema())
    if (table == schema_path(path)) return keys;
  static const std::vector<std::string> none;
  return none;
}

// Names that people write for our keys, which spelling distance does not find.
std::string synonym_of(const std::string& key) {
  std::string k;
  for (const char c : key) k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (k.find("young") != std::string::npos || k.find("modulus") != std::string::npos || k == "emod")
    return "E";
  if (k.find("poisson") != std::string::npos || k == "v" || k == "mu_poisson") return "nu";
  if (k == "load" || k == "pressure" || k == "traction" || k == "force") return "p";
  if (k == "clearance" || k == "initial_gap" || k == "g") return "gap";
  return "";
}

// "<file>:<line>: " where the node came from the file (not from --set), else "<file>: ".
std::string where(const std::string& file, const toml::source_region& source) {
  if (source.begin.line == 0 || !source.path || *source.path != file) return file + ": ";
  return file + ":" + std::to_string(source.begin.line) + ": ";
}

// How a file is read: its name for messages, and which keys came from --set (an unknown key says
// so, since the user would otherwise look for it in the file).
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden)
      : file_(std::move(file)), overridden_(std::move(overridden)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_ + ": " + one_line(message));
  }

  // With the line of the file where the offending key or value is.
  [[noreturn]] void fail_at(const toml::source_region& source, const std::string& message) const {
    throw InputError(where(file_, source) + one_line(message));
  }

  // Unknown keys are checked before the values of a table are read, so that a misspelt required
  // key reports "unknown key 'mesh.nxx' (did you mean 'mesh.nx'?)", not "missing 'mesh.nx'".
  void check_keys(const toml::table& t, const std::string& path) const {
    const std::vector<std::string>& known = known_keys(path);
    for (auto&& [k, v] : t) {
      const std::string key(k.str());
      if (std::find(known.begin(), known.end(), key) != known.end()) continue;
      std::string message = "unknown key '" + join(path, key) + "'";
      std::string guess = closest_match(key, known);
      if (guess.empty()) {
        const std::string synonym = synonym_of(key);
        if (std::find(known.begin(), known.end(), synonym) != known.end()) guess = synonym;
      }
      if (!guess.empty()) {
        message += " (did you mean '" + join(path, guess) + "'?)";
      } else {
        // A key of another table, as "nx" at the top level: name the table it belongs in.
        for (const auto& [table, keys] : schema())
          if (table != schema_path(path) && !table.empty() &&
              std::find(keys.begin(), keys.end(), key) != keys.end()) {
            const bool array = table == "clamp" || table == "traction" || table == "point_load";
            message += " (did you mean '" + table + "." + key + "'? it belongs in the " +
                       (array ? "[[" + table + "]]" : "[" + table + "]") + " section)";
            break;
          }
      }
      if (overridden_.contains(join(path, key))) message += ", given by --set";
      fail_at(k.source(), message);
    }
  }

  [[noreturn]] void wrong_type(const std::string& key, const std::string& expected,
                               const toml::node& n) const {
    fail_at(n.source(), "key '" + key + "' must be " + expected + ", got " + type_name(n));
  }

  [[noreturn]] void missing(const std::string& key, const std::string& what) const {
    fail("missing required key '" + key + "' (" + what + ")");
  }

  [[noreturn]] void out_of_range(const std::string& key, const std::string& value,
                                 const std::string& expected) const {
    fail("key '" + key + "' = " + value + ": expected " + expected);
  }

  std::optional<double> number(const toml::table& t, const std::string& path,
                               std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    // TOML keeps 1 and 1.0 apart; where a float is expected, "E = 210000" is meant as a number.
    if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
    if (const auto* f = n->as_floating_point()) return f->get();
    wrong_type(join(path, key), "a number", *n);
  }

  std::optional<std::int64_t> integer(const toml::table& t, const std::string& path,
                                      std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* i = n->as_integer()) return i->get();
    wrong_type(join(path, key), "an integer", *n);
  }

  // An integer option stored as int in the library structs.
  std::optional<int> small_integer(const toml::table& t, const std::string& path,
                                   std::string_view key) const {
    const auto v = integer(t, path, key);
    if (!v) return std::nullopt;
    if (*v < std::numeric_limits<int>::min() || *v > std::numeric_limits<int>::max())
      out_of_range(join(path, key), std::to_string(*v), "an integer that fits in 32 bits");
    return static_cast<int>(*v);
  }

  std::optional<bool> boolean(const toml::table& t, const std::string& path,
                              std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* b = n->as_boolean()) return b->get();
    wrong_type(join(path, key), "true or false", *n);
  }

  std::optional<std::string> string(const toml::table& t, const std::string& path,
                                    std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    if (const auto* s = n->as_string()) return s->get();
    wrong_type(join(path, key), "a string", *n);
  }

  std::optional<std::string> expression(const toml::table& t, const std::string& path,
                                        std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    auto text = expression_text(*n);
    if (!text) wrong_type(join(path, key), "an expression (a string or a number)", *n);
    return text;
  }

  std::optional<std::vector<std::string>> expressions(const toml::table& t, const std::string& path,
                                                      std::string_view key,
                                                      std::size_t count) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return std::nullopt;
    const std::string full = join(path, key);
    const auto* a = n->as_array();
    const std::string expected =
        "an array of " + std::to_string(count) + " expressions (strings or numbers)";
    if (a == nullptr) wrong_type(full, expected, *n);
    if (a->size() != count)
      fail("key '" + full + "' must have " + std::to_string(count) + " entries (x and y " +
           "components), got " + std::to_string(a->size()));
    std::vector<std::string> out;
    for (std::size_t i = 0; i < a->size(); ++i) {
      auto text = expression_text(*a->get(i));
      if (!text) wrong_type(element(full, i), "an expression (a string or a number)", *a->get(i));
      out.push_back(*text);
    }
    return out;
  }

  // An array of exactly `count` finite numbers ("mesh.origin", "traction[0].x_range"); `entries`
  // says what they are, for the message.
  std::vector<double> numbers(const toml::node& n, const std::string& key, std::size_t count,
                              const std::string& entries) const {
    const auto* a = n.as_array();
    if (a == nullptr) wrong_type(key, "an array of " + std::to_string(count) + " numbers", n);
    if (a->size() != count)
      fail_at(n.source(), "key '" + key + "' must have " + std::to_string(count) + " entries (" +
                              entries + "), got " + std::to_string(a->size()));
    std::vector<double> out;
    for (std::size_t i = 0; i < count; ++i) {
      const toml::node& e = *a->get(i);
      double v = 0.0;
      if (const auto* iv = e.as_integer())
        v = static_cast<double>(iv->get());
      else if (const auto* fv = e.as_floating_point())
        v = fv->get();
      else
        wrong_type(element(key, i), "a number", e);
      if (!std::isfinite(v)) out_of_range(element(key, i), toml_float(v), "a finite number");
      out.push_back(v);
    }
    return out;
  }

  const toml::table* table(const toml::table& t, const std::string& path,
                           std::string_view key) const {
    const toml::node* n = t.get(key);
    if (n == nullptr) return nullptr;
    if (const auto* tt = n->as_table()) return tt;
    wrong_type(join(path, key), "a table ([" + join(path, key) + "])", *n);
  }

  // The entries of an array of tables ([[clamp]]); empty if the key is absent.
  std::vector<const toml::table*> array_of_tables(const toml::table& t,
                                                  std::string_view key) const {
    std::vector<const toml::table*> out;
    const toml::node* n = t.get(key);
    if (n == nullptr) return out;
    const std::string expected = "an array of tables ([[" + std::string(key) + "]] sections)";
    const auto* a = n->as_array();
    if (a == nullptr) wrong_type(std::string(key), expected, *n);
    for (std::size_t i = 0; i < a->size(); ++i) {
      const auto* e = a->get(i)->as_table();
      if (e == nullptr) wrong_type(element(std::string(key), i), "a table", *a->get(i));
      out.push_back(e);
    }
    return out;
  }

  template <class Enum, std::size_t N>
  Enum enumeration(const toml::table& t, const std::string& path, std::string_view key,
                   const EnumNames<Enum, N>& names, Enum fallback) const {
    const auto text = string(t, path, key);
    if (!text) return fallback;
    if (const auto e = enum_from_string(names, *text)) return *e;
    std::vector<std::string> choices;
    for (const auto& [e, name] : names) choices.emplace_back(name);
    std::string message =
        "key '" + join(path, key) + "' must be " + enum_choices(names) + ", got '" + *text + "'";
    const std::string guess = closest_match(*text, choices);
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    fail_at(t.get(key)->source(), message);
  }

  // Calls a library validate() and names the file in its message.
  template <class Options>
  void validated(const Options& options) const {
    try {
      validate(options);
    } catch (const InputError& e) {
      fail(e.what());
    }
  }

  const std::string& file() const { return file_; }

 private:
  std::string file_;
  std::set<std::string> overridden_;
};

template <class T>
T required(const Reader& r, std::optional<T> value, const std::string& key,
           const std::string& what) {
  if (!value) r.missing(key, what);
  return *value;
}

std::string as_text(double x) {
  return toml_float(x);
}

// The expressions as written, for the effective settings (the spec keeps only callables).
struct ExpressionTexts {
  std::vector<std::vector<std::string>> tractions;
  std::vector<std::string> body_force;
  std::string gap = "0";
};

void read_mesh(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const toml::table* t = r.table(root, "", "mesh");
  if (t == nullptr) r.missing("mesh", "a [mesh] section with length, height, nx and ny");
  r.check_keys(*t, "mesh");
  const std::string type = r.string(*t, "mesh", "type").value_or("rectangle");
  if (type != "rectangle")
    r.fail("key 'mesh.type' must be \"rectangle\" (the only mesh type so far), got '" + type + "'");
  RectangleMeshOptions& m = spec.mesh;
  if (const toml::node* n = t->get("origin")) {
    const std::vector<double> xy = r.numbers(*n, "mesh.origin", 2, "x and y");
    m.x0 = xy[0];
    m.y0 = xy[1];
  } else {
    m.x0 = 0.0;
    m.y0 = 0.0;
  }
  m.length = required(r, r.number(*t, "mesh", "length"), "mesh.length", "a number > 0");
  m.height = required(r, r.number(*t, "mesh", "height"), "mesh.height", "a number > 0");
  const auto positive = [&](const char* key, double value) {
    if (!std::isfinite(value) || value <= 0.0)
      r.out_of_range(key, as_text(value), "a positive number");
  };
  positive("mesh.length", m.length);
  positive("mesh.height", m.height);
  m.nx = required(r, r.integer(*t, "mesh", "nx"), "mesh.nx", "integer >= 1");
  m.ny = required(r, r.integer(*t, "mesh", "ny"), "mesh.ny", "integer >= 1");
  if (m.nx < 1) r.out_of_range("mesh.nx", std::to_string(m.nx), "an integer >= 1");
  if (m.ny < 1) r.out_of_range("mesh.ny", std::to_string(m.ny), "an integer >= 1");
}

void read_material(const Reader& r, const toml::table& root, ProblemSpec& spec,
                   std::vector<std::string>& warnings) {
  const toml::table* t = r.table(root, "", "material");
  if (t == nullptr) r.missing("material", "a [material] section with E and nu");
  r.check_keys(*t, "material");
  IsotropicMaterial& m = spec.elasticity.material;
  m.E = required(r, r.number(*t, "material", "E"), "material.E", "Young's modulus > 0");
  m.nu = required(r, r.number(*t, "material", "nu"), "material.nu", "Poisson's ratio in (-1, 0.5)");
  spec.elasticity.plane_model =
      r.enumeration(*t, "material", "plane_model", kPlaneModelNames, PlaneModel::PlaneStrain);
  r.validated(m);
  // Valid, but bilinear elements lock as nu approaches 1/2: the displacements and the stresses
  // near the contact come out wrong by a factor that grows without bound (at nu = 0.49 the
  // stress under a contact peak overshoots the contact pressure by some 70 %), which the solver
  // cannot detect.
  if (m.nu >= 0.45)
    warnings.push_back(r.file() + ": material.nu = " + as_text(m.nu) +
                       " >= 0.45: nearly incompressible, and bilinear (Q1) elements lock: "
                       "displacements come out too small and stresses near the contact "
                       "oscillate; quadratic elements (planned) will avoid this, until then "
                       "check against a finer mesh");
}

void read_fem(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  spec.elasticity.gauss_points = 2;
  spec.boundary_gauss_points = 2;
  const toml::table* t = r.table(root, "", "fem");
  if (t == nullptr) return;
  r.check_keys(*t, "fem");
  const auto points = [&](std::string_view key, int& target) {
    if (const auto v = r.integer(*t, "fem", key)) {
      // quadrature.hpp has the Gauss-Legendre rules with 1 to 5 points.
      if (*v < 1 || *v > 5) r.out_of_range(join("fem", key), std::to_string(*v), "1 to 5");
      target = static_cast<int>(*v);
    }
  };
  points("gauss_points", spec.elasticity.gauss_points);
  points("boundary_gauss_points", spec.boundary_gauss_points);
}

void read_clamps(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "clamp");
  if (entries.empty())
    r.missing("clamp", "a [[clamp]] section with the boundary where u = 0; at least one");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("clamp", i);
    r.check_keys(t, path);
    ClampSpec c;
    c.boundary = required(r, r.string(t, path, "boundary"), join(path, "boundary"),
                          "name of a boundary part");
    if (const toml::node* n = t.get("components")) {
      const std::string key = join(path, "components");
      const auto* a = n->as_array();
      if (a == nullptr) r.wrong_type(key, "an array of component names (\"x\", \"y\")", *n);
      if (a->empty()) r.fail("key '" + key + "' must list at least one of \"x\", \"y\"");
      c.components = {false, false, false};
      for (std::size_t k = 0; k < a->size(); ++k) {
        const auto* s = a->get(k)->as_string();
        if (s == nullptr) r.wrong_type(element(key, k), "\"x\" or \"y\"", *a->get(k));
        if (s->get() == "x")
          c.components[0] = true;
        else if (s->get() == "y")
          c.components[1] = true;
        else
          r.fail("key '" + element(key, k) + "' must be \"x\" or \"y\", got '" + s->get() + "'");
      }
    }
    spec.clamps.push_back(std::move(c));
  }
}

// The assembly refuses a non-finite load or gap too, but names the boundary part only; these
// wrappers name the key, the formula and the position:
//   traction[1].p[1] = '1/(x-3)' is infinite at x = (3, 0.5)
std::string not_finite(const std::string& key, const std::string& formula, double value,
                       const Point& x) {
  return fmt::format(
      "{} = '{}' is {} at x = ({:g}, {:g}): expected finite values everywhere "
      "it is used",
      key, one_line(formula), std::isnan(value) ? "NaN" : "infinite", x(0), x(1));
}

VectorField finite_vector_field(VectorField f, const std::string& key,
                                const std::vector<std::string>& formulas) {
  return [f = std::move(f), key, formulas](const Point& x) {
    const Eigen::Vector3d v = f(x);
    for (std::size_t i = 0; i < formulas.size(); ++i) {
      const double value = v(static_cast<Eigen::Index>(i));
      if (!std::isfinite(value))
        throw InputError(not_finite(element(key, i), formulas[i], value, x));
    }
    return v;
  };
}

ScalarField finite_scalar_field(ScalarField f, const std::string& key, const std::string& formula) {
  return [f = std::move(f), key, formula](const Point& x) {
    const double value = f(x);
    if (!std::isfinite(value)) throw InputError(not_finite(key, formula, value, x));
    return value;
  };
}

// "(0, -2/3*(3 - x))": how a field was given, for reports.
std::string describe(const std::vector<std::string>& exprs) {
  std::string out = "(";
  for (std::size_t i = 0; i < exprs.size(); ++i) out += (i > 0 ? ", " : "") + exprs[i];
  return out + ")";
}

// Expression errors name the key; the file is added here.
template <class Make>
auto with_file(const Reader& r, Make make) {
  try {
    return make();
  } catch (const InputError& e) {
    r.fail(e.what());
  }
}

// A formula with a comparison or a ternary switches value between Gauss points, which sample
// it: a load on part of an edge comes out wrong by up to a whole facet's share.
bool looks_discontinuous(const std::string& formula) {
  return formula.find('?') != std::string::npos || formula.find('<') != std::string::npos ||
         formula.find('>') != std::string::npos;
}

// x_range = [a, b]: the traction acts where a <= x <= b (exactly integrated, load_assembly.hpp).
void read_range(const Reader& r, const toml::table& t, const std::string& path,
                std::string_view key, int axis, CoordinateBox& box) {
  const toml::node* n = t.get(key);
  if (n == nullptr) return;
  const std::string full = join(path, key);
  const std::vector<double> v = r.numbers(*n, full, 2, "lower and upper");
  if (!(v[0] < v[1]))
    r.fail_at(n->source(), "key '" + full + "' = [" + as_text(v[0]) + ", " + as_text(v[1]) +
                               "]: expected [lower, upper] with lower < upper");
  box.lower[static_cast<std::size_t>(axis)] = v[0];
  box.upper[static_cast<std::size_t>(axis)] = v[1];
}

void read_tractions(const Reader& r, const toml::table& root, ProblemSpec& spec,
                    ExpressionTexts& texts, std::vector<std::string>& warnings) {
  const auto entries = r.array_of_tables(root, "traction");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("traction", i);
    r.check_keys(t, path);
    TractionSpec tr;
    tr.boundary = required(r, r.string(t, path, "boundary"), join(path, "boundary"),
                           "name of a boundary part");
    const auto p = required(r, r.expressions(t, path, "p", 2), join(path, "p"),
                            "2 expressions of x, y: the traction (force per area)");
    tr.p = finite_vector_field(with_file(r, [&] { return make_vector_field(p, join(path, "p")); }),
                               join(path, "p"), p);
    tr.description = describe(p);
    read_range(r, t, path, "x_range", 0, tr.region);
    read_range(r, t, path, "y_range", 1, tr.region);
    for (std::size_t k = 0; k < p.size(); ++k)
      if (looks_discontinuous(p[k]))
        warnings.push_back(r.file() + ": " + element(join(path, "p"), k) + " = '" + one_line(p[k]) +
                           "' switches value inside the boundary: Gauss quadrature samples it, "
                           "so the load can be lost or overcounted; for a load on part of a "
                           "boundary give x_range/y_range instead (integrated exactly), and "
                           "check the applied load in the summary");
    texts.tractions.push_back(p);
    spec.tractions.push_back(std::move(tr));
  }
}

// [[point_load]] at = [x, y], force = [fx, fy], boundary (optional): a force at the nearest node.
void read_point_loads(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "point_load");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("point_load", i);
    r.check_keys(t, path);
    PointLoadSpec pl;
    const auto pair = [&](std::string_view key, const char* what) {
      const std::string full = join(path, key);
      const toml::node* n = t.get(key);
      if (n == nullptr) r.missing(full, what);
      const std::vector<double> xy = r.numbers(*n, full, 2, "x and y");
      return Eigen::Vector3d(xy[0], xy[1], 0.0);
    };
    pl.at = pair("at", "[x, y]: the point; the load acts at the nearest node");
    pl.force = pair("force", "[fx, fy]: the force (per unit thickness in 2D)");
    pl.boundary = r.string(t, path, "boundary").value_or("");
    spec.point_loads.push_back(std::move(pl));
  }
}

void read_body_force(const Reader& r, const toml::table& root, ProblemSpec& spec,
                     ExpressionTexts& texts) {
  const toml::table* t = r.table(root, "", "body_force");
  if (t == nullptr) return;
  r.check_keys(*t, "body_force");
  const auto f = required(r, r.expressions(*t, "body_force", "f", 2), "body_force.f",
                          "2 expressions of x, y: the force per volume");
  spec.body_force = finite_vector_field(
      with_file(r, [&] { return make_vector_field(f, "body_force.f"); }), "body_force.f", f);
  spec.body_force_description = describe(f);
  texts.body_force = f;
}

void read_contact(const Reader& r, const toml::table& root, ProblemSpec& spec,
                  ExpressionTexts& texts) {
  const toml::table* t = r.table(root, "", "contact");
  if (t == nullptr) r.missing("contact", "a [contact] section with the contact boundary");
  r.check_keys(*t, "contact");
  spec.contact.boundary = required(r, r.string(*t, "contact", "boundary"), "contact.boundary",
                                   "name of a boundary part");
  texts.gap = r.expression(*t, "contact", "gap").value_or("0");
  spec.contact.gap =
      finite_scalar_field(with_file(r, [&] { return make_scalar_field(texts.gap, "contact.gap"); }),
                          "contact.gap", texts.gap);
  spec.contact.description = texts.gap;
}

void read_solver(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  ContactSolverOptions& o = spec.solver;
  o = ContactSolverOptions{};
  if (const toml::table* t = r.table(root, "", "solver")) {
    r.check_keys(*t, "solver");
    o.method = r.enumeration(*t, "solver", "method", kContactMethodNames, o.method);
    const auto real = [&](std::string_view key, double& target) {
      if (const auto v = r.number(*t, "solver", key)) target = *v;
    };
    const auto whole = [&](std::string_view key, int& target) {
      if (const auto v = r.small_integer(*t, "solver", key)) target = *v;
    };
    // r: a number, or "auto" (the default: chosen from the problem, method.md section 7).
    if (const toml::node* n = t->get("r"); n != nullptr && n->is_string()) {
      if (n->as_string()->get() != "auto")
        r.fail_at(n->source(), "key 'solver.r' must be a positive number or \"auto\", got '" +
                                   n->as_string()->get() + "'");
    } else if (const auto v = r.number(*t, "solver", "r")) {
      o.r = *v;
    }
    real("auto_r_factor", o.auto_r_factor);
    real("kkt_tolerance", o.kkt_tolerance);
    real("uzawa_tolerance", o.uzawa_tolerance);
    whole("max_uzawa_iterations", o.max_uzawa_iterations);
    real("gnm_tolerance", o.gnm_tolerance);
    whole("max_gnm_iterations", o.max_gnm_iterations);
    real("armijo_sigma", o.armijo_sigma);
    whole("max_armijo_halvings", o.max_armijo_halvings);
    real("classical_step", o.classical_step);
    whole("max_classical_iterations", o.max_classical_iterations);
    whole("max_newton_iterations", o.max_newton_iterations);
    if (const auto v = r.boolean(*t, "solver", "schur_complement")) o.schur_complement = *v;
    o.device = r.enumeration(*t, "solver", "device", kDeviceKindNames, o.device);
    if (const toml::table* lt = r.table(*t, "solver", "linear")) {
      r.check_keys(*lt, "solver.linear");
      LinearSolverOptions& l = o.linear;
      l.type = r.enumeration(*lt, "solver.linear", "type", kLinearSolverTypeNames, l.type);
      if (const auto v = r.number(*lt, "solver.linear", "cg_tolerance")) l.cg_tolerance = *v;
      if (const auto v = r.small_integer(*lt, "solver.linear", "cg_max_iterations"))
        l.cg_max_iterations = *v;
      l.preconditioner = r.enumeration(*lt, "solver.linear", "preconditioner",
                                       kPreconditionerTypeNames, l.preconditioner);
      l.coarsening = r.enumeration(*lt, "solver.linear", "coarsening", kMultigridCoarseningNames,
                                   l.coarsening);
      if (const auto v = r.small_integer(*lt, "solver.linear", "chebyshev_degree"))
        l.chebyshev_degree = *v;
    }
  }
  r.validated(o);
}

// A mesh that cannot fit is refused now rather than after minutes of assembly, or by the
// out-of-memory killer.
void check_memory(const Reader& r, const ProblemSpec& spec) {
  const double nodes =
      (static_cast<double>(spec.mesh.nx) + 1.0) * (static_cast<double>(spec.mesh.ny) + 1.0);
  const double need = estimated_memory_bytes(nodes, spec.solver.linear.type);
  const double have = physical_memory_bytes();
  if (have > 0.0 && need > have)
    r.fail(fmt::format(
        "mesh {}x{} has {:.3g} nodes and needs about {:.3g} GB of memory with the {} solver, "
        "more than this machine's {:.3g} GB: use a smaller mesh.nx, mesh.ny",
        spec.mesh.nx, spec.mesh.ny, nodes, need / 1e9,
        enum_to_string(kLinearSolverTypeNames, spec.solver.linear.type), have / 1e9));
}

std::string effective_toml(const ProblemSpec& spec, const ExpressionTexts& texts) {
  TomlEmitter out;
  out.value("name", spec.name);
  if (!spec.units.empty()) out.value("units", spec.units);
  out.table("mesh");
  out.value("type", "rectangle");
  out.value("origin", std::vector<double>{spec.mesh.x0, spec.mesh.y0});
  out.value("length", spec.mesh.length);
  out.value("height", spec.mesh.height);
  out.value("nx", std::int64_t{spec.mesh.nx});
  out.value("ny", std::int64_t{spec.mesh.ny});
  out.table("material");
  out.value("E", spec.elasticity.material.E);
  out.value("nu", spec.elasticity.material.nu);
  out.value("plane_model", enum_to_string(kPlaneModelNames, spec.elasticity.plane_model));
  out.table("fem");
  out.value("gauss_points", spec.elasticity.gauss_points);
  out.value("boundary_gauss_points", spec.boundary_gauss_points);
  for (const ClampSpec& c : spec.clamps) {
    out.array_table("clamp");
    out.value("boundary", c.boundary);
    std::vector<std::string> components;
    if (c.components[0]) components.emplace_back("x");
    if (c.components[1]) components.emplace_back("y");
    out.value("components", components);
  }
  for (std::size_t i = 0; i < spec.tractions.size(); ++i) {
    out.array_table("traction");
    out.value("boundary", spec.tractions[i].boundary);
    out.value("p", texts.tractions[i]);
    const CoordinateBox& box = spec.tractions[i].region;
    if (std::isfinite(box.lower[0]))
      out.value("x_range", std::vector<double>{box.lower[0], box.upper[0]});
    if (std::isfinite(box.lower[1]))
      out.value("y_range", std::vector<double>{box.lower[1], box.upper[1]});
  }
  for (const PointLoadSpec& pl : spec.point_loads) {
    out.array_table("point_load");
    out.value("at", std::vector<double>{pl.at(0), pl.at(1)});
    out.value("force", std::vector<double>{pl.force(0), pl.force(1)});
    if (!pl.boundary.empty()) out.value("boundary", pl.boundary);
  }
  if (!texts.body_force.empty()) {
    out.table("body_force");
    out.value("f", texts.body_force);
  }
  out.table("contact");
  out.value("boundary", spec.contact.boundary);
  out.value("gap", texts.gap);
  const ContactSolverOptions& o = spec.solver;
  out.table("solver");
  out.value("method", enum_to_string(kContactMethodNames, o.method));
  if (o.r)
    out.value("r", *o.r);
  else
    out.value("r", "auto");
  out.value("auto_r_factor", o.auto_r_factor);
  out.value("kkt_tolerance", o.kkt_tolerance);
  out.value("uzawa_tolerance", o.uzawa_tolerance);
  out.value("max_uzawa_iterations", o.max_uzawa_iterations);
  out.value("gnm_tolerance", o.gnm_tolerance);
  out.value("max_gnm_iterations", o.max_gnm_iterations);
  out.value("armijo_sigma", o.armijo_sigma);
  out.value("max_armijo_halvings", o.max_armijo_halvings);
  out.value("classical_step", o.classical_step);
  out.value("max_classical_iterations", o.max_classical_iterations);
  out.value("max_newton_iterations", o.max_newton_iterations);
  out.value("schur_complement", o.schur_complement);
  out.value("device", enum_to_string(kDeviceKindNames, o.device));
  out.table("solver.linear");
  out.value("type", enum_to_string(kLinearSolverTypeNames, o.linear.type));
  out.value("cg_tolerance", o.linear.cg_tolerance);
  out.value("cg_max_iterations", o.linear.cg_max_iterations);
  out.value("preconditioner", enum_to_string(kPreconditionerTypeNames, o.linear.preconditioner));
  out.value("coarsening", enum_to_string(kMultigridCoarseningNames, o.linear.coarsening));
  out.value("chebyshev_degree", o.linear.chebyshev_degree);
  return out.text();
}

// --set overrides --------------------------------------------------------------------------

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto pos = s.find(sep, start);
    parts.push_back(s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
    if (pos == std::string::npos) break;
    start = pos + 1;
  }
  return parts;
}

std::optional<std::size_t> array_index(const std::string& s) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), digit)) return std::nullopt;
  return static_cast<std::size_t>(std::stoul(s));
}

// Applies "dotted.key=value" to the parsed file; returns the key as check_keys() names it
// ("clamp[0].boundary").
std::string apply_override(const Reader& r, toml::table& root, const std::string& text) {
  const auto eq = text.find('=');
  const std::string key = eq == std::string::npos ? std::string() : trim(text.substr(0, eq));
  if (key.empty()) r.fail("--set '" + text + "': expected key=value, e.g. --set mesh.nx=480");
  const std::string value = trim(text.substr(eq + 1));
  const std::vector<std::string> segments = split(key, '.');
  if (std::any_of(segments.begin(), segments.end(), [](const auto& s) { return trim(s).empty(); }))
    r.fail("--set '" + text + "': empty part in key '" + key + "'");

  toml::table* table = &root;
  std::string path;
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const std::string& seg = segments[i];
    path = join(path, seg);
    toml::node* next = table->get(seg);
    if (next == nullptr) next = &table->insert_or_assign(seg, toml::table{}).first->second;
    if (auto* t = next->as_table()) {
      table = t;
    } else if (auto* a = next->as_array()) {
      // clamp.0.boundary: the entry of an array of tables.
      const auto index = i + 2 < segments.size() ? array_index(segments[i + 1]) : std::nullopt;
      if (!index)
        r.fail("--set '" + text + "': '" + path + "' is an array: name an entry, as " + path +
               ".0." + segments.back());
      if (*index >= a->size() || !a->get(*index)->is_table())
        r.fail("--set '" + text + "': '" + path + "' has no table entry " + std::to_string(*index));
      table = a->get(*index)->as_table();
      path = element(path, *index);
      ++i;
    } else {
      const std::string type = type_name(*next);
      const char* article = type.find_first_of("aeiou") == 0 ? "an " : "a ";
      r.fail("--set '" + text + "': '" + path + "' is " + article + type + ", not a table");
    }
  }

  // The value is TOML if it parses as one ("480", "1e8", "[0, 1]", "\"x\""); a bare word such as
  // semismooth_newton or an expression such as 0.5*x is not, and is taken as the string it reads.
  std::optional<toml::table> parsed;
  try {
    parsed = toml::parse("v = " + value, std::string("--set"));
  } catch (const toml::parse_error&) {
  }
  const std::string& last = segments.back();
  if (parsed && parsed->size() == 1 && parsed->get("v") != nullptr) {
    parsed->get("v")->visit([&](auto& node) { table->insert_or_assign(last, std::move(node)); });
  } else {
    table->insert_or_assign(last, value);
  }
  return join(path, last);
}

}  // namespace

double estimated_memory_bytes(double num_nodes, LinearSolverType solver) {
  switch (solver) {
    case LinearSolverType::Cholmod:
      return 4096.0 * num_nodes;
    case LinearSolverType::ConjugateGradient:
      return 2048.0 * num_nodes;
    case LinearSolverType::Dense: {
      const double n = 2.0 * num_nodes;  // 2D: two unknowns per node
      return 2048.0 * num_nodes + 8.0 * n * n;
    }
  }
  return 4096.0 * num_nodes;
}

double physical_memory_bytes() {
  const long pages = ::sysconf(_SC_PHYS_PAGES);
  const long page_size = ::sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || page_size <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(page_size);
}

namespace {

// The dotted name of the table that line `number` (1-based) of `lines` is in ("traction[1]",
// "solver.linear", ""), from the headers above it.
std::string table_at(const std::vector<std::string>& lines, std::size_t number) {
  std::string table;
  std::map<std::string, int> entries;
  for (std::size_t n = 1; n < number && n <= lines.size(); ++n) {
    const std::string line = trim(lines[n - 1]);
    if (line.rfind("[[", 0) == 0 && line.find("]]") != std::string::npos) {
      const std::string name = trim(line.substr(2, line.find("]]") - 2));
      table = name + "[" + std::to_string(entries[name]++) + "]";
    } else if (line.rfind('[', 0) == 0 && line.find(']') != std::string::npos) {
      table = trim(line.substr(1, line.find(']') - 1));
    }
  }
  return table;
}

// The value part of "key = value # comment", without the comment (outside quotes).
std::string value_text(const std::string& after_equals) {
  bool quoted = false;
  for (std::size_t i = 0; i < after_equals.size(); ++i) {
    if (after_equals[i] == '"') quoted = !quoted;
    if (after_equals[i] == '#' && !quoted) return trim(after_equals.substr(0, i));
  }
  return trim(after_equals);
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  (void)std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// The entries of "[a, b(c, d), e]" split at the commas outside parentheses.
std::vector<std::string> array_entries(const std::string& array) {
  std::vector<std::string> out;
  std::string current;
  int depth = 0;
  for (std::size_t i = 1; i + 1 < array.size(); ++i) {
    const char c = array[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(trim(current));
      current.clear();
    } else {
      current += c;
    }
  }
  out.push_back(trim(current));
  return out;
}

// The usual mistakes behind a TOML syntax error, said in the problem file's terms: a number
// with a unit ("E = 210000 MPa") and a formula without quotes ("gap = 0.1*x", "p = [0, -x]").
// Empty when the line is none of these.
std::string explain_syntax_error(const std::string& text, std::size_t number) {
  const std::vector<std::string> lines = split(text, '\n');
  if (number < 1 || number > lines.size()) return {};
  const std::string line = lines[number - 1];
  const auto eq = line.find('=');
  if (eq == std::string::npos) return {};
  const std::string key = trim(line.substr(0, eq));
  const std::string value = value_text(line.substr(eq + 1));
  if (key.empty() || value.empty() || value[0] == '"' || value[0] == '\'') return {};
  // Only plain ASCII text is guessed at; anything else keeps the parser's own message.
  for (const char c : line)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
      if (c != '\t' && c != '\r') return {};
  const std::string table = table_at(lines, number);
  const std::string full = table.empty() ? key : table + "." + key;
  // A number and a word after it: a unit.
  const auto space = value.find_first_of(" \t");
  if (space != std::string::npos && is_number(value.substr(0, space))) {
    const std::string number_part = value.substr(0, space);
    return fmt::format(
        "key '{}' = {}: a number cannot carry a unit; write {} = {} (the numbers of a problem "
        "are in one consistent set of units, which the top-level key units = \"m-MPa\" (or "
        "\"mm-N\", \"m-Pa\", ...) names for the labels)",
        full, value, key, number_part);
  }
  if (value[0] == '[' && value.back() == ']') {
    std::string quoted;
    bool any = false;
    for (const std::string& e : array_entries(value)) {
      const bool plain = e.empty() || e[0] == '"' || is_number(e);
      any = any || !plain;
      quoted += (quoted.empty() ? "" : ", ") + (plain ? e : "\"" + e + "\"");
    }
    if (any)
      return fmt::format("key '{}' = {}: formulas in an array must be quoted strings, as {} = [{}]",
                         full, value, key, quoted);
    return {};
  }
  // A formula: the characters of one, and a letter or an operator among them.
  const bool formula_characters =
      value.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_ "
          ".+-*/^()<>?:!&|,") == std::string::npos &&
      value.find_first_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ*/^(") !=
          std::string::npos;
  if (formula_characters && !is_number(value) && value != "true" && value != "false")
    return fmt::format("key '{}' = {}: a formula or a name must be a quoted string, as {} = \"{}\"",
                       full, value, key, value);
  return {};
}

}  // namespace

LoadedProblem parse_problem_string(const std::string& toml_text, const std::string& name_for_errors,
                                   const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, name_for_errors);
  } catch (const toml::parse_error& e) {
    const std::string explained = explain_syntax_error(toml_text, e.source().begin.line);
    if (!explained.empty())
      throw InputError(
          fmt::format("{}:{}: {}", name_for_errors, e.source().begin.line, one_line(explained)));
    throw InputError(fmt::format("{}:{}:{}: TOML syntax error: {}", name_for_errors,
                                 e.source().begin.line, e.source().begin.column,
                                 one_line(std::string(e.description()))));
  }

  std::set<std::string> overridden;
  {
    const Reader pre(name_for_errors, {});
    for (const std::string& o : overrides) overridden.insert(apply_override(pre, root, o));
  }
  const Reader r(name_for_errors, std::move(overridden));
  r.check_keys(root, "");

  LoadedProblem out;
  out.path = name_for_errors;
  ProblemSpec& spec = out.spec;
  spec.name =
      r.string(root, "", "name").value_or(std::filesystem::path(name_for_errors).stem().string());
  spec.units = r.string(root, "", "units").value_or("");
  if (!spec.units.empty() && !is_unit_system(spec.units)) {
    std::string message = "key 'units' = '" + spec.units + "': expected one of " +
                          unit_system_choices() + " (labels only; or leave it out)";
    const std::string guess = closest_match(spec.units, unit_system_names());
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    r.fail_at(root.get("units")->source(), message);
  }
  ExpressionTexts texts;
  read_mesh(r, root, spec);
  read_material(r, root, spec, out.warnings);
  read_fem(r, root, spec);
  read_clamps(r, root, spec);
  read_tractions(r, root, spec, texts, out.warnings);
  read_point_loads(r, root, spec);
  read_body_force(r, root, spec, texts);
  read_contact(r, root, spec, texts);
  read_solver(r, root, spec);
  check_memory(r, spec);
  out.effective_toml = effective_toml(spec, texts);
  return out;
}

LoadedProblem read_problem_file(const std::string& path,
                                const std::vector<std::string>& overrides) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("cannot read '" + path + "': is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  return parse_problem_string(text.str(), path, overrides);
}

}  // namespace signorini

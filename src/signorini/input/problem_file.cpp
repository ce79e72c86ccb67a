#include "signorini/input/problem_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/core/error.hpp"
#include "signorini/core/peak_memory.hpp"
#include "signorini/input/effective_settings.hpp"
#include "signorini/input/expression.hpp"
#include "signorini/input/overrides.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/input/problem_table.hpp"
#include "signorini/input/suggestion.hpp"
#include "signorini/input/syntax_explanations.hpp"
#include "signorini/input/toml_reader.hpp"
#include "signorini/interface/obstacle_parameters.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"
#include "signorini/problem/unit_system.hpp"

// The section readers of a problem file. The sections of options ([mesh], [material], [fem],
// [solver], [solver.linear]) are read through their option tables (input/problem_schema.hpp): type,
// range and missing-key errors come from there. The sections of formulas and lists ([[clamp]],
// [[traction]], [[point_load]], [body_force], [contact]) have readers of their own here, their
// keys declared in the same tables for the unknown-key check and the docs.

namespace signorini {

namespace {

template <class T>
T required(const Reader& r, std::optional<T> value, const std::string& key,
           const std::string& what) {
  if (!value) r.missing(key, what);
  return *value;
}

// The required `boundary` of a section at `path` ("clamp[0]", "contact").
std::string boundary_of(const Reader& r, const toml::table& t, const std::string& path) {
  return required(r, r.string(t, path, "boundary"), join(path, "boundary"),
                  "name of a boundary part");
}

// What the file says the problem's dimension is. A rectangle is 2D and a box 3D, and every key
// must agree, checked here with the line. A Gmsh mesh's dimension is known only when
// build_model reads it, so there the first key that implies one decides
// (ProblemSpec::implied_dimension), later keys must agree with it, and build_model checks it
// against the mesh: reading the mesh here too would cost a second read of a large file, or a
// second run of gmsh on a .geo.
class Dimension {
 public:
  Dimension(const Reader& r, ProblemSpec& spec) : r_(r), spec_(spec) {}

  /// 2 for a rectangle, 3 for a box: how many components a point or vector must have; 0 for a
  /// Gmsh mesh, which takes 2 or 3, and imply() checks that the keys agree, naming the first.
  [[nodiscard]] int known() const {
    return spec_.mesh_type == MeshType::Gmsh ? 0 : stated_dimension(spec_);
  }
  /// The dimension as far as the file says it so far (a Gmsh mesh's: what its keys implied).
  [[nodiscard]] int stated() const { return stated_dimension(spec_); }

  /// `key`, at `n`, gives `given`, which only problems of `dim` dimensions take; a problem of
  /// the other dimension expects `instead` there.
  void imply(const toml::node& n, const std::string& key, int dim, const std::string& given,
             const std::string& instead) const {
    const std::string says =
        "key '" + key + "' gives " + given + " (" + std::to_string(dim) + "D problems only)";
    if (spec_.mesh_type != MeshType::Gmsh) {
      if (dim != known())
        r_.fail_at(
            n.source(),
            says + ", but the mesh is " + std::to_string(known()) + "D (" +
                (spec_.mesh_type == MeshType::Given
                     ? std::string("the given mesh")
                     : "mesh.type = \"" +
                           std::string(enum_to_string(kMeshTypeNames, spec_.mesh_type)) + "\"") +
                "): expected " + instead);
      return;
    }
    ImpliedDimension& first = spec_.implied_dimension;
    if (first.dimension == 0) {
      first = {dim, key, given, instead};
      return;
    }
    if (first.dimension != dim)
      r_.fail_at(n.source(), says + ", but " + first.key + " gives " + first.given + " (" +
                                 std::to_string(first.dimension) + "D problems only): expected " +
                                 instead);
  }

  /// The point or vector of `key` at `n`, given as `count` components: 2 or 3 of them imply
  /// that dimension.
  void imply_components(const toml::node& n, const std::string& key, std::size_t count) const {
    imply(n, key, static_cast<int>(count), std::to_string(count) + " components",
          count == 3 ? "2 components (x, y)" : "3 components (x, y, z)");
  }

  /// "x and y", "x, y and z", or both possibilities: the names of a point's entries.
  [[nodiscard]] std::string entries() const {
    const int d = known();
    return d == 2 ? "x and y" : d == 3 ? "x, y and z" : "x, y and, in 3D, z";
  }

 private:
  const Reader& r_;
  ProblemSpec& spec_;
};

// The required point or vector `key` of the section at `path` ([x, y] or [x, y, z], as the
// problem's dimension says); `what` says what it is, for the message when it is missing. z is 0
// in 2D.
Eigen::Vector3d required_point(const Reader& r, const Dimension& dim, const toml::table& t,
                               const std::string& path, std::string_view key, const char* what) {
  const std::string full = join(path, key);
  const toml::node* n = t.get(key);
  if (n == nullptr) r.missing(full, what);
  const std::vector<double> v =
      r.numbers(*n, full, static_cast<std::size_t>(dim.known()), dim.entries());
  dim.imply_components(*n, full, v.size());
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < v.size(); ++k) out(static_cast<Eigen::Index>(k)) = v[k];
  return out;
}

// The expressions of the vector field `key` (a traction, a body force), one per component of
// the problem's dimension.
std::optional<std::vector<std::string>> vector_expressions(const Reader& r, const Dimension& dim,
                                                           const toml::table& t,
                                                           const std::string& path,
                                                           std::string_view key) {
  auto e = r.expressions(t, path, key, static_cast<std::size_t>(dim.known()));
  if (e) dim.imply_components(*t.get(key), join(path, key), e->size());
  return e;
}

std::string as_text(double x) {
  return toml_float(x);
}

void read_top_level(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  spec.name = std::filesystem::path(r.file()).stem().string();  // unless the file names it
  read_options(r, root, top_level_options(), spec);
  spec.units = r.string(root, "", "units").value_or("");
  if (!spec.units.empty() && !is_unit_system(spec.units)) {
    std::string message = "key 'units' = '" + spec.units + "': expected one of " +
                          unit_system_choices() + " (labels only; or leave it out)";
    const std::string guess = closest_match(spec.units, unit_system_names());
    if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
    r.fail_at(root.get("units")->source(), message);
  }
}

void read_mesh(const Reader& r, const toml::table& root, ProblemSpec& spec,
               std::shared_ptr<const Mesh> given) {
  if (given) {
    // The program gives the mesh (arrays, mesh/mesh_arrays.hpp): a [mesh] section would be a
    // second one, and one of them would be silently ignored.
    if (const toml::node* n = root.get("mesh"); n != nullptr)
      r.fail_at(n->source(),
                "section [mesh]: the mesh is given by the program (a Mesh argument); leave "
                "[mesh] out");
    spec.mesh_type = MeshType::Given;
    spec.given_mesh = std::move(given);
    return;
  }
  const toml::table* t = r.table(root, "", "mesh");
  if (t == nullptr)
    r.missing("mesh",
              "a [mesh] section: type = \"rectangle\" with length, height, nx and ny, "
              "type = \"box\" with length, width, height, nx, ny and nz, or type = \"gmsh\" "
              "with file");
  r.check_keys(*t, "mesh");
  read_options(r, *t, mesh_options(), spec);
  check_options(r, t, mesh_options(), spec);
  // mesh.cell takes the names of both structured meshes; each takes its own.
  if (is_structured(spec.mesh_type) && !cell_fits_mesh(spec)) {
    const bool box = spec.mesh_type == MeshType::Box;
    const toml::node* cell = t->get("cell");
    r.fail_at(
        cell != nullptr ? cell->source() : t->get("type")->source(),
        "key 'mesh.cell' = \"" +
            std::string(enum_to_string(kCellTypeNames, box ? spec.box.cell : spec.mesh.cell)) +
            "\" is a " + (box ? "2D" : "3D") + " cell: with type = \"" +
            (box ? "box" : "rectangle") + "\" expected " +
            (box ? enum_choices(kBoxCellNames) : enum_choices(kRectangleCellNames)));
  }
  // Which keys a type needs (those it has no use for were refused by check_options).
  if (is_structured(spec.mesh_type)) {
    const bool box = spec.mesh_type == MeshType::Box;
    const std::vector<const char*> keys =
        box ? std::vector<const char*>{"length", "width", "height", "nx", "ny", "nz"}
            : std::vector<const char*>{"length", "height", "nx", "ny"};
    for (const char* key : keys)
      if (!t->contains(key))
        r.missing(std::string("mesh.") + key, type_words(*mesh_options().find(key)));
    return;
  }
  if (spec.mesh_file.empty()) r.missing("mesh.file", "the path of a .msh or .geo file");
  // Relative to the problem file's folder, so that a problem and its mesh move together.
  const std::filesystem::path file(spec.mesh_file);
  if (file.is_relative()) {
    const std::filesystem::path folder = std::filesystem::path(r.file()).parent_path();
    spec.mesh_file = (folder / file).lexically_normal().string();
  }
}

// The cell type of the mesh, for the warning about locking: a structured mesh's, a given mesh's
// first linear type (or its first type). (A Gmsh mesh's cells are known only when it is read.)
CellType structured_cell(const ProblemSpec& spec) {
  if (spec.mesh_type == MeshType::Given && spec.given_mesh) {
    const std::vector<CellType> types = spec.given_mesh->cell_types();
    for (const CellType t : types)
      if (cell_order(t) == 1) return t;
    return types.front();
  }
  return spec.mesh_type == MeshType::Box ? spec.box.cell : spec.mesh.cell;
}

void read_material(const Reader& r, const Dimension& dim, const toml::table& root,
                   ProblemSpec& spec, std::vector<std::string>& warnings) {
  const toml::table* t = r.table(root, "", "material");
  if (t == nullptr) r.missing("material", "a [material] section with E and nu");
  r.check_keys(*t, "material");
  read_options(r, *t, material_options(), spec);
  // A plane model makes a Gmsh problem 2D, like any 2D key: build_model checks that against the
  // mesh, and the table's condition (a 2D problem) then holds. A box refuses it by that
  // condition, below.
  if (spec.mesh_type == MeshType::Gmsh && t->contains("plane_model"))
    dim.imply(*t->get("plane_model"), "material.plane_model", 2, "a plane model",
              "no plane_model (a 3D body has none)");
  // The library's own check of a material first: its words ("expected a positive modulus") are
  // the ones the tool has always printed. The table's ranges, which the docs state, hold too.
  const IsotropicMaterial& m = spec.elasticity.material;
  r.validated(m);
  check_options(r, t, material_options(), spec);
  // Valid, but linear elements lock as nu approaches 1/2: the displacements and the stresses
  // near the contact come out wrong by a factor that grows without bound (at nu = 0.49 the
  // stress under a contact peak overshoots the contact pressure by some 70 %), which the solver
  // cannot detect. Quadratic elements lock far less (the mesh is read before the material).
  // (A Gmsh mesh's cells are known once it is read: problem/model.hpp, mesh_warnings.)
  if (m.nu >= 0.45 && spec.mesh_type != MeshType::Gmsh && cell_order(structured_cell(spec)) == 1)
    warnings.push_back(
        r.file() + ": material.nu = " + as_text(m.nu) +
        " >= 0.45: nearly incompressible, and linear elements (" +
        std::string(enum_to_string(kCellTypeNames, structured_cell(spec))) +
        ") lock: displacements come out too small and stresses near the contact "
        "oscillate; use quadratic ones (mesh.cell = " +
        (spec.mesh_type == MeshType::Box ? "\"hex27\" or \"tet10\"" : "\"quad9\" or \"tri6\"") +
        ") or check against a finer mesh");
}

void read_fem(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const toml::table* t = r.table(root, "", "fem");
  if (t == nullptr) return;
  r.check_keys(*t, "fem");
  read_options(r, *t, fem_options(), spec);
  check_options(r, t, fem_options(), spec);
}

// [[region]] name, E, nu: a material for the cells of one region of the mesh.
void read_regions(const Reader& r, const toml::table& root, ProblemSpec& spec,
                  std::vector<std::string>& warnings) {
  const auto entries = r.array_of_tables(root, "region");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("region", i);
    r.check_keys(t, path);
    RegionMaterialSpec m;
    m.region = required(r, r.string(t, path, "name"), join(path, "name"), "name of a region");
    m.material.E = required(r, r.number(t, path, "E"), join(path, "E"), "a positive number");
    m.material.nu = required(r, r.number(t, path, "nu"), join(path, "nu"), "a number in (-1, 0.5)");
    try {
      validate(m.material);
    } catch (const InputError& e) {
      r.fail(path + ": " + e.what());
    }
    for (const RegionMaterialSpec& other : spec.region_materials)
      if (other.region == m.region)
        r.fail(path + ": region '" + m.region + "' has a material already");
    if (m.material.nu >= 0.45 && spec.mesh_type != MeshType::Gmsh &&
        cell_order(structured_cell(spec)) == 1)
      warnings.push_back(r.file() + ": " + path + ".nu = " + as_text(m.material.nu) +
                         " >= 0.45: nearly incompressible; linear elements lock (see material.nu)");
    spec.region_materials.push_back(std::move(m));
  }
}

void read_clamps(const Reader& r, const Dimension& dim, const toml::table& root,
                 ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "clamp");
  if (entries.empty() && !root.contains("displacement"))
    r.missing("clamp",
              "a [[clamp]] section with the boundary where u = 0, or a [[displacement]] "
              "section; at least one");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("clamp", i);
    r.check_keys(t, path);
    ClampSpec c;
    if (t.contains("at")) {  // a pinned node: the boundary, if given, says where to look
      c.at = required_point(r, dim, t, path, "at",
                            "[x, y] ([x, y, z] in 3D): the point whose nearest node is held");
      c.boundary = r.string(t, path, "boundary").value_or("");
    } else {
      c.boundary = boundary_of(r, t, path);
    }
    if (const toml::node* n = t.get("components")) {
      const std::string key = join(path, "components");
      // z in a 2D problem is refused as any other name; on a Gmsh mesh it implies 3D.
      const bool z_allowed = dim.known() != 2;
      const std::string names = z_allowed ? "\"x\", \"y\" or \"z\"" : "\"x\" or \"y\"";
      const auto* a = n->as_array();
      if (a == nullptr)
        r.wrong_type(key,
                     std::string("an array of component names (\"x\", \"y\"") +
                         (z_allowed ? ", \"z\")" : ")"),
                     *n);
      if (a->empty())
        r.fail("key '" + key + "' must list at least one of \"x\", \"y\"" +
               (z_allowed ? ", \"z\"" : ""));
      c.components = {false, false, false};
      for (std::size_t k = 0; k < a->size(); ++k) {
        const auto* s = a->get(k)->as_string();
        if (s == nullptr) r.wrong_type(element(key, k), names, *a->get(k));
        if (s->get() == "x") {
          c.components[0] = true;
        } else if (s->get() == "y") {
          c.components[1] = true;
        } else if (s->get() == "z" && z_allowed) {
          c.components[2] = true;
          dim.imply(*a->get(k), element(key, k), 3, "component z", "\"x\" and \"y\" only");
        } else {
          r.fail("key '" + element(key, k) + "' must be " + names + ", got '" + s->get() + "'");
        }
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
  // z is 0 in a 2D problem: leave it out there.
  const std::string at = x(2) == 0.0 ? fmt::format("({:g}, {:g})", x(0), x(1))
                                     : fmt::format("({:g}, {:g}, {:g})", x(0), x(1), x(2));
  return fmt::format(
      "{} = '{}' is {} at x = {}: expected finite values everywhere "
      "it is used",
      key, one_line(formula), std::isnan(value) ? "NaN" : "infinite", at);
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

// The formula `text` of `key` as a field that refuses non-finite values, naming the key, the
// formula and the point; a formula that does not parse is refused now, naming the file.
ScalarField scalar_formula(const Reader& r, const std::string& key, const std::string& text) {
  return finite_scalar_field(with_file(r, [&] { return make_scalar_field(text, key); }), key, text);
}

// A formula with a comparison or a ternary switches value between Gauss points, which sample
// it: a load on part of an edge comes out wrong by up to a whole facet's share.
bool looks_discontinuous(const std::string& formula) {
  return formula.find('?') != std::string::npos || formula.find('<') != std::string::npos ||
         formula.find('>') != std::string::npos;
}

// x_range = [a, b]: the traction acts where a <= x <= b (exactly integrated, load_assembly.hpp).
// The assembly cuts edges, not faces: a range takes a 2D problem.
void read_range(const Reader& r, const Dimension& dim, const toml::table& t,
                const std::string& path, std::string_view key, int axis, CoordinateBox& box) {
  const toml::node* n = t.get(key);
  if (n == nullptr) return;
  const std::string full = join(path, key);
  dim.imply(*n, full, 2, "a coordinate range",
            "no range (not supported on 3D boundary parts yet): make the loaded part a boundary "
            "part of its own");
  const std::vector<double> v = r.numbers(*n, full, 2, "lower and upper");
  if (!(v[0] < v[1]))
    r.fail_at(n->source(), "key '" + full + "' = [" + as_text(v[0]) + ", " + as_text(v[1]) +
                               "]: expected [lower, upper] with lower < upper");
  box.lower[static_cast<std::size_t>(axis)] = v[0];
  box.upper[static_cast<std::size_t>(axis)] = v[1];
}

// An array of load factors at `key`: finite numbers, and >= 0 where `non_negative` (the
// history's own; an entry's may be negative: a shear may reverse).
std::vector<double> factor_array(const Reader& r, const toml::node& n, const std::string& key,
                                 const std::string& expected, bool non_negative) {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->empty()) r.wrong_type(key, expected, n);
  const std::string number = non_negative ? "a number >= 0" : "a number";
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    const std::optional<double> v = e.value<double>();
    if (!v) r.wrong_type(element(key, i), number, e);
    if (!std::isfinite(*v) || (non_negative && !(*v >= 0.0)))
      r.out_of_range(element(key, i), as_text(*v), "a finite " + number.substr(2), &e);
    out.push_back(*v);
  }
  return out;
}

// `factors` of a load or displacement entry: its own load factors, one per step of [loading]
// (counted against it by check_own_factors once that is read).
std::vector<double> own_factors(const Reader& r, const toml::table& t, const std::string& path) {
  const toml::node* n = t.get("factors");
  if (n == nullptr) return {};
  return factor_array(r, *n, join(path, "factors"),
                      "a non-empty array of numbers, one load factor per step of [loading]", false);
}

void read_tractions(const Reader& r, const Dimension& dim, const toml::table& root,
                    ProblemSpec& spec, ExpressionTexts& texts, std::vector<std::string>& warnings) {
  const auto entries = r.array_of_tables(root, "traction");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("traction", i);
    r.check_keys(t, path);
    TractionSpec tr;
    tr.boundary = boundary_of(r, t, path);
    const auto p = required(r, vector_expressions(r, dim, t, path, "p"), join(path, "p"),
                            "an expression of x, y, z per component: the traction (force per "
                            "area)");
    tr.p = finite_vector_field(with_file(r, [&] { return make_vector_field(p, join(path, "p")); }),
                               join(path, "p"), p);
    tr.description = describe(p);
    read_range(r, dim, t, path, "x_range", 0, tr.region);
    read_range(r, dim, t, path, "y_range", 1, tr.region);
    tr.factors = own_factors(r, t, path);
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

// [[displacement]] boundary, x, y and/or z (numbers or formulas), or normal.
void read_displacements(const Reader& r, const Dimension& dim, const toml::table& root,
                        ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "displacement");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("displacement", i);
    r.check_keys(t, path);
    DisplacementSpec d;
    d.boundary = boundary_of(r, t, path);
    const auto field = [&](std::string_view key, std::string& text) -> ScalarField {
      const std::optional<std::string> e = r.expression(t, path, key);
      if (!e) return {};
      text = *e;
      return scalar_formula(r, join(path, key), text);
    };
    // Local axes per node (DofMap::set_frame) are 2D so far: a normal displacement takes a 2D
    // problem, component z a 3D one.
    if (const toml::node* n = t.get("normal"))
      dim.imply(*n, join(path, "normal"), 2, "a normal displacement",
                "the components x, y and z (a normal displacement is not supported in 3D yet)");
    if (const toml::node* n = t.get("z"))
      dim.imply(*n, join(path, "z"), 3, "component z", "x and y only");
    d.normal = field("normal", d.normal_text);
    d.values[0] = field("x", d.texts[0]);
    d.values[1] = field("y", d.texts[1]);
    d.values[2] = field("z", d.texts[2]);
    const bool components = d.values[0] || d.values[1] || d.values[2];
    if (d.normal && components)
      r.fail_at(t.get("normal")->source(),
                join(path, "normal") +
                    " prescribes the normal component: give either normal or "
                    "the components x and y, not both");
    if (!d.normal && !components)
      r.missing(join(path, "x"),
                dim.known() == 2   ? "the displacement to prescribe: x and/or y, or normal "
                                     "(numbers or expressions of x, y)"
                : dim.known() == 3 ? "the displacement to prescribe: x, y and/or z (numbers or "
                                     "expressions of x, y, z)"
                                   : "the displacement to prescribe: x, y and/or z (in 3D), or "
                                     "normal (numbers or expressions of x, y, z)");
    d.factors = own_factors(r, t, path);
    spec.displacements.push_back(std::move(d));
  }
}

// [[pressure]] boundary, p: a pressure normal to the boundary.
void read_pressures(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "pressure");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("pressure", i);
    r.check_keys(t, path);
    PressureSpec p;
    p.boundary = boundary_of(r, t, path);
    const std::string key = join(path, "p");
    p.text = required(r, r.expression(t, path, "p"), key,
                      "a number or an expression of x, y: the pressure (force per area)");
    p.p = scalar_formula(r, key, p.text);
    p.factors = own_factors(r, t, path);
    spec.pressures.push_back(std::move(p));
  }
}

// [[point_load]] at = [x, y] (or [x, y, z]), force likewise, boundary (optional): a force at
// the nearest node.
void read_point_loads(const Reader& r, const Dimension& dim, const toml::table& root,
                      ProblemSpec& spec) {
  const auto entries = r.array_of_tables(root, "point_load");
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const toml::table& t = *entries[i];
    const std::string path = element("point_load", i);
    r.check_keys(t, path);
    PointLoadSpec pl;
    pl.at =
        required_point(r, dim, t, path, "at",
                       "[x, y] ([x, y, z] in 3D): the point; the load acts at the nearest node");
    pl.force =
        required_point(r, dim, t, path, "force",
                       "[fx, fy] ([fx, fy, fz] in 3D): the force (per unit thickness in 2D)");
    pl.boundary = r.string(t, path, "boundary").value_or("");
    pl.factors = own_factors(r, t, path);
    spec.point_loads.push_back(std::move(pl));
  }
}

void read_body_force(const Reader& r, const Dimension& dim, const toml::table& root,
                     ProblemSpec& spec, ExpressionTexts& texts) {
  const toml::table* t = r.table(root, "", "body_force");
  if (t == nullptr) return;
  r.check_keys(*t, "body_force");
  const auto f = required(r, vector_expressions(r, dim, *t, "body_force", "f"), "body_force.f",
                          "an expression of x, y, z per component: the force per volume");
  spec.body_force = finite_vector_field(
      with_file(r, [&] { return make_vector_field(f, "body_force.f"); }), "body_force.f", f);
  spec.body_force_description = describe(f);
  spec.body_force_factors = own_factors(r, *t, "body_force");
  texts.body_force = f;
}

// "[0, 0]", "[0, 0, 0]": a vector as the file gave it, for messages.
std::string vector_text(const Eigen::Vector3d& v, int count) {
  std::string out;
  for (int k = 0; k < count; ++k) out += fmt::format("{}{:g}", k > 0 ? ", " : "", v(k));
  return "[" + out + "]";
}

// friction = "none" | "tresca" (slip_bound) | "coulomb" (mu): the keys of the other laws refused.
void read_friction(const Reader& r, const toml::table& t, const std::string& path,
                   ContactSpec& contact) {
  const std::string law = r.string(t, path, "friction").value_or("none");
  const auto parsed = enum_from_string(kFrictionModelNames, law);
  if (!parsed)
    r.fail_at(t.get("friction")->source(), join(path, "friction") + " = \"" + law +
                                               "\": expected " + enum_choices(kFrictionModelNames));
  contact.friction = *parsed;
  const auto refuse = [&](const char* key, const char* with) {
    if (t.contains(key))
      r.fail_at(t.get(key)->source(), join(path, key) + " applies with friction = \"" + with +
                                          "\" only; this boundary has friction = \"" + law + "\"");
  };
  if (contact.friction != FrictionModel::Tresca) refuse("slip_bound", "tresca");
  if (contact.friction != FrictionModel::Coulomb) refuse("mu", "coulomb");
  if (contact.friction == FrictionModel::Tresca) {
    const std::string key = join(path, "slip_bound");
    contact.slip_bound_text =
        required(r, r.expression(t, path, "slip_bound"), key,
                 "a number or an expression of x, y, z >= 0: the tangential traction at which "
                 "the boundary slides");
    contact.slip_bound = scalar_formula(r, key, contact.slip_bound_text);
  }
  if (contact.friction == FrictionModel::Coulomb) {
    const std::optional<double> mu = r.number(t, path, "mu");
    if (!mu) r.missing(join(path, "mu"), "a number >= 0: the friction coefficient");
    if (!(*mu >= 0.0) || !std::isfinite(*mu))
      r.out_of_range(join(path, "mu"), as_text(*mu), "a finite number >= 0", t.get("mu"));
    contact.mu = *mu;
  }
}

// One contact boundary, from the table at `path` ("contact", or "contact[1]" of [[contact]]).
ContactSpec read_contact_entry(const Reader& r, const Dimension& dim, const toml::table* t,
                               const std::string& path) {
  r.check_keys(*t, path);
  ContactSpec contact;
  contact.boundary = boundary_of(r, *t, path);
  RigidObstacle& o = contact.obstacle;
  const std::string shape = r.string(*t, path, "obstacle").value_or("gap");
  const auto parsed = enum_from_string(kObstacleShapeNames, shape);
  if (!parsed)
    r.fail_at(t->get("obstacle")->source(), join(path, "obstacle") + " = \"" + shape +
                                                "\": expected " +
                                                enum_choices(kObstacleShapeNames));
  o.shape = *parsed;
  if (auto normal = vector_expressions(r, dim, *t, path, "surface_normal")) {
    const std::string key = join(path, "surface_normal");
    contact.surface_normal = finite_vector_field(
        with_file(r, [&] { return make_vector_field(*normal, key); }), key, *normal);
    contact.surface_normal_text = std::move(*normal);
  }
  read_friction(r, *t, path, contact);
  // The keys of the shape (interface/obstacle_parameters.hpp); a key that only other shapes
  // have is refused, naming them.
  const ObstacleShapeRow& row = obstacle_shape(o.shape);
  const auto has = [](const ObstacleShapeRow& s, std::string_view key) {
    return std::any_of(s.parameters.begin(), s.parameters.end(),
                       [&](const ObstacleParameter& p) { return key == p.key; });
  };
  for (const ObstacleShapeRow& any_shape : obstacle_shapes())
    for (const ObstacleParameter& p : any_shape.parameters) {
      if (!t->contains(p.key) || has(row, p.key)) continue;
      std::string shapes;
      for (const ObstacleShapeRow& other : obstacle_shapes())
        if (has(other, p.key))
          shapes += std::string(shapes.empty() ? "" : " or ") + "\"" +
                    std::string(enum_to_string(kObstacleShapeNames, other.shape)) + "\"";
      r.fail_at(t->get(p.key)->source(), join(path, p.key) + " applies with obstacle = " + shapes +
                                             " only; this obstacle is \"" + shape + "\"");
    }
  if (row.only_dimension != 0)
    dim.imply(*t->get("obstacle"), join(path, "obstacle"), row.only_dimension, "a " + shape,
              row.instead);
  using K = ObstacleParameterKind;
  for (const ObstacleParameter& p : row.parameters) {
    const std::string key = join(path, p.key);
    const toml::node* n = t->get(p.key);
    switch (p.kind) {
      case K::Formula: {  // the gap formula, the paper's foundation
        const std::string gap = r.expression(*t, path, p.key).value_or("0");
        contact.gap = scalar_formula(r, key, gap);
        contact.description = gap;
        break;
      }
      case K::Position:
      case K::Direction:
        o.*p.vector = required_point(r, dim, *t, path, p.key, p.expected);
        break;
      case K::Axis: {
        if (n == nullptr) r.missing(key, p.expected);
        const std::vector<double> a = r.numbers(*n, key, 3, "x, y and z");
        o.*p.vector = Eigen::Vector3d(a[0], a[1], a[2]);
        break;
      }
      case K::Positive: {
        const std::optional<double> v = r.number(*t, path, p.key);
        if (!v) r.missing(key, p.expected);
        if (!(*v > 0.0)) r.out_of_range(key, as_text(*v), p.expected, n);
        o.*p.number = *v;
        break;
      }
      case K::Flag:
        o.*p.flag = r.boolean(*t, path, p.key).value_or(false);
        break;
    }
    // A direction (a plane's normal, a cylinder's axis) may have any length, but not 0.
    if ((p.kind == K::Direction || p.kind == K::Axis) && !((o.*p.vector).norm() > 0.0))
      r.fail_at(n->source(), key + " = " +
                                 vector_text(o.*p.vector, p.kind == K::Axis ? 3 : dim.stated()) +
                                 ": expected a non-zero vector " + p.direction_words);
  }
  return contact;
}

// [loading] steps = N (factors k / N) or factors = [..]: the loading history.
void read_loading(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  const toml::table* t = r.table(root, "", "loading");
  if (t == nullptr) return;
  r.check_keys(*t, "loading");
  const std::optional<std::int64_t> steps = r.integer(*t, "loading", "steps");
  const toml::node* factors = t->get("factors");
  if (steps && factors != nullptr)
    r.fail_at(factors->source(), "loading.factors and loading.steps: give one of them");
  if (steps) {
    if (*steps < 1 || *steps > 100000)
      r.out_of_range("loading.steps", std::to_string(*steps), "an integer from 1 to 100000",
                     t->get("steps"));
    for (std::int64_t k = 1; k <= *steps; ++k)
      spec.load_factors.push_back(static_cast<double>(k) / static_cast<double>(*steps));
    return;
  }
  if (factors == nullptr)
    r.missing("loading.steps", "an integer >= 1 (or loading.factors, an array of numbers >= 0)");
  spec.load_factors =
      factor_array(r, *factors, "loading.factors", "a non-empty array of numbers >= 0", true);
}

// The entries' own factors (own_factors): one per step of [loading], which they need.
void check_own_factors(const Reader& r, const toml::table& root, const ProblemSpec& spec) {
  const auto check = [&](const toml::table& t, const std::string& path) {
    const toml::node* n = t.get("factors");
    if (n == nullptr) return;
    const std::string key = join(path, "factors");
    if (spec.load_factors.empty())
      r.fail_at(n->source(), key +
                                 ": an entry's own load factors belong to a loading history: "
                                 "add a [loading] section (steps or factors) with as many steps");
    const std::size_t size = n->as_array()->size();
    if (size != spec.load_factors.size())
      r.fail_at(n->source(),
                fmt::format("{}: expected {} load factors, one per step of [loading], got {}", key,
                            spec.load_factors.size(), size));
  };
  for (const char* name : {"displacement", "traction", "pressure", "point_load"}) {
    const auto entries = r.array_of_tables(root, name);
    for (std::size_t i = 0; i < entries.size(); ++i) check(*entries[i], element(name, i));
  }
  if (const toml::table* t = r.table(root, "", "body_force")) check(*t, "body_force");
}

// [contact] (one contact boundary) or [[contact]] (several, each with its obstacle).
void read_contacts(const Reader& r, const Dimension& dim, const toml::table& root,
                   ProblemSpec& spec) {
  const toml::node* n = root.get("contact");
  if (n == nullptr)
    r.missing("contact",
              "a [contact] section with the contact boundary (or [[contact]] "
              "sections, one per contact boundary)");
  if (const toml::table* t = n->as_table()) {
    spec.contacts.push_back(read_contact_entry(r, dim, t, "contact"));
    return;
  }
  const auto* a = n->as_array();
  if (a == nullptr || a->empty())
    r.wrong_type("contact", "a [contact] section or [[contact]] sections", *n);
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto* t = a->get(i)->as_table();
    if (t == nullptr) r.wrong_type(element("contact", i), "a table", *a->get(i));
    const std::string path = element("contact", i);
    spec.contacts.push_back(read_contact_entry(r, dim, t, path));
    for (std::size_t k = 0; k + 1 < spec.contacts.size(); ++k)
      if (spec.contacts[k].boundary == spec.contacts.back().boundary)
        r.fail(join(path, "boundary") + " = '" + spec.contacts.back().boundary + "' is " +
               element("contact", k) + ".boundary already: one obstacle per contact boundary");
  }
}

void read_solver(const Reader& r, const toml::table& root, ProblemSpec& spec) {
  ContactSolverOptions& o = spec.solver;
  const toml::table* t = r.table(root, "", "solver");
  const toml::table* lt = nullptr;
  if (t != nullptr) {
    r.check_keys(*t, "solver");
    read_options(r, *t, contact_solver_option_table(), o);
    lt = r.table(*t, "solver", "linear");
    if (lt != nullptr) {
      r.check_keys(*lt, "solver.linear");
      read_options(r, *lt, linear_solver_option_table(), o.linear);
    }
  }
  check_options(r, t, contact_solver_option_table(), o);
  check_options(r, lt, linear_solver_option_table(), o.linear);
  r.validated(o);  // what no single option says (solver.device = "cuda" needs cg, ...)
}

// A mesh that cannot fit is refused now rather than after minutes of assembly, or by the
// out-of-memory killer.
void check_memory(const Reader& r, const ProblemSpec& spec) {
  // A file's size is known when it is read, a given mesh's by its caller.
  if (!is_structured(spec.mesh_type)) return;
  const bool box = spec.mesh_type == MeshType::Box;
  // Quadratic cells: the lattice of half steps.
  const double p = cell_order(box ? spec.box.cell : spec.mesh.cell);
  const double nx = static_cast<double>(box ? spec.box.nx : spec.mesh.nx);
  const double ny = static_cast<double>(box ? spec.box.ny : spec.mesh.ny);
  const double nz = box ? static_cast<double>(spec.box.nz) : 0.0;
  // The estimate is per node of a 2D mesh; a 3D node costs more, so for a box it is a lower
  // bound, which is all a refusal needs.
  const double nodes = (p * nx + 1.0) * (p * ny + 1.0) * (p * nz + 1.0);
  const double need = estimated_memory_bytes(nodes, spec.solver.linear.type);
  const double have = physical_memory_bytes();
  if (have > 0.0 && need > have)
    r.fail(fmt::format(
        "mesh {} has {:.3g} nodes and needs about {:.3g} GB of memory with the {} solver, "
        "more than this machine's {:.3g} GB: use a smaller {}",
        box ? fmt::format("{}x{}x{}", spec.box.nx, spec.box.ny, spec.box.nz)
            : fmt::format("{}x{}", spec.mesh.nx, spec.mesh.ny),
        nodes, need / 1e9, enum_to_string(kLinearSolverTypeNames, spec.solver.linear.type),
        have / 1e9, box ? "mesh.nx, mesh.ny, mesh.nz" : "mesh.nx, mesh.ny"));
}

}  // namespace

LoadedProblem parse_problem_string(const std::string& toml_text, const std::string& name_for_errors,
                                   const std::vector<std::string>& overrides,
                                   std::shared_ptr<const Mesh> mesh) {
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
  return read_problem_table(std::move(root), name_for_errors, overrides, std::move(mesh));
}

LoadedProblem read_problem_table(toml::table root, const std::string& name_for_errors,
                                 const std::vector<std::string>& overrides,
                                 std::shared_ptr<const Mesh> mesh) {
  std::set<std::string> overridden;
  {
    const Reader pre(name_for_errors, {}, problem_schema());
    for (const std::string& o : overrides) overridden.insert(apply_override(pre, root, o));
  }
  const Reader r(name_for_errors, std::move(overridden), problem_schema());
  r.check_keys(root, "");

  LoadedProblem out;
  out.path = name_for_errors;
  ProblemSpec& spec = out.spec;
  ExpressionTexts texts;
  read_top_level(r, root, spec);
  read_mesh(r, root, spec, std::move(mesh));
  const Dimension dim(r, spec);  // known from the mesh type, or implied by the keys that follow
  read_material(r, dim, root, spec, out.warnings);
  read_regions(r, root, spec, out.warnings);
  read_fem(r, root, spec);
  read_clamps(r, dim, root, spec);
  read_displacements(r, dim, root, spec);
  read_tractions(r, dim, root, spec, texts, out.warnings);
  read_pressures(r, root, spec);
  read_point_loads(r, dim, root, spec);
  read_body_force(r, dim, root, spec, texts);
  read_contacts(r, dim, root, spec);
  read_loading(r, root, spec);
  check_own_factors(r, root, spec);
  read_solver(r, root, spec);
  check_memory(r, spec);
  out.effective_toml = effective_toml(spec, texts);
  return out;
}

LoadedProblem read_problem_file(const std::string& path, const std::vector<std::string>& overrides,
                                std::shared_ptr<const Mesh> mesh) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError("cannot read '" + path + "': is a directory");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw InputError("cannot read '" + path + "': " + std::strerror(errno));
  return parse_problem_string(text.str(), path, overrides, std::move(mesh));
}

}  // namespace signorini

#include "signorini/input/problem_schema.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/interface/obstacle_parameters.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/unit_system.hpp"

namespace signorini {

namespace {

using P = ProblemSpec;

// Fields below the top level of ProblemSpec, as projections (one lambda serves the getter on a
// const spec and the setter alike). The rectangle and the box share the names of their keys
// (length, height, nx, ny, cell): the projection takes the field of the mesh type the spec has,
// which `type`, the first key of [mesh], has set by then.
constexpr auto mesh_length = [](auto& s) -> auto& {
  return s.mesh_type == MeshType::Box ? s.box.length : s.mesh.length;
};
constexpr auto mesh_width = [](auto& s) -> auto& {
  return s.box.width;
};
constexpr auto mesh_height = [](auto& s) -> auto& {
  return s.mesh_type == MeshType::Box ? s.box.height : s.mesh.height;
};
constexpr auto mesh_nx = [](auto& s) -> auto& {
  return s.mesh_type == MeshType::Box ? s.box.nx : s.mesh.nx;
};
constexpr auto mesh_ny = [](auto& s) -> auto& {
  return s.mesh_type == MeshType::Box ? s.box.ny : s.mesh.ny;
};
constexpr auto mesh_nz = [](auto& s) -> auto& {
  return s.box.nz;
};
constexpr auto mesh_cell = [](auto& s) -> auto& {
  return s.mesh_type == MeshType::Box ? s.box.cell : s.mesh.cell;
};
constexpr auto young_modulus = [](auto& s) -> auto& {
  return s.elasticity.material.E;
};
constexpr auto poisson_ratio = [](auto& s) -> auto& {
  return s.elasticity.material.nu;
};
constexpr auto plane_model = [](auto& s) -> auto& {
  return s.elasticity.plane_model;
};
constexpr auto gauss_points = [](auto& s) -> auto& {
  return s.elasticity.gauss_points;
};

// `"m-Pa"`, `"m-kPa"`, ...: the unit systems for the docs' type column.
std::string unit_system_list() {
  std::string out;
  for (const std::string& name : unit_system_names())
    out += (out.empty() ? "`\"" : ", `\"") + name + "\"`";
  return out;
}

template <class S>
void append_values(std::vector<std::pair<std::string, OptionValue>>& out,
                   const OptionTable<S>& table, const S& s) {
  for (const auto& [key, value] : table.values(s)) out.emplace_back(table.full_key(key), value);
}

}  // namespace

const OptionTable<P>& top_level_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("");
    t.text("name", &P::name, "name of the problem, in reports and `summary.json`")
        .default_text("the file name without folder and extension");
    t.custom("units", unit_system_list(),
             "the consistent set of units the numbers are in, as LENGTH-STRESS (`\"mm-N\"` = mm "
             "and N, so N/mm^2; `\"m-N\"` = m and N/m^2 = Pa). Labels only: the figures and "
             "reports print units only when it is given; the solver does not use it")
        .default_text("none");
    return t;
  }();
  return table;
}

const auto rectangle_mesh = [](const P& s) { return s.mesh_type == MeshType::Rectangle; };
const auto gmsh_mesh = [](const P& s) { return s.mesh_type == MeshType::Gmsh; };
const auto box_mesh = [](const P& s) { return s.mesh_type == MeshType::Box; };
const auto structured_mesh = [](const P& s) { return is_structured(s.mesh_type); };
constexpr const char* kStructuredWords = "type = \"rectangle\" or \"box\"";
constexpr const char* kBoxWords = "type = \"box\"";

// The cells of both structured meshes, for mesh.cell: the reader then checks that the cell fits
// the mesh type (cell_fits_mesh()).
constexpr EnumNames<CellType, 9> kStructuredCellNames{{
    {CellType::Quad4, "quad4"},
    {CellType::Quad8, "quad8"},
    {CellType::Quad9, "quad9"},
    {CellType::Tri3, "tri3"},
    {CellType::Tri6, "tri6"},
    {CellType::Hex8, "hex8"},
    {CellType::Hex27, "hex27"},
    {CellType::Tet4, "tet4"},
    {CellType::Tet10, "tet10"},
}};

const OptionTable<P>& mesh_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("mesh");
    t.choice("type", &P::mesh_type, kMeshTypeNames,
             "`rectangle`: the structured 2D mesh of the keys below; `gmsh`: the mesh of `file`, "
             "2D or 3D; `box`: the structured 3D mesh of the keys below");
    t.text("file", &P::mesh_file,
           "type = \"gmsh\": the mesh file, a path relative to the problem file; a Gmsh .msh "
           "file (formats 4.1 and 2.2, ASCII or binary), 2D or 3D, or a .geo file that the "
           "`gmsh` program meshes (in 2D, with the element order the .geo asks for). Physical "
           "curves (surfaces in 3D) become boundary parts and physical surfaces (volumes in 3D) "
           "regions, by name (docs/problem-format.md, Meshes from Gmsh)")
        .default_text("required with type = \"gmsh\"")
        .applies_when(gmsh_mesh, "type = \"gmsh\"");
    const auto get_origin = [](const P& s) {
      if (s.mesh_type == MeshType::Box) return std::vector<double>{s.box.x0, s.box.y0, s.box.z0};
      return std::vector<double>{s.mesh.x0, s.mesh.y0};
    };
    const auto set_origin = [](P& s, const std::vector<double>& v) {
      if (s.mesh_type == MeshType::Box && v.size() == 3) {
        s.box.x0 = v[0];
        s.box.y0 = v[1];
        s.box.z0 = v[2];
      } else if (v.size() == 2) {
        s.mesh.x0 = v[0];
        s.mesh.y0 = v[1];
      }
    };
    const auto origin_size = [](const P& s) { return s.mesh_type == MeshType::Box ? 3 : 2; };
    t.vector("origin", get_origin, set_origin, origin_size, {"x0", "y0", "z0"},
             "array of 2 numbers (rectangle) or 3 (box)",
             "rectangle: lower-left corner [x0, y0]; box: the corner with the smallest "
             "coordinates [x0, y0, z0]")
        .unit("L")
        .default_text("`[0.0, 0.0]` or `[0.0, 0.0, 0.0]`")
        .applies_when(structured_mesh, kStructuredWords);
    t.number("length", mesh_length, positive(), "extent in x")
        .unit("L")
        .default_text("required with type = \"rectangle\" or \"box\"")
        .applies_when(structured_mesh, kStructuredWords);
    t.number("width", mesh_width, positive(), "box: extent in y")
        .unit("L")
        .default_text("required with type = \"box\"")
        .applies_when(box_mesh, kBoxWords);
    t.number("height", mesh_height, positive(), "rectangle: extent in y; box: extent in z")
        .unit("L")
        .default_text("required with type = \"rectangle\" or \"box\"")
        .applies_when(structured_mesh, kStructuredWords);
    t.integer("nx", mesh_nx, at_least(1), "cells along x")
        .default_text("required with type = \"rectangle\" or \"box\"")
        .applies_when(structured_mesh, kStructuredWords);
    t.integer("ny", mesh_ny, at_least(1), "cells along y")
        .default_text("required with type = \"rectangle\" or \"box\"")
        .applies_when(structured_mesh, kStructuredWords);
    t.integer("nz", mesh_nz, at_least(1), "box: cells along z")
        .default_text("required with type = \"box\"")
        .applies_when(box_mesh, kBoxWords);
    t.choice("cell", mesh_cell, kStructuredCellNames,
             "the finite element. Rectangle: bilinear (`quad4`, the paper's), serendipity "
             "(`quad8`) or biquadratic (`quad9`) quadrilaterals, or each square split into two "
             "linear (`tri3`) or quadratic (`tri6`) triangles. Box: trilinear (`hex8`) or "
             "triquadratic (`hex27`) hexahedra, or each cube split into six linear (`tet4`) or "
             "quadratic (`tet10`) tetrahedra. Quadratic elements are far more accurate per "
             "unknown and lock much less for nu near 0.5; the geometric multigrid needs `quad4`")
        .default_text("`\"quad4\"` (rectangle), `\"hex8\"` (box)")
        .applies_when(structured_mesh, kStructuredWords);
    return t;
  }();
  return table;
}

bool cell_fits_mesh(const ProblemSpec& spec) {
  const auto among = [](const auto& names, CellType cell) {
    return std::any_of(names.begin(), names.end(), [&](const auto& e) { return e.first == cell; });
  };
  return spec.mesh_type == MeshType::Box ? among(kBoxCellNames, spec.box.cell)
                                         : among(kRectangleCellNames, spec.mesh.cell);
}

int stated_dimension(const ProblemSpec& spec) {
  switch (spec.mesh_type) {
    case MeshType::Rectangle:
      return 2;
    case MeshType::Box:
      return 3;
    case MeshType::Given:
      return spec.given_mesh ? spec.given_mesh->dim() : 0;
    case MeshType::Gmsh:
      break;
  }
  return spec.implied_dimension.dimension;
}

const OptionTable<P>& material_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("material");
    t.number("E", young_modulus, positive(), "Young's modulus")
        .unit("S")
        .required()
        .synonyms({"*young", "*modulus", "emod"});
    t.number("nu", poisson_ratio, open_interval(-1.0, 0.5),
             "Poisson's ratio; from 0.45 on a warning is printed where the mesh has "
             "first-order cells (the run goes on): they lock as nu approaches 0.5, so "
             "displacements come out too small and stresses near the contact oscillate (at 0.49 "
             "the stress under a contact peak overshoots the pressure by some 70 %). Quadratic "
             "cells lock far less (`mesh.cell`; a Gmsh mesh: `Mesh.ElementOrder = 2`)")
        .required()
        .synonyms({"*poisson", "v", "mu_poisson"});
    // A plane model means nothing in 3D: refused with a box rather than ignored. A Gmsh mesh's
    // dimension is known only when it is read: the key implies 2D (problem_file.cpp), which
    // build_model checks against the mesh. Where nothing implied a dimension the key was not
    // given, and the effective settings leave its default out.
    t.choice("plane_model", plane_model, kPlaneModelNames,
             "how the 2D problem stands for a 3D body: plane strain (eps_zz = 0, a long body) or "
             "plane stress (sigma_zz = 0, a thin plate). Refused with a box or a 3D Gmsh mesh")
        .applies_when([](const P& s) { return stated_dimension(s) == 2; },
                      "a 2D problem (type = \"rectangle\", or \"gmsh\" with a 2D mesh)");
    return t;
  }();
  return table;
}

const OptionTable<P>& fem_options() {
  // quadrature.hpp has the Gauss-Legendre rules with 1 to 5 points.
  static const OptionTable<P> table = [] {
    OptionTable<P> t("fem");
    t.integer("gauss_points", gauss_points, closed_interval(1.0, 5.0),
              "Gauss points per direction in each quad4 cell (2: the paper's 2 x 2 rule, exact for "
              "the Q1 stiffness of a parallelogram); the other cells have their own rules: 3 x 3 "
              "on quad8 and quad9, 3 points on tri3, 6 on tri6");
    t.integer("boundary_gauss_points", &P::boundary_gauss_points, closed_interval(1.0, 5.0),
              "Gauss points per boundary edge for the traction loads (integrated consistently, "
              "not lumped to nodes)");
    return t;
  }();
  return table;
}

const OptionTable<P>& region_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("region", true);
    t.custom("name", "string",
             "a region of the mesh: a physical surface (a physical volume in 3D) of a Gmsh mesh "
             "(`signorini check` lists them)")
        .required();
    t.custom("E", "number > 0", "Young's modulus of the region's cells").unit("S").required();
    t.custom("nu", "number in (-1, 0.5)", "Poisson's ratio of the region's cells").required();
    return t;
  }();
  return table;
}

const OptionTable<P>& clamp_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("clamp", true);
    t.custom("boundary", "string",
             "a boundary part: `left`, `right`, `bottom`, `top` of a rectangle, `xmin`, `xmax`, "
             "`ymin`, `ymax`, `zmin`, `zmax` of a box, or a physical curve (surface in 3D) of a "
             "Gmsh mesh")
        .default_text("required, unless `at` is given");
    t.custom("components", "array of `\"x\"`, `\"y\"`, `\"z\"` (3D)",
             "the displacement components held at 0 (`[\"x\"]`: a roller that slides along y, "
             "and z in 3D)")
        .default_text("every component: `[\"x\", \"y\"]`, in 3D `[\"x\", \"y\", \"z\"]`");
    t.custom("at", "array of 2 (3 in 3D) numbers",
             "a pinned node instead of a whole part: the node nearest to this point (on "
             "`boundary`, where that is given too) is held in `components`")
        .unit("L");
    return t;
  }();
  return table;
}

// `factors` of a load or displacement entry (problem_file.cpp, own_factors).
void own_factors_option(OptionTable<P>& t) {
  t.custom("factors", "array of numbers, one per load step",
           "its own load factors in a loading history, instead of `[loading]`'s: for example a "
           "shear after a press, `[0, 0.5, 1]` beside `[loading] factors = [1, 1, 1]`; needs "
           "`[loading]`")
      .default_text("`[loading]`'s");
}

const OptionTable<P>& displacement_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("displacement", true);
    t.custom("boundary", "string",
             "a boundary part whose displacement is given (a clamp with nonzero values)")
        .required();
    t.custom("x", "number or expression of x, y, z", "u_x on the part")
        .unit("L")
        .default_text("free");
    t.custom("y", "number or expression of x, y, z", "u_y on the part")
        .unit("L")
        .default_text("free");
    t.custom("z", "number or expression of x, y, z", "u_z on the part (3D problems only)")
        .unit("L")
        .default_text("free");
    t.custom("normal", "number or expression of x, y",
             "u . n along the part's outward normal n at each node, instead of `x` and `y` (the "
             "tangential component stays free): on a side parallel to x or y the component "
             "along that axis, elsewhere (inclined and curved parts) in local axes per node. 2D "
             "problems only so far")
        .unit("L")
        .default_text("free");
    own_factors_option(t);
    return t;
  }();
  return table;
}

const OptionTable<P>& pressure_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("pressure", true);
    t.custom("boundary", "string", "a boundary part (not a contact boundary)").required();
    t.custom("p", "number or expression of x, y, z",
             "the pressure, normal to the boundary: the traction -p n with n the outward unit "
             "normal at each point (on curved quadratic edges it follows the curve); p > 0 "
             "pushes into the body")
        .unit("S")
        .required();
    own_factors_option(t);
    return t;
  }();
  return table;
}

const OptionTable<P>& traction_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("traction", true);
    t.custom("boundary", "string", "a boundary part (not the contact boundary)").required();
    t.custom("p", "array of 2 (3 in 3D) expressions of x, y, z",
             "the traction [p_x, p_y] (in 3D [p_x, p_y, p_z])")
        .unit("S")
        .required()
        .synonyms({"load", "pressure", "traction", "force"});
    t.custom("x_range", "array of 2 numbers [lower, upper]",
             "the traction acts only where lower <= x <= upper (2D problems only so far)")
        .unit("L")
        .default_text("the whole part");
    t.custom("y_range", "array of 2 numbers [lower, upper]", "likewise in y")
        .unit("L")
        .default_text("the whole part");
    own_factors_option(t);
    return t;
  }();
  return table;
}

const OptionTable<P>& point_load_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("point_load", true);
    t.custom("at", "array of 2 (3 in 3D) numbers",
             "where the load acts (the nearest node takes it)")
        .unit("L")
        .required();
    t.custom("force", "array of 2 (3 in 3D) numbers",
             "the force [f_x, f_y] (in 3D [f_x, f_y, f_z]; in 2D per unit thickness)")
        .unit("S L")
        .required();
    t.custom("boundary", "string", "look for the nearest node on this boundary part only")
        .default_text("all nodes");
    own_factors_option(t);
    return t;
  }();
  return table;
}

const OptionTable<P>& body_force_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("body_force");
    t.custom("f", "array of 2 (3 in 3D) expressions of x, y, z",
             "force per unit volume [f_x, f_y] (in 3D [f_x, f_y, f_z]); without the section, "
             "f = 0")
        .unit("S/L")
        .default_text("required in the section");
    own_factors_option(t);
    return t;
  }();
  return table;
}

// [contact]'s obstacle key and the keys of every shape's parameters, from the shapes' table
// (interface/obstacle_parameters.hpp): a key that several shapes have says what it is for each.
void add_obstacle_keys(OptionTable<P>& t) {
  using K = ObstacleParameterKind;
  const auto shapes = obstacle_shapes();
  const auto name = [](const ObstacleShapeRow& row) {
    return std::string(enum_to_string(kObstacleShapeNames, row.shape));
  };
  // "a, b or c": the items joined (`between`: ", "; "; " where items have commas of their own).
  const auto list = [](const std::vector<std::string>& items, const char* last,
                       const char* between = ", ") {
    std::string out;
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (i > 0) out += i + 1 == items.size() ? last : between;
      out += items[i];
    }
    return out;
  };
  std::vector<std::string> choices, partners;
  for (const ObstacleShapeRow& row : shapes) {
    choices.push_back(fmt::format("`\"{}\"`{}", name(row), row.only_dimension == 3 ? " (3D)" : ""));
    std::vector<std::string> keys;
    for (const ObstacleParameter& p : row.parameters)
      if (p.kind != K::Formula) keys.push_back(fmt::format("`{}`", p.key));
    partners.push_back(row.doc + (keys.empty() ? "" : " with " + list(keys, ", ")));
  }
  t.custom("obstacle", list(choices, " or "),
           "the rigid partner: " + list(partners, "; or ", "; ") +
               ". Against a shape the constraint at each contact node acts along the "
               "obstacle's normal at the node's closest point of its surface and the gap is the "
               "exact distance to it; a node whose outward normal points away from the obstacle "
               "never touches it. A body that starts more than a tenth of its smallest extent "
               "inside the obstacle is refused")
      .default_text(fmt::format("`\"{}\"`", name(shapes.front())));
  std::vector<std::string> done{"gap"};  // (the gap formula: its own entry above)
  for (const ObstacleShapeRow& row : shapes)
    for (const ObstacleParameter& p : row.parameters) {
      if (std::find(done.begin(), done.end(), p.key) != done.end()) continue;
      done.emplace_back(p.key);
      // Per distinct meaning, the shapes that give it: "disc, cylinder: the radius".
      std::vector<std::pair<std::string, std::string>> meanings;  // (doc, shapes)
      std::vector<std::string> with;
      for (const ObstacleShapeRow& other : shapes)
        for (const ObstacleParameter& q : other.parameters)
          if (std::string_view(q.key) == p.key) {
            with.push_back(fmt::format("\"{}\"", name(other)));
            auto it = std::find_if(meanings.begin(), meanings.end(),
                                   [&](const auto& m) { return m.first == q.doc; });
            if (it == meanings.end())
              meanings.emplace_back(q.doc, name(other));
            else
              it->second += ", " + name(other);
          }
      std::string doc;
      for (const auto& [meaning, which] : meanings) {
        if (!doc.empty()) doc += "; ";
        doc += which;
        doc += ": ";
        doc += meaning;
      }
      const char* type = p.kind == K::Positive ? "number > 0"
                         : p.kind == K::Flag   ? "boolean"
                         : p.kind == K::Axis   ? "array of 3 numbers"
                                               : "array of 2 (3 in 3D) numbers";
      auto& entry = t.custom(p.key, type, doc);
      if (*p.unit != '\0') entry.unit(p.unit);
      entry.default_text(p.kind == K::Flag ? "`false`"
                                           : "required with obstacle = " + list(with, " or "));
    }
}

const OptionTable<P>& contact_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("contact");
    t.custom("boundary", "string", "a boundary part").required();
    t.custom("gap", "expression of x, y, z",
             "initial gap g(x) between body and foundation along the outward normal: g > 0 a "
             "clearance, 0 touching, g < 0 an initial interference (the foundation starts "
             "inside the body and pushes it out: a way to press a body onto an obstacle by a "
             "given depth). A function of x gives a curved foundation: "
             "`\"R - sqrt(R^2 - (x - c)^2)\"` for a cylinder of radius R under a flat face, "
             "touching at x = c")
        .unit("L")
        .default_text("`\"0\"`")
        .synonyms({"clearance", "initial_gap", "g"});
    add_obstacle_keys(t);
    t.custom("surface_normal", "array of 2 (3 in 3D) expressions of x, y, z",
             "the body's outward normal on this boundary where its geometry is known, e.g. "
             "`[\"x\", \"y\", \"z - 1\"]` on a ball of centre (0, 0, 1): its value at each "
             "contact node (any length) replaces the normal averaged from the facets, which is "
             "exact on flat faces only. With a gap formula the constraint acts along it; an "
             "obstacle of known shape sets the direction itself (its own normal), and this "
             "normal then tells which nodes face it. It must point out of the body (within 100 "
             "degrees of the facets' normal) and not vanish")
        .default_text("the facets' average");
    t.custom("friction", "`\"none\"`, `\"tresca\"` or `\"coulomb\"`",
             "friction on this boundary: none (the paper's frictionless contact); Tresca's, the "
             "tangential traction bounded by `slip_bound`; Coulomb's, bounded by `mu` times the "
             "contact pressure. Solved by `uzawa_gnm`, `semismooth_newton` or `classical_uzawa` on "
             "the sparse direct path ([method.md](method.md), \"Friction\")")
        .default_text("`\"none\"`");
    t.custom("slip_bound", "expression of x, y, z, >= 0",
             "Tresca: the slip bound s(x), the tangential traction at which the boundary slides")
        .unit("S")
        .default_text("required with friction = \"tresca\"");
    t.custom("mu", "number >= 0", "Coulomb: the friction coefficient")
        .default_text("required with friction = \"coulomb\"");
    return t;
  }();
  return table;
}

const OptionTable<P>& loading_options() {
  static const OptionTable<P> table = [] {
    OptionTable<P> t("loading");
    t.custom("steps", "integer >= 1",
             "proportional loading in this many equal steps: load factors 1/steps, 2/steps, .., "
             "1 on every load and prescribed displacement without `factors` of its own (not on "
             "the gaps), each step warm-started from the last")
        .default_text("1 (without the section: one solve)");
    t.custom("factors", "array of numbers >= 0",
             "or a table of load factors, in the order they are applied (for example "
             "`[0.5, 1, 0.5, 0]` loads and unloads); instead of `steps`");
    return t;
  }();
  return table;
}

const std::vector<const OptionTableInfo*>& problem_schema() {
  static const std::vector<const OptionTableInfo*> tables = {&top_level_options(),
                                                             &mesh_options(),
                                                             &material_options(),
                                                             &fem_options(),
                                                             &region_options(),
                                                             &clamp_options(),
                                                             &displacement_options(),
                                                             &traction_options(),
                                                             &pressure_options(),
                                                             &point_load_options(),
                                                             &body_force_options(),
                                                             &contact_options(),
                                                             &loading_options(),
                                                             &contact_solver_option_table(),
                                                             &linear_solver_option_table()};
  return tables;
}

std::vector<std::pair<std::string, OptionValue>> contact_values(const ContactSpec& contact,
                                                                const std::string& gap_text,
                                                                int dim) {
  std::vector<std::pair<std::string, OptionValue>> out{{"boundary", contact.boundary}};
  const RigidObstacle& o = contact.obstacle;
  // A point or vector of the problem's dimension; a cylinder's axis has 3 whatever it is.
  const auto coordinates = [](const Eigen::Vector3d& v, int n) {
    return std::vector<double>(v.data(), v.data() + n);
  };
  // The shape's parameters in its row's order (interface/obstacle_parameters.hpp); the gap
  // formula, the default, without the obstacle key.
  if (o.shape != ObstacleShape::Gap)
    out.emplace_back("obstacle", std::string(enum_to_string(kObstacleShapeNames, o.shape)));
  for (const ObstacleParameter& p : obstacle_shape(o.shape).parameters) switch (p.kind) {
      case ObstacleParameterKind::Formula:
        out.emplace_back(p.key, gap_text);
        break;
      case ObstacleParameterKind::Position:
      case ObstacleParameterKind::Direction:
        out.emplace_back(p.key, coordinates(o.*p.vector, dim));
        break;
      case ObstacleParameterKind::Axis:
        out.emplace_back(p.key, coordinates(o.*p.vector, 3));
        break;
      case ObstacleParameterKind::Positive:
        out.emplace_back(p.key, o.*p.number);
        break;
      case ObstacleParameterKind::Flag:
        out.emplace_back(p.key, o.*p.flag);
        break;
    }
  if (contact.friction != FrictionModel::None)
    out.emplace_back("friction",
                     std::string(enum_to_string(kFrictionModelNames, contact.friction)));
  if (contact.friction == FrictionModel::Tresca)
    out.emplace_back("slip_bound", contact.slip_bound_text);
  if (contact.friction == FrictionModel::Coulomb) out.emplace_back("mu", contact.mu);
  return out;
}

std::vector<std::pair<std::string, OptionValue>> displacement_values(
    const DisplacementSpec& displacement) {
  std::vector<std::pair<std::string, OptionValue>> out{{"boundary", displacement.boundary}};
  if (displacement.normal) {
    out.emplace_back("normal", displacement.normal_text);
  } else {
    const char* names[] = {"x", "y", "z"};
    for (std::size_t k = 0; k < 3; ++k)
      if (displacement.values[k]) out.emplace_back(names[k], displacement.texts[k]);
  }
  if (!displacement.factors.empty()) out.emplace_back("factors", displacement.factors);
  return out;
}

std::vector<std::pair<std::string, OptionValue>> pressure_values(const PressureSpec& pressure) {
  std::vector<std::pair<std::string, OptionValue>> out{{"boundary", pressure.boundary},
                                                       {"p", pressure.text}};
  if (!pressure.factors.empty()) out.emplace_back("factors", pressure.factors);
  return out;
}

std::vector<std::pair<std::string, OptionValue>> region_values(const RegionMaterialSpec& region) {
  return {{"name", region.region}, {"E", region.material.E}, {"nu", region.material.nu}};
}

std::vector<std::pair<std::string, OptionValue>> option_values(const ProblemSpec& spec) {
  std::vector<std::pair<std::string, OptionValue>> out;
  append_values(out, top_level_options(), spec);
  append_values(out, mesh_options(), spec);
  append_values(out, material_options(), spec);
  append_values(out, fem_options(), spec);
  append_values(out, contact_solver_option_table(), spec.solver);
  append_values(out, linear_solver_option_table(), spec.solver.linear);
  return out;
}

}  // namespace signorini

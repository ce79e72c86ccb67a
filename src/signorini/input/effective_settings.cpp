#include "signorini/input/effective_settings.hpp"

#include <cmath>

#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/input/toml_emitter.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {

namespace {

// A section's keys and values (region_values(), contact_values(), ...), in their order.
void emit_values(TomlEmitter& out, const std::vector<std::pair<std::string, OptionValue>>& values) {
  for (const auto& [key, value] : values) out.value(key, value);
}

// Every option of `table` that lives in the struct, in the table's order (Custom ones are the
// caller's).
template <class S>
void emit_options(TomlEmitter& out, const OptionTable<S>& table, const S& s) {
  emit_values(out, table.values(s));
}

}  // namespace

std::string effective_toml(const ProblemSpec& spec, const ExpressionTexts& texts) {
  // Points and vectors have as many components as the problem has dimensions. On a Gmsh mesh
  // that is what the file's keys implied; where none did (0), no point or vector is written.
  const int dim = stated_dimension(spec);
  TomlEmitter out;
  emit_options(out, top_level_options(), spec);
  if (!spec.units.empty()) out.value("units", spec.units);
  if (spec.mesh_type == MeshType::Given) {
    // No text can say a mesh given as arrays: the log says what it was instead.
    out.comment(spec.given_mesh ? "[mesh]: given by the program (" +
                                      std::to_string(spec.given_mesh->num_nodes()) + " nodes, " +
                                      std::to_string(spec.given_mesh->num_cells()) + " cells)"
                                : "[mesh]: given by the program");
  } else {
    out.table("mesh");
    emit_options(out, mesh_options(), spec);
  }
  out.table("material");
  emit_options(out, material_options(), spec);
  for (const RegionMaterialSpec& m : spec.region_materials) {
    out.array_table("region");
    emit_values(out, region_values(m));
  }
  out.table("fem");
  emit_options(out, fem_options(), spec);
  for (const ClampSpec& c : spec.clamps) {
    out.array_table("clamp");
    if (!c.boundary.empty()) out.value("boundary", c.boundary);
    if (c.at)
      out.value("at", std::vector<double>(
                          c.at->data(),
                          c.at->data() + (dim == 3 || (dim == 0 && (*c.at)(2) != 0.0) ? 3 : 2)));
    std::vector<std::string> components;
    if (c.components[0]) components.emplace_back("x");
    if (c.components[1]) components.emplace_back("y");
    if (c.components[2] && dim == 3) components.emplace_back("z");
    // Every component of a problem whose dimension the mesh will decide: the default, which
    // holds z in 3D, unlike ["x", "y"].
    if (dim == 0 && c.components[0] && c.components[1] && c.components[2]) continue;
    out.value("components", components);
  }
  for (const DisplacementSpec& d : spec.displacements) {
    out.array_table("displacement");
    emit_values(out, displacement_values(d));
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
    if (!spec.tractions[i].factors.empty()) out.value("factors", spec.tractions[i].factors);
  }
  for (const PressureSpec& p : spec.pressures) {
    out.array_table("pressure");
    emit_values(out, pressure_values(p));
  }
  for (const PointLoadSpec& pl : spec.point_loads) {
    out.array_table("point_load");
    out.value("at", std::vector<double>(pl.at.data(), pl.at.data() + dim));
    out.value("force", std::vector<double>(pl.force.data(), pl.force.data() + dim));
    if (!pl.boundary.empty()) out.value("boundary", pl.boundary);
    if (!pl.factors.empty()) out.value("factors", pl.factors);
  }
  if (!texts.body_force.empty()) {
    out.table("body_force");
    out.value("f", texts.body_force);
    if (!spec.body_force_factors.empty()) out.value("factors", spec.body_force_factors);
  }
  // One contact boundary as [contact], as the files mostly give it; several as [[contact]].
  for (const ContactSpec& c : spec.contacts) {
    if (spec.contacts.size() == 1)
      out.table("contact");
    else
      out.array_table("contact");
    emit_values(out, contact_values(c, c.description, dim));
    if (!c.surface_normal_text.empty()) out.value("surface_normal", c.surface_normal_text);
  }
  if (!spec.load_factors.empty()) {
    out.table("loading");
    out.value("factors", spec.load_factors);
  }
  out.table("solver");
  emit_options(out, contact_solver_option_table(), spec.solver);
  out.table("solver.linear");
  emit_options(out, linear_solver_option_table(), spec.solver.linear);
  return out.text();
}

}  // namespace signorini

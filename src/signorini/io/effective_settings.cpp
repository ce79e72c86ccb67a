#include "signorini/io/effective_settings.hpp"

#include <cmath>

#include "signorini/contact/contact_solver_option_table.hpp"
#include "signorini/io/problem_schema.hpp"
#include "signorini/io/toml_emitter.hpp"
#include "signorini/linalg/linear_solver_option_table.hpp"

namespace signorini {

namespace {

// Every option of `table` that lives in the struct, in the table's order (Custom ones are the
// caller's).
template <class S>
void emit_options(TomlEmitter& out, const OptionTable<S>& table, const S& s) {
  for (std::size_t i = 0; i < table.options.size(); ++i)
    if (table.getter(i) && table.applies(i, s)) out.value(table.options[i].key, table.getter(i)(s));
}

}  // namespace

std::string effective_toml(const ProblemSpec& spec, const ExpressionTexts& texts) {
  TomlEmitter out;
  emit_options(out, top_level_options(), spec);
  if (!spec.units.empty()) out.value("units", spec.units);
  out.table("mesh");
  emit_options(out, mesh_options(), spec);
  out.table("material");
  emit_options(out, material_options(), spec);
  for (const RegionMaterialSpec& m : spec.region_materials) {
    out.array_table("region");
    out.value("name", m.region);
    out.value("E", m.material.E);
    out.value("nu", m.material.nu);
  }
  out.table("fem");
  emit_options(out, fem_options(), spec);
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
  const RigidObstacle& o = spec.contact.obstacle;
  switch (o.shape) {
    case ObstacleShape::Gap:
      out.value("gap", texts.gap);
      break;
    case ObstacleShape::Plane:
      out.value("obstacle", std::string("plane"));
      out.value("point", std::vector<double>{o.point(0), o.point(1)});
      out.value("normal", std::vector<double>{o.normal(0), o.normal(1)});
      break;
    case ObstacleShape::Disc:
      out.value("obstacle", std::string("disc"));
      out.value("centre", std::vector<double>{o.centre(0), o.centre(1)});
      out.value("radius", o.radius);
      out.value("inside", o.body_inside);
      break;
  }
  out.table("solver");
  emit_options(out, contact_solver_option_table(), spec.solver);
  out.table("solver.linear");
  emit_options(out, linear_solver_option_table(), spec.solver.linear);
  return out.text();
}

}  // namespace signorini

#include <fmt/format.h>

#include "signorini/problem/model.hpp"

namespace signorini {

std::vector<std::string> mesh_warnings(const ProblemSpec& spec, const Mesh& mesh) {
  if (spec.mesh_type != MeshType::Gmsh) return {};
  std::string linear;
  for (const CellType t : mesh.cell_types())
    if (cell_order(t) == 1)
      linear += (linear.empty() ? "" : ", ") + std::string(enum_to_string(kCellTypeNames, t));
  if (linear.empty()) return {};  // quadratic cells lock far less
  // As input/problem_file.cpp says of the other meshes: linear elements lock as nu approaches 1/2,
  // and the solver cannot detect it.
  std::vector<std::string> out;
  const auto warn = [&](const std::string& key, double nu) {
    if (nu < 0.45) return;
    out.push_back(fmt::format(
        "{} = {:g} >= 0.45: nearly incompressible, and the first-order cells of '{}' ({}) lock: "
        "displacements come out too small and stresses near the contact oscillate; mesh it with "
        "second-order cells (Mesh.ElementOrder = 2 in the .geo, or gmsh -order 2) or check "
        "against a finer mesh",
        key, nu, spec.mesh_file, linear));
  };
  warn("material.nu", spec.elasticity.material.nu);
  for (std::size_t i = 0; i < spec.region_materials.size(); ++i)
    warn(fmt::format("region[{}].nu", i), spec.region_materials[i].material.nu);
  return out;
}

}  // namespace signorini

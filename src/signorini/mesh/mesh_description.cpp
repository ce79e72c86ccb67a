#include "signorini/mesh/mesh_description.hpp"

#include <fmt/format.h>

#include <map>

namespace signorini {

std::string mesh_description(const Mesh& mesh) {
  std::map<CellType, Index> per_type;
  std::vector<Index> per_region(mesh.region_names().size(), 0);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    ++per_type[mesh.cell_type(c)];
    ++per_region[static_cast<std::size_t>(mesh.cell_region(c))];
  }
  std::string types;
  for (const auto& [t, n] : per_type)
    types +=
        fmt::format("{}{}: {}", types.empty() ? "" : ", ", enum_to_string(kCellTypeNames, t), n);
  std::string out =
      fmt::format("{} nodes, {} cells ({})", mesh.num_nodes(), mesh.num_cells(), types);
  std::string regions;
  for (std::size_t r = 0; r < per_region.size(); ++r)
    if (!mesh.region_names()[r].empty() && per_region[r] > 0)
      regions += fmt::format("{}{} ({} cells)", regions.empty() ? "" : ", ", mesh.region_names()[r],
                             per_region[r]);
  if (!regions.empty()) out += "; regions: " + regions;
  std::string parts;
  for (const std::string& name : mesh.boundary_part_names())
    parts += fmt::format("{}{} ({} nodes)", parts.empty() ? "" : ", ", name,
                         mesh.boundary_part_nodes(name).size());
  if (!parts.empty()) out += "; boundary parts: " + parts;
  return out;
}

}  // namespace signorini

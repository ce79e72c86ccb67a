#include "signorini/mesh/mesh.hpp"

#include <algorithm>

#include "signorini/core/error.hpp"

namespace signorini {

Mesh::Mesh(CellType type, Eigen::MatrixXd coordinates, std::vector<Index> connectivity)
    : coordinates_(std::move(coordinates)), connectivity_(std::move(connectivity)) {
  const auto per_cell = static_cast<std::size_t>(nodes_per_cell(type));
  if (connectivity_.size() % per_cell != 0)
    throw InputError("mesh: connectivity length is not a multiple of the nodes per cell");
  types_.assign(connectivity_.size() / per_cell, type);
  check();
}

Mesh::Mesh(std::vector<CellType> types, Eigen::MatrixXd coordinates,
           std::vector<Index> connectivity)
    : types_(std::move(types)),
      coordinates_(std::move(coordinates)),
      connectivity_(std::move(connectivity)) {
  check();
}

void Mesh::check() {
  offsets_.resize(types_.size() + 1);
  offsets_[0] = 0;
  for (std::size_t c = 0; c < types_.size(); ++c) {
    const CellType t = types_[c];
    if (cell_dimension(t) != dim())
      throw InputError("mesh: cell " + std::to_string(c) + " is a " +
                       std::string(enum_to_string(kCellTypeNames, t)) + " (dimension " +
                       std::to_string(cell_dimension(t)) + "), but the coordinates have " +
                       std::to_string(dim()) + " rows, expected the cell dimension");
    offsets_[c + 1] = offsets_[c] + nodes_per_cell(t);
    max_nodes_per_cell_ = std::max(max_nodes_per_cell_, nodes_per_cell(t));
  }
  if (offsets_.back() != static_cast<Index>(connectivity_.size()))
    throw InputError("mesh: the connectivity has " + std::to_string(connectivity_.size()) +
                     " node numbers, expected " + std::to_string(offsets_.back()) +
                     " for the cell types given");
  for (const Index n : connectivity_)
    if (n < 0 || n >= num_nodes())
      throw InputError("mesh: cell refers to node " + std::to_string(n) + ", expected 0.." +
                       std::to_string(num_nodes() - 1));
}

std::vector<CellType> Mesh::cell_types() const {
  std::vector<bool> seen(kCellTypeNames.size(), false);
  for (const CellType t : types_) seen[static_cast<std::size_t>(t)] = true;
  std::vector<CellType> out;
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (seen[k]) out.push_back(static_cast<CellType>(k));
  return out;
}

std::vector<Index> Mesh::facet_nodes(const Facet& f) const {
  const auto local = facet_local_nodes(cell_type(f.cell), f.local);
  const auto nodes = cell(f.cell);
  std::vector<Index> out;
  out.reserve(local.size());
  for (const int i : local) out.push_back(nodes[static_cast<std::size_t>(i)]);
  return out;
}

void Mesh::set_cell_regions(std::vector<std::string> names, std::vector<int> region_of_cell) {
  if (static_cast<Index>(region_of_cell.size()) != num_cells())
    throw InputError("mesh: " + std::to_string(region_of_cell.size()) + " cell regions for " +
                     std::to_string(num_cells()) + " cells");
  for (const int r : region_of_cell)
    if (r < 0 || r >= static_cast<int>(names.size()))
      throw InputError("mesh: cell region " + std::to_string(r) + " has no name");
  region_names_ = std::move(names);
  regions_ = std::move(region_of_cell);
}

void Mesh::set_cell_source_tags(std::vector<Index> tags) {
  if (static_cast<Index>(tags.size()) != num_cells())
    throw InputError("mesh: " + std::to_string(tags.size()) + " cell tags for " +
                     std::to_string(num_cells()) + " cells");
  source_tags_ = std::move(tags);
}

void Mesh::set_boundary_part(std::string name, std::vector<Facet> facets) {
  for (const Facet& f : facets)
    if (f.cell < 0 || f.cell >= num_cells() || f.local < 0 ||
        f.local >= facets_per_cell(cell_type(f.cell)))
      throw InputError("mesh: boundary part '" + name + "' names facet (" + std::to_string(f.cell) +
                       ", " + std::to_string(f.local) + "), which does not exist");
  BoundaryPart part{name, std::move(facets)};
  parts_.insert_or_assign(std::move(name), std::move(part));
}

bool Mesh::has_boundary_part(std::string_view name) const {
  return parts_.contains(name);
}

const BoundaryPart& Mesh::boundary_part(std::string_view name) const {
  const auto it = parts_.find(name);
  if (it == parts_.end()) {
    std::string known;
    for (const auto& [n, p] : parts_) known += (known.empty() ? "" : ", ") + n;
    if (known.empty())  // (a Gmsh geometry without physical groups one dimension down)
      throw InputError("mesh has no boundary part '" + std::string(name) +
                       "': it has no named boundary parts at all; a Gmsh geometry names them "
                       "with physical groups (e.g. Physical Curve(\"" +
                       std::string(name) + "\") = {1}; in 2D, Physical Surface in 3D)");
    throw InputError("mesh has no boundary part '" + std::string(name) + "' (it has: " + known +
                     ")");
  }
  return it->second;
}

std::vector<std::string> Mesh::boundary_part_names() const {
  std::vector<std::string> names;
  for (const auto& [n, p] : parts_) names.push_back(n);
  return names;
}

std::vector<Index> Mesh::boundary_part_nodes(std::string_view name) const {
  std::vector<Index> nodes;
  for (const Facet& f : boundary_part(name).facets) {
    const auto fn = facet_nodes(f);
    nodes.insert(nodes.end(), fn.begin(), fn.end());
  }
  std::sort(nodes.begin(), nodes.end());
  nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
  return nodes;
}

}  // namespace signorini

#include "signorini/mesh/mesh_arrays.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <set>

#include "signorini/core/error.hpp"
#include "signorini/mesh/cell_orientation.hpp"
#include "signorini/mesh/cell_overlap.hpp"
#include "signorini/mesh/facet_matching.hpp"

namespace signorini {

namespace {

std::string type_name(CellType t) {
  return std::string(enum_to_string(kCellTypeNames, t));
}

}  // namespace

Mesh mesh_from_arrays(const MeshArrays& a) {
  if (a.points.rows() != 2 && a.points.rows() != 3)
    throw InputError(fmt::format(
        "mesh: the points have {} coordinates each, expected 2 (a 2D mesh) or 3 (a 3D mesh)",
        a.points.rows()));
  // 2D cells on points with three coordinates (as meshio and Gmsh give a plane mesh): a 2D mesh
  // where z is one constant, its z dropped.
  bool plane = a.points.rows() == 3 && !a.blocks.empty();
  for (const CellBlock& block : a.blocks) plane = plane && cell_dimension(block.type) == 2;
  Eigen::MatrixXd flat;
  if (plane && a.points.cols() > 0) {
    const double zmin = a.points.row(2).minCoeff(), zmax = a.points.row(2).maxCoeff();
    const double size =
        (a.points.topRows(2).rowwise().maxCoeff() - a.points.topRows(2).rowwise().minCoeff())
            .maxCoeff();
    if (!(zmax - zmin <= 1e-9 * std::max(size, 1e-300)))
      throw InputError(fmt::format(
          "mesh: 2D cells on points whose z ranges from {:g} to {:g}: expected a plane mesh, z "
          "one constant (or two coordinates per point)",
          zmin, zmax));
    flat = a.points.topRows(2);
  }
  const Eigen::MatrixXd& x = plane ? flat : a.points;
  const auto dim = static_cast<int>(x.rows());
  const Index n = x.cols();
  if (n == 0) throw InputError("mesh: no points");
  for (Index i = 0; i < n; ++i)
    if (!x.col(i).allFinite())
      throw InputError(fmt::format("mesh: point {} has a coordinate that is not finite", i));

  std::vector<CellType> types;
  std::vector<Index> cells;
  std::vector<std::string> region_names{""};
  std::vector<int> regions;
  std::vector<char> used(static_cast<std::size_t>(n), 0);
  std::vector<std::pair<std::size_t, std::size_t>> origin;  // (block, cell in it) of each cell
  for (std::size_t b = 0; b < a.blocks.size(); ++b) {
    const CellBlock& block = a.blocks[b];
    const std::string what = fmt::format("mesh: cell block {} ({})", b, type_name(block.type));
    if (cell_dimension(block.type) != dim)
      throw InputError(fmt::format("{}: a {}D cell type, but the points have {} coordinates", what,
                                   cell_dimension(block.type), dim));
    const auto npc = static_cast<std::size_t>(nodes_per_cell(block.type));
    if (block.nodes.size() % npc != 0)
      throw InputError(fmt::format("{}: {} node numbers, not a multiple of {} (nodes per cell)",
                                   what, block.nodes.size(), npc));
    auto r = std::find(region_names.begin(), region_names.end(), block.region);
    if (r == region_names.end()) r = region_names.insert(region_names.end(), block.region);
    const int region = static_cast<int>(r - region_names.begin());
    for (std::size_t c = 0; c * npc < block.nodes.size(); ++c) {
      const std::size_t first = cells.size();
      for (std::size_t k = 0; k < npc; ++k) {
        const Index v = block.nodes[c * npc + k];
        if (v < 0 || v >= n)
          throw InputError(
              fmt::format("{}, cell {}: node {} out of range, expected 0..{}", what, c, v, n - 1));
        used[static_cast<std::size_t>(v)] = 1;
        cells.push_back(v);
      }
      Index* v = cells.data() + first;
      if (dim == 2) {
        const double area2 = signed_corner_area2(block.type, v, x);
        if (area2 == 0.0)
          throw InputError(fmt::format("{}, cell {}: degenerate (zero area)", what, c));
        if (area2 < 0.0) mirror_cell(block.type, v);  // clockwise: turned counterclockwise
      } else if (const double det = min_corner_det(block.type, v, x); !(det > 0.0)) {
        throw InputError(fmt::format(
            "{}, cell {}: {}", what, c,
            det < 0.0 ? "inverted: det J < 0 at a corner (expected Gmsh's node order, which "
                        "gives det J > 0)"
                      : "degenerate: det J = 0 at a corner"));
      }
      types.push_back(block.type);
      regions.push_back(region);
      origin.emplace_back(b, c);
    }
  }
  if (types.empty()) throw InputError("mesh: no cells");
  for (Index i = 0; i < n; ++i)
    if (used[static_cast<std::size_t>(i)] == 0)
      throw InputError(fmt::format(
          "mesh: point {} belongs to no cell (it would have no stiffness): remove the points "
          "that no cell uses",
          i));
  Mesh mesh(std::move(types), x, std::move(cells));
  mesh.set_cell_regions(std::move(region_names), std::move(regions));
  check_cells_do_not_overlap(mesh, "mesh", [&](Index c) {
    const auto [b, k] = origin[static_cast<std::size_t>(c)];
    return fmt::format("cell block {} ({}), cell {}", b, type_name(a.blocks[b].type), k);
  });

  std::set<std::string> names;
  for (const BoundaryFacets& part : a.boundaries) {
    if (part.name.empty()) throw InputError("mesh: a boundary part without a name");
    if (!names.insert(part.name).second)
      throw InputError("mesh: boundary part '" + part.name + "' is given twice");
    const std::string what = "mesh: boundary part '" + part.name + "'";
    const int corners = boundary_element_corners(dim, part.nodes_per_facet);
    if (corners == 0)
      throw InputError(fmt::format(
          "{}: facets of {} nodes, expected {}", what, part.nodes_per_facet,
          dim == 2 ? "2 or 3 (lines)" : "3 or 6 (triangles), 4, 8 or 9 (quadrilaterals)"));
    const auto npf = static_cast<std::size_t>(part.nodes_per_facet);
    if (part.nodes.empty() || part.nodes.size() % npf != 0)
      throw InputError(fmt::format("{}: {} node numbers, expected a positive multiple of {}", what,
                                   part.nodes.size(), npf));
    std::vector<BoundaryElement> elements;
    for (std::size_t f = 0; f * npf < part.nodes.size(); ++f) {
      for (std::size_t k = 0; k < npf; ++k) {
        const Index v = part.nodes[f * npf + k];
        if (v < 0 || v >= n)
          throw InputError(
              fmt::format("{}, facet {}: node {} out of range, expected 0..{}", what, f, v, n - 1));
      }
      elements.push_back({std::span<const Index>(part.nodes.data() + f * npf, npf), corners});
    }
    const std::vector<std::optional<Facet>> matched = match_facets(mesh, elements);
    std::vector<Facet> facets;
    facets.reserve(matched.size());
    for (std::size_t f = 0; f < matched.size(); ++f) {
      if (!matched[f]) {
        std::string nodes;
        for (std::size_t k = 0; k < npf; ++k)
          nodes += (k == 0 ? "" : ", ") + std::to_string(part.nodes[f * npf + k]);
        throw InputError(fmt::format("{}, facet {} (nodes {}): not {} of any cell", what, f, nodes,
                                     dim == 2 ? "an edge" : "a face"));
      }
      facets.push_back(*matched[f]);
    }
    mesh.set_boundary_part(part.name, std::move(facets));
  }
  return mesh;
}

}  // namespace signorini

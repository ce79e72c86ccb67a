#pragma once
// Reference cells: how many nodes a cell has, and which local nodes make up each facet.
// Only Quad4 is implemented by the finite elements today; the others are listed so that meshes of
// triangles and 3D cells can be held by the same Mesh type when their elements arrive.

#include <span>
#include <string_view>

#include "signorini/core/enum_names.hpp"

namespace signorini {

enum class CellType { Quad4, Tri3, Hex8, Tet4 };

inline constexpr EnumNames<CellType, 4> kCellTypeNames{{
    {CellType::Quad4, "quad4"},
    {CellType::Tri3, "tri3"},
    {CellType::Hex8, "hex8"},
    {CellType::Tet4, "tet4"},
}};

/// Spatial dimension of a cell type.
constexpr int cell_dimension(CellType t) {
  return (t == CellType::Quad4 || t == CellType::Tri3) ? 2 : 3;
}

/// Number of nodes of a cell.
constexpr int nodes_per_cell(CellType t) {
  switch (t) {
    case CellType::Quad4:
      return 4;
    case CellType::Tri3:
      return 3;
    case CellType::Hex8:
      return 8;
    case CellType::Tet4:
      return 4;
  }
  return 0;
}

/// Number of facets (edges in 2D, faces in 3D) of a cell.
constexpr int facets_per_cell(CellType t) {
  switch (t) {
    case CellType::Quad4:
      return 4;
    case CellType::Tri3:
      return 3;
    case CellType::Hex8:
      return 6;
    case CellType::Tet4:
      return 4;
  }
  return 0;
}

/// Local node numbers of facet `f` of a cell, ordered so that the facet's outward normal follows
/// from the right-hand rule (counterclockwise cells in 2D: edge (a, b) has outward normal
/// (t_y, -t_x) with t = x_b - x_a).
std::span<const int> facet_local_nodes(CellType t, int facet);

}  // namespace signorini

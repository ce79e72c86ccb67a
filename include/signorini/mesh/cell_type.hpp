#pragma once
// Reference cells: how many nodes a cell has, its dimension and order, and which local nodes make
// up each facet. Node orders are Gmsh's: corners first, counterclockwise in 2D, then the mid-edge
// nodes in the order of the edges, then the face centres and a centre node. VTK agrees for the
// lines, the 2D types, Tet4 and Hex8; its Tet10 and Hex27 list some nodes in another order
// (output/vtu_file.cpp permutes them). The 3D cells: Tet4 (corners (0,0,0), (1,0,0), (0,1,0),
// (0,0,1)); Tet10 (mid-edge nodes on 0-1, 1-2, 2-0, 0-3, 2-3, 1-3); Hex8 on [-1, 1]^3 (the bottom
// z = -1 counterclockwise 0..3 seen from above, the top 4..7 above them); Hex27 (mid-edge nodes on
// 0-1, 0-3, 0-4, 1-2, 1-5, 2-3, 2-6, 3-7, 4-5, 4-7, 5-6, 6-7, the centres of the faces z = -1,
// y = -1, x = -1, x = 1, y = 1, z = 1, the centre of the cell).

#include <span>
#include <string_view>

#include "signorini/core/enum_names.hpp"

namespace signorini {

enum class CellType { Line2, Line3, Tri3, Tri6, Quad4, Quad8, Quad9, Tet4, Tet10, Hex8, Hex27 };

inline constexpr EnumNames<CellType, 11> kCellTypeNames{{
    {CellType::Line2, "line2"},
    {CellType::Line3, "line3"},
    {CellType::Tri3, "tri3"},
    {CellType::Tri6, "tri6"},
    {CellType::Quad4, "quad4"},
    {CellType::Quad8, "quad8"},
    {CellType::Quad9, "quad9"},
    {CellType::Tet4, "tet4"},
    {CellType::Tet10, "tet10"},
    {CellType::Hex8, "hex8"},
    {CellType::Hex27, "hex27"},
}};

/// Spatial dimension of the reference cell (1 for lines, which are the facets of 2D cells).
constexpr int cell_dimension(CellType t) {
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      return 1;
    case CellType::Tri3:
    case CellType::Tri6:
    case CellType::Quad4:
    case CellType::Quad8:
    case CellType::Quad9:
      return 2;
    case CellType::Tet4:
    case CellType::Tet10:
    case CellType::Hex8:
    case CellType::Hex27:
      return 3;
  }
  return 0;
}

/// Number of nodes of a cell.
constexpr int nodes_per_cell(CellType t) {
  switch (t) {
    case CellType::Line2:
      return 2;
    case CellType::Line3:
    case CellType::Tri3:
      return 3;
    case CellType::Tri6:
      return 6;
    case CellType::Quad4:
    case CellType::Tet4:
      return 4;
    case CellType::Quad8:
    case CellType::Hex8:
      return 8;
    case CellType::Quad9:
      return 9;
    case CellType::Tet10:
      return 10;
    case CellType::Hex27:
      return 27;
  }
  return 0;
}

/// Polynomial order of the geometry and of the displacement (1: linear, 2: quadratic).
constexpr int cell_order(CellType t) {
  switch (t) {
    case CellType::Line3:
    case CellType::Tri6:
    case CellType::Quad8:
    case CellType::Quad9:
    case CellType::Tet10:
    case CellType::Hex27:
      return 2;
    default:
      return 1;
  }
}

/// Number of corners of a cell: its first nodes, the nodes of the first-order cell of its shape.
constexpr int corners_per_cell(CellType t) {
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      return 2;
    case CellType::Tri3:
    case CellType::Tri6:
      return 3;
    case CellType::Quad4:
    case CellType::Quad8:
    case CellType::Quad9:
    case CellType::Tet4:
    case CellType::Tet10:
      return 4;
    case CellType::Hex8:
    case CellType::Hex27:
      return 8;
  }
  return 0;
}

/// Number of facets (end points of lines, edges in 2D, faces in 3D) of a cell.
constexpr int facets_per_cell(CellType t) {
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      return 2;
    case CellType::Tri3:
    case CellType::Tri6:
      return 3;
    case CellType::Quad4:
    case CellType::Quad8:
    case CellType::Quad9:
      return 4;
    case CellType::Tet4:
    case CellType::Tet10:
      return 4;
    case CellType::Hex8:
    case CellType::Hex27:
      return 6;
  }
  return 0;
}

/// The cell type of the facets of a 2D or 3D cell (Line2 for linear 2D cells, Line3 for
/// quadratic ones). Lines have no facet type; asking is a logic error.
CellType facet_type(CellType t);

/// Local node numbers of facet `f` of a cell, ordered so that the facet's outward normal follows
/// from the right-hand rule (counterclockwise cells in 2D: edge (a, b) has outward normal
/// (t_y, -t_x) with t = x_b - x_a). Quadratic edges list their two ends, then the middle node
/// (the Line3 order).
std::span<const int> facet_local_nodes(CellType t, int facet);

}  // namespace signorini

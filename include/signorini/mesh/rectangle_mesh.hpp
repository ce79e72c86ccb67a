#pragma once
// Structured mesh of a rectangle by nx x ny quadrilaterals (the paper's benchmark mesh, Section 5,
// with Q1 cells), or by 2 nx ny triangles, of first or second order, with the four edges named
// `left`, `right`, `bottom`, `top`.

#include "signorini/mesh/cell_type.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The cell types a rectangle can be made of (RectangleMeshOptions::cell).
inline constexpr EnumNames<CellType, 5> kRectangleCellNames{{
    {CellType::Quad4, "quad4"},
    {CellType::Quad8, "quad8"},
    {CellType::Quad9, "quad9"},
    {CellType::Tri3, "tri3"},
    {CellType::Tri6, "tri6"},
}};

struct RectangleMeshOptions {
  double x0 = 0.0;      ///< lower-left corner, x (m)
  double y0 = 0.0;      ///< lower-left corner, y (m)
  double length = 3.0;  ///< extent in x (m)
  double height = 1.0;  ///< extent in y (m)
  Index nx = 60;        ///< cells along x, >= 1
  Index ny = 20;        ///< cells along y, >= 1
  /// quad4 (the paper's), quad8, quad9, or tri3 / tri6: each square split into two triangles
  /// along its diagonal from lower left to upper right.
  CellType cell = CellType::Quad4;
};

/// Quad4: node (i, j) has number j * (nx + 1) + i; cell (i, j) has number j * nx + i and its
/// nodes are counterclockwise. The other types number the nodes of the (order nx + 1) x (order
/// ny + 1) lattice row by row, leaving out the cell centres that Quad8 does not use; triangles
/// (i, j) are cells 2 (j nx + i) (below the diagonal) and 2 (j nx + i) + 1. Boundary facets are
/// listed in increasing x (bottom, top) or y (left, right). Throws InputError on non-positive
/// sizes or a cell type that is not a 2D one.
Mesh make_rectangle_mesh(const RectangleMeshOptions& options);

}  // namespace signorini

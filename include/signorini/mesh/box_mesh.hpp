#pragma once
// Structured mesh of a box by nx x ny x nz hexahedra, or by 6 nx ny nz tetrahedra, of first or
// second order, with the six sides named `xmin`, `xmax`, `ymin`, `ymax`, `zmin`, `zmax`: the 3D
// counterpart of rectangle_mesh.hpp.

#include <array>
#include <vector>

#include "signorini/mesh/cell_type.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The cell types a box can be made of (BoxMeshOptions::cell).
inline constexpr EnumNames<CellType, 4> kBoxCellNames{{
    {CellType::Hex8, "hex8"},
    {CellType::Hex27, "hex27"},
    {CellType::Tet4, "tet4"},
    {CellType::Tet10, "tet10"},
}};

struct BoxMeshOptions {
  double x0 = 0.0;      ///< corner with the smallest coordinates, x (m)
  double y0 = 0.0;      ///< same, y (m)
  double z0 = 0.0;      ///< same, z (m)
  double length = 1.0;  ///< extent in x (m)
  double width = 1.0;   ///< extent in y (m)
  double height = 1.0;  ///< extent in z (m)
  Index nx = 4;         ///< cells along x, >= 1
  Index ny = 4;         ///< cells along y, >= 1
  Index nz = 4;         ///< cells along z, >= 1
  /// hex8, hex27, or tet4 / tet10: each cube split into six tetrahedra around its diagonal from
  /// (x0, y0, z0) towards (x0 + length, y0 + width, z0 + height).
  CellType cell = CellType::Hex8;
};

/// Hex8: node (i, j, k) has number i + (nx + 1) (j + (ny + 1) k); cell (i, j, k) has number
/// i + nx (j + ny k), its nodes in the Hex8 order (bottom z counterclockwise seen from +z, then
/// the top). Hex27 numbers the (2 nx + 1) x (2 ny + 1) x (2 nz + 1) lattice the same way. Tet4
/// and Tet10: cube (i, j, k) is cut into tetrahedra 6 (i + nx (j + ny k)) + 0..5, the Kuhn
/// subdivision (the same in every cube, hence conforming), each positively oriented; Tet10 takes
/// its mid-edge nodes from the Hex27 lattice, numbered as there with any unused point left out.
/// Boundary facets are listed cube by cube, k, j, i loops (outer to inner), then by cell and
/// local facet. Throws InputError on non-positive sizes or counts or a cell type that is not a 3D
/// one.
Mesh make_box_mesh(const BoxMeshOptions& options);

/// The cubes first[a] <= i_a < end[a] of the box (along x, y, z) as a mesh of their own: a
/// rank's part of a box made in parts (docs/distributed.md). Its nodes are the lattice points of
/// those cubes in increasing order of their numbers in the whole box (global_nodes), with the
/// whole box's coordinates to the bit; its cells are the cubes' cells in the whole box's order
/// (global_cells: their numbers there), and its six sides the facets of the whole box's sides
/// that lie in the part (empty where it does not reach a side), in the whole box's order.
/// make_box_mesh is the part of all the cubes. Throws InputError as make_box_mesh does.
struct BoxMeshPart {
  Mesh mesh;
  std::vector<Index> global_nodes;
  std::vector<Index> global_cells;
};
BoxMeshPart make_box_mesh_part(const BoxMeshOptions& options, const std::array<Index, 3>& first,
                               const std::array<Index, 3>& end);

}  // namespace signorini

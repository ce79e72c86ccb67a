#pragma once
// The orientation of a cell given by its nodes: 2D cells turned counterclockwise (their node
// order mirrored where a mesh generator or a user gave them clockwise), and the sign of det J at
// the corners of a 3D cell, so that a cell turned inside out never reaches the assembly as a
// negative stiffness. Shared by the Gmsh reader and meshes given as arrays.

#include "signorini/core/types.hpp"
#include "signorini/mesh/cell_type.hpp"

namespace signorini {

/// Mirrors the node order of a 2D cell (corners and mid-edge nodes alike), turning it from
/// clockwise to counterclockwise or back; other types are left as they are.
void mirror_cell(CellType t, Index* nodes);

/// Twice the signed area of a 2D cell's corner polygon (shoelace): negative when clockwise.
double signed_corner_area2(CellType t, const Index* nodes, const Eigen::MatrixXd& x);

/// The smallest det J at the corners of a 3D cell, up to a positive factor: the triple product
/// of the edges from each corner (one for a tetrahedron, whose det J is constant; for a
/// hexahedron each corner with its neighbours along xi, eta, zeta, taken right-handed).
double min_corner_det(CellType t, const Index* nodes, const Eigen::MatrixXd& x);

}  // namespace signorini

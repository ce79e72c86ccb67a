#pragma once
// Boundary elements named by their nodes (a line in 2D, a triangle or quadrilateral in 3D, as a
// Gmsh file or a user's arrays give them) matched to the facets of the mesh's cells: a facet is
// known by its sorted corners, the same from both cells it bounds and from the boundary element
// on it, whatever their node orders. Shared by the Gmsh reader and meshes given as arrays.

#include <optional>
#include <span>
#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// One boundary element: its nodes, corners first (its other nodes, where it has them, must be
/// the facet's other nodes).
struct BoundaryElement {
  std::span<const Index> nodes;
  int corners = 0;
};

/// For each element the facet of a cell it lies on (the first cell found, so the one cell of a
/// boundary facet), oriented with the cell; nullopt where no cell has a facet with those corners,
/// or where a second-order element's nodes are not the facet's.
std::vector<std::optional<Facet>> match_facets(const Mesh& mesh,
                                               const std::vector<BoundaryElement>& elements);

/// How many corners a boundary element of `nodes` nodes has in a mesh of dimension `dim`: 2 for
/// lines (2 or 3 nodes), 3 for triangles (3 or 6), 4 for quadrilaterals (4, 8 or 9); 0 for a
/// count that fits none.
int boundary_element_corners(int dim, int nodes);

}  // namespace signorini

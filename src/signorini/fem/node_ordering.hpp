#pragma once
// An order of a mesh's nodes that keeps neighbours close in memory: the Z-order (Morton) curve
// through the nodes' coordinates. A sparse product reads the vector at the columns of each row;
// in the order of a mesh generator those lie anywhere in a vector of millions of values, in
// Z-order mostly within a few cache lines of the row's own. On Hertz's ball of 940,094 unknowns
// (a Gmsh mesh of tetrahedra) a CG iteration took a third less time (docs/performance.md,
// "Unknowns in Z-order").

#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The nodes along the Z-order curve of their coordinates in the mesh's bounding box (21 bits
/// per axis; ties in the order of the nodes): a permutation of 0 .. num_nodes-1.
[[nodiscard]] std::vector<Index> z_order(const Mesh& mesh);

}  // namespace signorini

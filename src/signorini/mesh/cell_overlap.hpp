#pragma once
// Cells that cover the same ground: a cell that names a node twice (collapsed), two cells with
// the same corners (doubled), and two cells on the same side of a facet they share, or a facet
// shared by three cells (overlapping or folded). Any of them counts the stiffness of that ground
// twice or not at all and still assembles, so a mesh from a file or from a user's arrays is
// refused with it. Shared by the Gmsh reader and meshes given as arrays.
//
// Why facets: in a conforming mesh each facet bounds one cell (on the boundary) or two, which
// see it turned opposite ways (their outward normals opposed). A doubled cell repeats every
// facet the same way; a cell folded over its neighbour, or laid over part of another with a
// facet in common, repeats that facet the same way. Cells that overlap without sharing a facet
// (two separate meshes laid over each other) are not found: that needs a geometric search.

#include <functional>
#include <string>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// Throws InputError, "<what>: cell 7 names node 3 twice (a collapsed cell): ..." and the like,
/// for the first collapsed cell, or the first pair of doubled or overlapping cells. `cell_name`
/// gives a cell's name in messages ("element 12" for a Gmsh file's tag, "cell 3" for an index).
void check_cells_do_not_overlap(const Mesh& mesh, const std::string& what,
                                const std::function<std::string(Index cell)>& cell_name);

}  // namespace signorini

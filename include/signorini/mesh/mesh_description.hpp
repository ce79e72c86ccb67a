#pragma once
// A one-line account of a mesh, for `signorini check` and messages: how many nodes and cells of
// which types, its regions, and its boundary parts with their node counts, so that a user sees
// what a mesh file turned into (and which names a problem file can use).

#include <string>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// "1281 nodes, 1200 cells (quad4: 1200); boundary parts: bottom (61 nodes), left (21 nodes)";
/// regions are listed where a cell has a named one.
std::string mesh_description(const Mesh& mesh);

}  // namespace signorini

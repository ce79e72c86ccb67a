#pragma once
// Structured mesh of a rectangle by nx x ny Q1 quadrilaterals, with the four edges named
// `left`, `right`, `bottom`, `top` (the paper's benchmark mesh, Section 5).

#include "signorini/mesh/mesh.hpp"

namespace signorini {

struct RectangleMeshOptions {
  double x0 = 0.0;      ///< lower-left corner, x (m)
  double y0 = 0.0;      ///< lower-left corner, y (m)
  double length = 3.0;  ///< extent in x (m)
  double height = 1.0;  ///< extent in y (m)
  Index nx = 60;        ///< cells along x, >= 1
  Index ny = 20;        ///< cells along y, >= 1
};

/// Node (i, j) has number j * (nx + 1) + i; cell (i, j) has number j * nx + i and its nodes are
/// counterclockwise. Boundary facets are listed in increasing x (bottom, top) or y (left, right).
/// Throws InputError on non-positive sizes.
Mesh make_rectangle_mesh(const RectangleMeshOptions& options);

}  // namespace signorini

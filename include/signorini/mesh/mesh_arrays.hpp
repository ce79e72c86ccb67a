#pragma once
// A mesh given as arrays by a program (the Python package's signorini.Mesh, a mesh made with
// meshio or Gmsh's Python API, a C++ caller's own generator): the points, blocks of cells of one
// type each, optionally a region per block, and named boundary parts given by the nodes of their
// facets (lines in 2D; triangles or quadrilaterals in 3D). Node orders are Gmsh's
// (mesh/cell_type.hpp). What the Gmsh reader checks is checked here, in one line naming the
// block and the cell, or the boundary part and the facet, by their positions in the arrays.

#include <string>
#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// Cells of one type: nodes_per_cell(type) node numbers per cell, cell after cell.
struct CellBlock {
  CellType type = CellType::Tri3;
  std::vector<Index> nodes;
  /// The region of its cells, for materials per region ([[region]] name); "" for none.
  std::string region;
};

/// A named boundary part: facets of `nodes_per_facet` nodes each (corners first: 2 or 3 for a
/// line, 3 or 6 for a triangle, 4, 8 or 9 for a quadrilateral), facet after facet.
struct BoundaryFacets {
  std::string name;
  int nodes_per_facet = 2;
  std::vector<Index> nodes;
};

struct MeshArrays {
  /// dim x num_points (dim 2 or 3; 2D cells on three rows with one constant z make a 2D mesh).
  Eigen::MatrixXd points;
  std::vector<CellBlock> blocks;
  std::vector<BoundaryFacets> boundaries;
};

/// The mesh of the arrays. Throws InputError ("mesh: ...") on: a dimension other than 2 or 3, a
/// coordinate that is not finite, a cell type of another dimension than the points, a node
/// number out of range, a point that no cell uses (it would have no stiffness), a 3D cell
/// inverted or degenerate (det J <= 0 at a corner), a 2D cell of zero area, a boundary facet
/// that is no facet of any cell, an empty or repeated boundary name, no cells. 2D cells given
/// clockwise are turned counterclockwise (their node order mirrored), as the Gmsh reader does.
/// Cells keep the order of the blocks, and boundary facets the order given.
Mesh mesh_from_arrays(const MeshArrays& arrays);

}  // namespace signorini

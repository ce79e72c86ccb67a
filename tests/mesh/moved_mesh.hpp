#pragma once
// A mesh with the cells and boundary parts of another and new node coordinates, for tests that
// distort a structured mesh (patch tests on irregular cells).

#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini::testing {

inline Mesh with_coordinates(const Mesh& grid, Eigen::MatrixXd coordinates) {
  std::vector<CellType> types;
  std::vector<Index> cells;
  for (Index c = 0; c < grid.num_cells(); ++c) {
    types.push_back(grid.cell_type(c));
    for (const Index v : grid.cell(c)) cells.push_back(v);
  }
  Mesh mesh(types, std::move(coordinates), cells);
  for (const auto& name : grid.boundary_part_names())
    mesh.set_boundary_part(name, grid.boundary_part(name).facets);
  return mesh;
}

}  // namespace signorini::testing

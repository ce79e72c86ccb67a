#include "signorini/mesh/rectangle_mesh.hpp"

#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {

Mesh make_rectangle_mesh(const RectangleMeshOptions& o) {
  if (o.nx < 1 || o.ny < 1)
    throw InputError("rectangle mesh: nx and ny must be >= 1 (got " + std::to_string(o.nx) + " x " +
                     std::to_string(o.ny) + ")");
  if (!(o.length > 0.0) || !(o.height > 0.0) || !std::isfinite(o.length) ||
      !std::isfinite(o.height))
    throw InputError("rectangle mesh: length and height must be positive and finite");
  const CellType t = o.cell;
  if (cell_dimension(t) != 2)
    throw InputError("rectangle mesh: cell type '" +
                     std::string(enum_to_string(kCellTypeNames, t)) +
                     "' is not a 2D cell (expected quad4, quad8, quad9, tri3 or tri6)");
  // Cells on the lattice of order p (the grid of nodes itself for linear cells); only Quad8
  // leaves lattice points unused (the cell centres), which are then numbered out.
  const Index p = cell_order(t);
  const Index mx = p * o.nx + 1, my = p * o.ny + 1;
  const auto L = [mx](Index I, Index J) { return J * mx + I; };
  const bool triangles = t == CellType::Tri3 || t == CellType::Tri6;
  const Index per_square = triangles ? 2 : 1;
  std::vector<Index> cells;
  cells.reserve(static_cast<std::size_t>(o.nx * o.ny * per_square * nodes_per_cell(t)));
  for (Index j = 0; j < o.ny; ++j)
    for (Index i = 0; i < o.nx; ++i) {
      const Index I = p * i, J = p * j;
      const Index c00 = L(I, J), c10 = L(I + p, J), c11 = L(I + p, J + p), c01 = L(I, J + p);
      if (t == CellType::Tri3) {
        cells.insert(cells.end(), {c00, c10, c11, c00, c11, c01});
      } else if (t == CellType::Tri6) {
        cells.insert(cells.end(), {c00, c10, c11, L(I + 1, J), L(I + 2, J + 1), L(I + 1, J + 1)});
        cells.insert(cells.end(), {c00, c11, c01, L(I + 1, J + 1), L(I + 1, J + 2), L(I, J + 1)});
      } else {
        cells.insert(cells.end(), {c00, c10, c11, c01});
        if (p == 2)
          cells.insert(cells.end(), {L(I + 1, J), L(I + 2, J + 1), L(I + 1, J + 2), L(I, J + 1)});
        if (t == CellType::Quad9) cells.push_back(L(I + 1, J + 1));
      }
    }
  std::vector<Index> number;  // lattice point -> node, where not the identity
  Index count = mx * my;
  if (t == CellType::Quad8) {
    number.assign(static_cast<std::size_t>(mx * my), -1);
    for (const Index v : cells) number[static_cast<std::size_t>(v)] = 0;
    count = 0;
    for (Index& n : number)
      if (n == 0) n = count++;
    for (Index& v : cells) v = number[static_cast<std::size_t>(v)];
  }
  Eigen::MatrixXd xy(2, count);
  for (Index J = 0; J < my; ++J)
    for (Index I = 0; I < mx; ++I) {
      const Index n = number.empty() ? L(I, J) : number[static_cast<std::size_t>(L(I, J))];
      if (n < 0) continue;
      // Multiply before dividing so that the far edges land exactly on x0 + length, y0 + height.
      xy(0, n) = o.x0 + o.length * static_cast<double>(I) / static_cast<double>(mx - 1);
      xy(1, n) = o.y0 + o.height * static_cast<double>(J) / static_cast<double>(my - 1);
    }
  Mesh mesh(t, std::move(xy), std::move(cells));

  std::vector<Facet> bottom, top, left, right;
  const auto cell = [&](Index i, Index j, Index k) { return per_square * (j * o.nx + i) + k; };
  for (Index i = 0; i < o.nx; ++i) {
    bottom.push_back({cell(i, 0, 0), 0});
    top.push_back(triangles ? Facet{cell(i, o.ny - 1, 1), 1} : Facet{cell(i, o.ny - 1, 0), 2});
  }
  for (Index j = 0; j < o.ny; ++j) {
    left.push_back(triangles ? Facet{cell(0, j, 1), 2} : Facet{cell(0, j, 0), 3});
    right.push_back({cell(o.nx - 1, j, 0), 1});
  }
  mesh.set_boundary_part("bottom", std::move(bottom));
  mesh.set_boundary_part("top", std::move(top));
  mesh.set_boundary_part("left", std::move(left));
  mesh.set_boundary_part("right", std::move(right));
  return mesh;
}

}  // namespace signorini

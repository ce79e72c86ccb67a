#include "signorini/mesh/box_mesh.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// A node's place in its cube in half edges (0, 1, 2 along x, y, z), so that corners, mid-edge
// nodes and centres of all four cell types are integers.
using Offset = std::array<int, 3>;

// The Hex27 nodes in Gmsh's order (cell_type.hpp); the first eight are the Hex8 corners.
constexpr std::array<Offset, 27> kHexNodes{{
    {0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2},  //
    {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {2, 1, 0}, {2, 0, 1}, {1, 2, 0},                        //
    {2, 2, 1}, {0, 2, 1}, {1, 0, 2}, {0, 1, 2}, {2, 1, 2}, {1, 2, 2},                        //
    {1, 1, 0}, {1, 0, 1}, {0, 1, 1}, {2, 1, 1}, {1, 2, 1}, {1, 1, 2}, {1, 1, 1},
}};

// Kuhn subdivision: one tetrahedron per order of the axes, the path from corner 0 to corner 6
// along one edge of each axis in turn. Its volume has the sign of the permutation, so the odd
// ones list their middle corners swapped to be positive. Every cube cut the same way: the
// diagonals of a shared face agree, and so the mesh is conforming.
constexpr std::array<std::array<int, 4>, 6> kKuhnTets{{
    {0, 1, 2, 6},  // x, y, z
    {0, 3, 7, 6},  // y, z, x
    {0, 4, 5, 6},  // z, x, y
    {0, 5, 1, 6},  // x, z, y (odd)
    {0, 2, 3, 6},  // y, x, z (odd)
    {0, 7, 4, 6},  // z, y, x (odd)
}};

// Tet10 mid-edge nodes (cell_type.hpp): on the edges 0-1, 1-2, 2-0, 0-3, 2-3, 1-3.
constexpr std::array<std::array<int, 2>, 6> kTet10Edges{
    {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {2, 3}, {1, 3}}};

// The cells one cube is cut into, each as the offsets of its nodes in the order of its type.
std::vector<std::vector<Offset>> cube_cells(CellType t) {
  std::vector<std::vector<Offset>> out;
  if (t == CellType::Hex8 || t == CellType::Hex27) {
    out.emplace_back(kHexNodes.begin(), kHexNodes.begin() + nodes_per_cell(t));
    return out;
  }
  for (const auto& tet : kKuhnTets) {
    std::vector<Offset>& cell = out.emplace_back();
    for (const int c : tet) cell.push_back(kHexNodes[static_cast<std::size_t>(c)]);
    if (t == CellType::Tet10)
      for (const auto& [a, b] : kTet10Edges) {
        const Offset p = cell[static_cast<std::size_t>(a)];  // copies: push_back may move them
        const Offset q = cell[static_cast<std::size_t>(b)];
        cell.push_back({(p[0] + q[0]) / 2, (p[1] + q[1]) / 2, (p[2] + q[2]) / 2});
      }
  }
  return out;
}

}  // namespace

Mesh make_box_mesh(const BoxMeshOptions& o) {
  if (o.nx < 1 || o.ny < 1 || o.nz < 1)
    throw InputError("box mesh: nx, ny and nz must be >= 1 (got " + std::to_string(o.nx) + " x " +
                     std::to_string(o.ny) + " x " + std::to_string(o.nz) + ")");
  for (const double s : {o.length, o.width, o.height})
    if (!(s > 0.0) || !std::isfinite(s))
      throw InputError("box mesh: length, width and height must be positive and finite");
  const CellType t = o.cell;
  if (cell_dimension(t) != 3)
    throw InputError("box mesh: cell type '" + std::string(enum_to_string(kCellTypeNames, t)) +
                     "' is not a 3D cell (expected hex8, hex27, tet4 or tet10)");
  // Cells on the lattice of order p (the grid of nodes itself for linear cells).
  const Index p = cell_order(t);
  const std::array<Index, 3> n{o.nx, o.ny, o.nz};
  const Index mx = p * o.nx + 1, my = p * o.ny + 1, mz = p * o.nz + 1;
  const auto L = [mx, my](Index I, Index J, Index K) { return I + mx * (J + my * K); };
  const std::vector<std::vector<Offset>> per_cube = cube_cells(t);
  const auto cells_per_cube = static_cast<Index>(per_cube.size());
  std::vector<Index> cells;
  cells.reserve(static_cast<std::size_t>(o.nx * o.ny * o.nz * cells_per_cube * nodes_per_cell(t)));
  for (Index k = 0; k < o.nz; ++k)
    for (Index j = 0; j < o.ny; ++j)
      for (Index i = 0; i < o.nx; ++i)
        for (const auto& cell : per_cube)
          for (const Offset& d : cell)  // half edges to lattice steps: times p / 2
            cells.push_back(L(p * i + d[0] * p / 2, p * j + d[1] * p / 2, p * k + d[2] * p / 2));
  // Lattice points no cell uses are numbered out (none with the cells above, but the numbering
  // must not depend on that).
  std::vector<Index> number(static_cast<std::size_t>(mx * my * mz), -1);
  for (const Index v : cells) number[static_cast<std::size_t>(v)] = 0;
  Index count = 0;
  for (Index& v : number)
    if (v == 0) v = count++;
  for (Index& v : cells) v = number[static_cast<std::size_t>(v)];
  Eigen::MatrixXd xyz(3, count);
  for (Index K = 0; K < mz; ++K)
    for (Index J = 0; J < my; ++J)
      for (Index I = 0; I < mx; ++I) {
        const Index v = number[static_cast<std::size_t>(L(I, J, K))];
        if (v < 0) continue;
        // Multiply before dividing so that the far sides land exactly on x0 + length etc.
        xyz(0, v) = o.x0 + o.length * static_cast<double>(I) / static_cast<double>(mx - 1);
        xyz(1, v) = o.y0 + o.width * static_cast<double>(J) / static_cast<double>(my - 1);
        xyz(2, v) = o.z0 + o.height * static_cast<double>(K) / static_cast<double>(mz - 1);
      }
  Mesh mesh(t, std::move(xyz), std::move(cells));

  // Side s lies on axis s / 2, at the low (even s) or high end: the cubes of that layer, and in
  // each the faces whose nodes all lie on the cube's side.
  constexpr std::array<const char*, 6> kSides{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (std::size_t s = 0; s < kSides.size(); ++s) {
    const std::size_t axis = s / 2;
    const bool high = s % 2 == 1;
    std::array<Index, 3> lo{0, 0, 0}, hi = n;
    lo[axis] = high ? n[axis] - 1 : 0;
    hi[axis] = lo[axis] + 1;
    std::vector<Facet> facets;
    for (Index k = lo[2]; k < hi[2]; ++k)
      for (Index j = lo[1]; j < hi[1]; ++j)
        for (Index i = lo[0]; i < hi[0]; ++i)
          for (Index c = 0; c < cells_per_cube; ++c) {
            const auto& cell = per_cube[static_cast<std::size_t>(c)];
            for (int f = 0; f < facets_per_cell(t); ++f) {
              bool on_side = true;
              for (const int v : facet_local_nodes(t, f))
                on_side = on_side && cell[static_cast<std::size_t>(v)][axis] == (high ? 2 : 0);
              if (on_side) facets.push_back({(i + o.nx * (j + o.ny * k)) * cells_per_cube + c, f});
            }
          }
    mesh.set_boundary_part(kSides[s], std::move(facets));
  }
  return mesh;
}

}  // namespace signorini

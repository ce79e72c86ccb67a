#include "signorini/mesh/box_mesh.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
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

namespace {

void validate_box(const BoxMeshOptions& o) {
  if (o.nx < 1 || o.ny < 1 || o.nz < 1)
    throw InputError("box mesh: nx, ny and nz must be >= 1 (got " + std::to_string(o.nx) + " x " +
                     std::to_string(o.ny) + " x " + std::to_string(o.nz) + ")");
  for (const double s : {o.length, o.width, o.height})
    if (!(s > 0.0) || !std::isfinite(s))
      throw InputError("box mesh: length, width and height must be positive and finite");
  if (cell_dimension(o.cell) != 3)
    throw InputError("box mesh: cell type '" + std::string(enum_to_string(kCellTypeNames, o.cell)) +
                     "' is not a 3D cell (expected hex8, hex27, tet4 or tet10)");
}

}  // namespace

Mesh make_box_mesh(const BoxMeshOptions& o) {
  return std::move(make_box_mesh_part(o, {0, 0, 0}, {o.nx, o.ny, o.nz}).mesh);
}

BoxMeshPart make_box_mesh_part(const BoxMeshOptions& o, const std::array<Index, 3>& first,
                               const std::array<Index, 3>& end) {
  validate_box(o);
  const std::array<Index, 3> n{o.nx, o.ny, o.nz};
  for (std::size_t a = 0; a < 3; ++a)
    if (first[a] < 0 || end[a] > n[a] || first[a] >= end[a])
      throw std::logic_error("make_box_mesh_part: an empty or outside range of cubes");
  const CellType t = o.cell;
  // Cells on the lattice of order p (the grid of nodes itself for linear cells): the whole
  // box's lattice is M[a] points along axis a, the part's the m[a] points from lattice point
  // p first[a] on.
  const Index p = cell_order(t);
  const std::array<Index, 3> M{p * o.nx + 1, p * o.ny + 1, p * o.nz + 1};
  std::array<Index, 3> m{}, I0{};
  for (std::size_t a = 0; a < 3; ++a) {
    I0[a] = p * first[a];
    m[a] = p * (end[a] - first[a]) + 1;
  }
  // (I, J, K) of the part's lattice, counted from I0.
  const auto L = [&m](Index I, Index J, Index K) { return I + m[0] * (J + m[1] * K); };
  const std::vector<std::vector<Offset>> per_cube = cube_cells(t);
  const auto cells_per_cube = static_cast<Index>(per_cube.size());
  std::vector<Index> global_nodes, global_cells;
  std::vector<Index> cells;
  const Index cubes = (end[0] - first[0]) * (end[1] - first[1]) * (end[2] - first[2]);
  cells.reserve(static_cast<std::size_t>(cubes * cells_per_cube * nodes_per_cell(t)));
  global_cells.reserve(static_cast<std::size_t>(cubes * cells_per_cube));
  for (Index k = first[2]; k < end[2]; ++k)
    for (Index j = first[1]; j < end[1]; ++j)
      for (Index i = first[0]; i < end[0]; ++i)
        for (Index c = 0; c < cells_per_cube; ++c) {
          global_cells.push_back((i + o.nx * (j + o.ny * k)) * cells_per_cube + c);
          for (const Offset& d : per_cube[static_cast<std::size_t>(c)])  // half edges: p / 2
            cells.push_back(L(p * (i - first[0]) + d[0] * p / 2, p * (j - first[1]) + d[1] * p / 2,
                              p * (k - first[2]) + d[2] * p / 2));
        }
  // Every lattice point is a node of some cell with these four types (Tet10 uses each cube's
  // 27 points: its edges, the diagonals of its faces and its own), so that the whole box's node
  // (I, J, K) is number I + M0 (J + M1 K) and a part's nodes are numbered as in the whole.
  std::vector<bool> used(static_cast<std::size_t>(m[0] * m[1] * m[2]), false);
  for (const Index v : cells) used[static_cast<std::size_t>(v)] = true;
  if (std::find(used.begin(), used.end(), false) != used.end())
    throw std::logic_error("make_box_mesh_part: a lattice point without a cell");
  Eigen::MatrixXd xyz(3, m[0] * m[1] * m[2]);
  global_nodes.reserve(static_cast<std::size_t>(xyz.cols()));
  for (Index K = 0; K < m[2]; ++K)
    for (Index J = 0; J < m[1]; ++J)
      for (Index I = 0; I < m[0]; ++I) {
        const Index v = L(I, J, K);
        const Index gI = I0[0] + I, gJ = I0[1] + J, gK = I0[2] + K;
        global_nodes.push_back(gI + M[0] * (gJ + M[1] * gK));
        // Multiply before dividing so that the far sides land exactly on x0 + length etc.
        xyz(0, v) = o.x0 + o.length * static_cast<double>(gI) / static_cast<double>(M[0] - 1);
        xyz(1, v) = o.y0 + o.width * static_cast<double>(gJ) / static_cast<double>(M[1] - 1);
        xyz(2, v) = o.z0 + o.height * static_cast<double>(gK) / static_cast<double>(M[2] - 1);
      }
  Mesh mesh(t, std::move(xyz), std::move(cells));

  // Side s lies on axis s / 2, at the low (even s) or high end: the cubes of that layer within
  // the part, and in each the faces whose nodes all lie on the cube's side.
  constexpr std::array<const char*, 6> kSides{"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"};
  for (std::size_t s = 0; s < kSides.size(); ++s) {
    const std::size_t axis = s / 2;
    const bool high = s % 2 == 1;
    std::array<Index, 3> lo = first, hi = end;
    lo[axis] = std::max(first[axis], high ? n[axis] - 1 : 0);
    hi[axis] = std::min(end[axis], high ? n[axis] : 1);
    std::vector<Facet> facets;
    for (Index k = lo[2]; k < hi[2]; ++k)
      for (Index j = lo[1]; j < hi[1]; ++j)
        for (Index i = lo[0]; i < hi[0]; ++i)
          for (Index c = 0; c < cells_per_cube; ++c) {
            const auto& cell = per_cube[static_cast<std::size_t>(c)];
            const Index local_cube =
                (i - first[0]) +
                (end[0] - first[0]) * ((j - first[1]) + (end[1] - first[1]) * (k - first[2]));
            for (int f = 0; f < facets_per_cell(t); ++f) {
              bool on_side = true;
              for (const int v : facet_local_nodes(t, f))
                on_side = on_side && cell[static_cast<std::size_t>(v)][axis] == (high ? 2 : 0);
              if (on_side) facets.push_back({local_cube * cells_per_cube + c, f});
            }
          }
    mesh.set_boundary_part(kSides[s], std::move(facets));
  }
  return {std::move(mesh), std::move(global_nodes), std::move(global_cells)};
}

}  // namespace signorini

#pragma once
// Geometry of 3D cells and their facets by plain vector algebra on the corners, for the mesh
// tests: the orientation (det J at the corners, up to a positive factor), volumes, facet normals
// and areas. Written apart from the library so that a test checks it rather than repeats it.

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <vector>

#include "signorini/mesh/mesh.hpp"

namespace signorini::testing {

inline double triple(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  return a.dot(b.cross(c));
}

/// The triple products of the edges at the corners of a tetrahedron (one) or hexahedron (each
/// corner with its neighbours along x, y, z of the reference cell, taken right-handed): all
/// positive for a positively oriented cell.
inline std::vector<double> corner_dets(const Mesh& m, Index c) {
  const auto v = m.cell(c);
  const auto x = [&](int k) { return m.point(v[static_cast<std::size_t>(k)]); };
  if (corners_per_cell(m.cell_type(c)) == 4) return {triple(x(1) - x(0), x(2) - x(0), x(3) - x(0))};
  static constexpr std::array<std::array<int, 4>, 8> kHexCorners{{{0, 1, 3, 4},
                                                                  {1, 2, 0, 5},
                                                                  {2, 3, 1, 6},
                                                                  {3, 0, 2, 7},
                                                                  {4, 7, 5, 0},
                                                                  {5, 4, 6, 1},
                                                                  {6, 5, 7, 2},
                                                                  {7, 6, 4, 3}}};
  std::vector<double> out;
  for (const auto& [a, b, d, e] : kHexCorners)
    out.push_back(triple(x(b) - x(a), x(d) - x(a), x(e) - x(a)));
  return out;
}

/// Volume of a tetrahedron, or of a hexahedron with plane faces (cut into six tetrahedra around
/// its diagonal from corner 0 to corner 6, whose faces lie on the hexahedron's).
inline double cell_volume(const Mesh& m, Index c) {
  const auto v = m.cell(c);
  const auto x = [&](int k) { return m.point(v[static_cast<std::size_t>(k)]); };
  const auto tet = [&](int a, int b, int d, int e) {
    return triple(x(b) - x(a), x(d) - x(a), x(e) - x(a)) / 6.0;
  };
  if (corners_per_cell(m.cell_type(c)) == 4) return tet(0, 1, 2, 3);
  return tet(0, 1, 2, 6) + tet(0, 3, 7, 6) + tet(0, 4, 5, 6) + tet(0, 5, 1, 6) + tet(0, 2, 3, 6) +
         tet(0, 7, 4, 6);
}

/// The normal of a facet by the right-hand rule on its first three corners (outward for the
/// facets of a positively oriented cell), not normalised.
inline Eigen::Vector3d facet_normal(const Mesh& m, const Facet& f) {
  const auto v = m.facet_nodes(f);
  const Eigen::Vector3d a = m.point(v[0]);
  return (m.point(v[1]) - a).cross(m.point(v[2]) - a);
}

/// Area of a triangle or of a plane quadrilateral (half the cross product of its diagonals).
inline double facet_area(const Mesh& m, const Facet& f) {
  const auto v = m.facet_nodes(f);
  if (corners_per_cell(facet_type(m.cell_type(f.cell))) == 3)
    return 0.5 * facet_normal(m, f).norm();
  return 0.5 * (m.point(v[2]) - m.point(v[0])).cross(m.point(v[3]) - m.point(v[1])).norm();
}

/// For each mid-edge, mid-face and centre node of a second-order cell type (in order, after the
/// corners), the corners it lies in the middle of (Gmsh's node orders, cell_type.hpp).
inline std::vector<std::vector<int>> middle_nodes_of(CellType t) {
  if (t == CellType::Tet10) return {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {2, 3}, {1, 3}};
  if (t == CellType::Hex27)
    return {{0, 1},
            {0, 3},
            {0, 4},
            {1, 2},
            {1, 5},
            {2, 3},
            {2, 6},
            {3, 7},
            {4, 5},
            {4, 7},
            {5, 6},
            {6, 7},
            {0, 1, 2, 3},
            {0, 1, 4, 5},
            {0, 3, 4, 7},
            {1, 2, 5, 6},
            {2, 3, 6, 7},
            {4, 5, 6, 7},
            {0, 1, 2, 3, 4, 5, 6, 7}};
  return {};
}

/// The largest distance of a cell's middle nodes from the mean of the corners they lie between
/// (0 for straight-edged cells of the second order, and for the first order).
inline double middle_node_error(const Mesh& m, Index c) {
  const auto v = m.cell(c);
  const auto between = middle_nodes_of(m.cell_type(c));
  const auto first = static_cast<std::size_t>(corners_per_cell(m.cell_type(c)));
  double worst = 0.0;
  for (std::size_t q = 0; q < between.size(); ++q) {
    Eigen::Vector3d mean = Eigen::Vector3d::Zero();
    for (const int a : between[q]) mean += m.point(v[static_cast<std::size_t>(a)]);
    mean /= static_cast<double>(between[q].size());
    worst = std::max(worst, (m.point(v[first + q]) - mean).norm());
  }
  return worst;
}

}  // namespace signorini::testing

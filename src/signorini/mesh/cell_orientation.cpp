#include "signorini/mesh/cell_orientation.hpp"

#include <array>
#include <cmath>
#include <utility>

namespace signorini {

void mirror_cell(CellType t, Index* v) {
  switch (t) {
    case CellType::Tri3:
      std::swap(v[1], v[2]);
      return;
    case CellType::Tri6:
      std::swap(v[1], v[2]);
      std::swap(v[3], v[5]);
      return;
    case CellType::Quad4:
      std::swap(v[1], v[3]);
      return;
    case CellType::Quad8:
    case CellType::Quad9:
      std::swap(v[1], v[3]);
      std::swap(v[4], v[7]);
      std::swap(v[5], v[6]);
      return;
    default:
      return;
  }
}

double signed_corner_area2(CellType t, const Index* v, const Eigen::MatrixXd& x) {
  const int corners = corners_per_cell(t);
  double area2 = 0.0;
  for (int a = 0; a < corners; ++a) {
    const Index m = v[a], q = v[(a + 1) % corners];
    area2 += x(0, m) * x(1, q) - x(0, q) * x(1, m);
  }
  return area2;
}

double min_corner_det(CellType t, const Index* v, const Eigen::MatrixXd& x) {
  const auto triple = [&](int a, int b, int c, int d) {
    const Eigen::Vector3d o = x.col(v[a]);
    const Eigen::Vector3d e1 = x.col(v[b]) - o, e2 = x.col(v[c]) - o, e3 = x.col(v[d]) - o;
    return e1(0) * (e2(1) * e3(2) - e2(2) * e3(1)) - e1(1) * (e2(0) * e3(2) - e2(2) * e3(0)) +
           e1(2) * (e2(0) * e3(1) - e2(1) * e3(0));
  };
  if (corners_per_cell(t) == 4) return triple(0, 1, 2, 3);
  static constexpr std::array<std::array<int, 4>, 8> kHexCorners{{{0, 1, 3, 4},
                                                                  {1, 2, 0, 5},
                                                                  {2, 3, 1, 6},
                                                                  {3, 0, 2, 7},
                                                                  {4, 7, 5, 0},
                                                                  {5, 4, 6, 1},
                                                                  {6, 5, 7, 2},
                                                                  {7, 6, 4, 3}}};
  double m = INFINITY;
  for (const auto& [a, b, c, d] : kHexCorners) m = std::min(m, triple(a, b, c, d));
  return m;
}

}  // namespace signorini

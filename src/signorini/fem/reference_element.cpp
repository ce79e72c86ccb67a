#include "signorini/fem/reference_element.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/fem/quadrature.hpp"

namespace signorini {

namespace {

// Quadrilateral nodes: corners, mid-edge nodes (edges 0-1, 1-2, 2-3, 3-0), centre.
constexpr std::array<double, 9> kQuadXi{-1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0};
constexpr std::array<double, 9> kQuadEta{-1.0, -1.0, 1.0, 1.0, -1.0, 0.0, 1.0, 0.0, 0.0};
// Triangle nodes: corners, then the mid-edge nodes of edges 0-1, 1-2, 2-0.
constexpr std::array<double, 6> kTriXi{0.0, 1.0, 0.0, 0.5, 0.5, 0.0};
constexpr std::array<double, 6> kTriEta{0.0, 0.0, 1.0, 0.0, 0.5, 0.5};
// Line nodes: the two ends, then the middle.
constexpr std::array<double, 3> kLineXi{-1.0, 1.0, 0.0};
// Tetrahedron nodes: corners (0,0,0), (1,0,0), (0,1,0), (0,0,1), then the mid-edge nodes of the
// edges in kTetEdges (Gmsh's order: 0-1, 1-2, 2-0, 0-3, 2-3, 1-3).
constexpr std::array<double, 10> kTetX{0.0, 1.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.0, 0.0, 0.5};
constexpr std::array<double, 10> kTetY{0.0, 0.0, 1.0, 0.0, 0.0, 0.5, 0.5, 0.0, 0.5, 0.0};
constexpr std::array<double, 10> kTetZ{0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 0.5, 0.5, 0.5};
constexpr std::array<std::array<int, 2>, 6> kTetEdges{
    {{0, 1}, {1, 2}, {2, 0}, {0, 3}, {2, 3}, {1, 3}}};
// Hexahedron nodes (Gmsh's order): corners 0..7 (z = -1 counterclockwise seen from above, then
// z = 1), mid-edge nodes 8..19 on 0-1, 0-3, 0-4, 1-2, 1-5, 2-3, 2-6, 3-7, 4-5, 4-7, 5-6, 6-7, the
// centres 20..25 of the faces z = -1, y = -1, x = -1, x = 1, y = 1, z = 1, the centre 26.
constexpr std::array<std::array<double, 3>, 27> kHexNodes{
    {{-1.0, -1.0, -1.0}, {1.0, -1.0, -1.0}, {1.0, 1.0, -1.0}, {-1.0, 1.0, -1.0}, {-1.0, -1.0, 1.0},
     {1.0, -1.0, 1.0},   {1.0, 1.0, 1.0},   {-1.0, 1.0, 1.0}, {0.0, -1.0, -1.0}, {-1.0, 0.0, -1.0},
     {-1.0, -1.0, 0.0},  {1.0, 0.0, -1.0},  {1.0, -1.0, 0.0}, {0.0, 1.0, -1.0},  {1.0, 1.0, 0.0},
     {-1.0, 1.0, 0.0},   {0.0, -1.0, 1.0},  {-1.0, 0.0, 1.0}, {1.0, 0.0, 1.0},   {0.0, 1.0, 1.0},
     {0.0, 0.0, -1.0},   {0.0, -1.0, 0.0},  {-1.0, 0.0, 0.0}, {1.0, 0.0, 0.0},   {0.0, 1.0, 0.0},
     {0.0, 0.0, 1.0},    {0.0, 0.0, 0.0}}};

// The barycentric coordinates of the reference tetrahedron at x, and d l_i / d x_k.
std::array<double, 4> tet_barycentric(double x, double y, double z) {
  return {1.0 - x - y - z, x, y, z};
}
constexpr double tet_barycentric_derivative(int i, int k) {
  return i == 0 ? -1.0 : (i == k + 1 ? 1.0 : 0.0);
}

// The 1D quadratic Lagrange polynomials on {-1, 0, 1}: l(s) for the node at p, and l'(s).
double lagrange2(double p, double s) {
  if (p < -0.5) return 0.5 * s * (s - 1.0);
  if (p > 0.5) return 0.5 * s * (s + 1.0);
  return 1.0 - s * s;
}
double lagrange2_derivative(double p, double s) {
  if (p < -0.5) return s - 0.5;
  if (p > 0.5) return s + 0.5;
  return -2.0 * s;
}

}  // namespace

bool has_finite_element(CellType t) {
  // Every type listed, so that a new one is a compiler warning here until it has an element.
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
    case CellType::Tri3:
    case CellType::Tri6:
    case CellType::Quad4:
    case CellType::Quad8:
    case CellType::Quad9:
    case CellType::Tet4:
    case CellType::Tet10:
    case CellType::Hex8:
    case CellType::Hex27:
      return true;
  }
  return false;
}

void require_finite_element(CellType t) {
  if (!has_finite_element(t))
    throw InputError("finite elements for cell type '" +
                     std::string(enum_to_string(kCellTypeNames, t)) +
                     "' are not implemented yet (available: " + enum_choices(kCellTypeNames) + ")");
}

void shape_functions(CellType t, const Eigen::Vector3d& x, ShapeValues& N) {
  const double xi = x(0), eta = x(1), zeta = x(2);
  N.resize(nodes_per_cell(t));
  switch (t) {
    case CellType::Line2:
      N << 0.5 * (1.0 - xi), 0.5 * (1.0 + xi);
      return;
    case CellType::Line3:
      for (int a = 0; a < 3; ++a) N(a) = lagrange2(kLineXi[a], xi);
      return;
    case CellType::Tri3:
      N << 1.0 - xi - eta, xi, eta;
      return;
    case CellType::Tri6: {
      const double l0 = 1.0 - xi - eta, l1 = xi, l2 = eta;
      N << l0 * (2.0 * l0 - 1.0), l1 * (2.0 * l1 - 1.0), l2 * (2.0 * l2 - 1.0), 4.0 * l0 * l1,
          4.0 * l1 * l2, 4.0 * l2 * l0;
      return;
    }
    case CellType::Quad4:
      for (int a = 0; a < 4; ++a) N(a) = 0.25 * (1.0 + kQuadXi[a] * xi) * (1.0 + kQuadEta[a] * eta);
      return;
    case CellType::Quad8:
      for (int a = 0; a < 4; ++a) {
        const double p = kQuadXi[a] * xi, q = kQuadEta[a] * eta;
        N(a) = 0.25 * (1.0 + p) * (1.0 + q) * (p + q - 1.0);
      }
      for (int a = 4; a < 8; ++a)
        N(a) = kQuadXi[a] == 0.0 ? 0.5 * (1.0 - xi * xi) * (1.0 + kQuadEta[a] * eta)
                                 : 0.5 * (1.0 + kQuadXi[a] * xi) * (1.0 - eta * eta);
      return;
    case CellType::Quad9:
      for (int a = 0; a < 9; ++a) N(a) = lagrange2(kQuadXi[a], xi) * lagrange2(kQuadEta[a], eta);
      return;
    case CellType::Tet4:
      N << 1.0 - xi - eta - zeta, xi, eta, zeta;
      return;
    case CellType::Tet10: {
      const std::array<double, 4> l = tet_barycentric(xi, eta, zeta);
      for (int a = 0; a < 4; ++a) N(a) = l[a] * (2.0 * l[a] - 1.0);
      for (int e = 0; e < 6; ++e) N(4 + e) = 4.0 * l[kTetEdges[e][0]] * l[kTetEdges[e][1]];
      return;
    }
    case CellType::Hex8:
      for (int a = 0; a < 8; ++a) {
        const auto& [xa, ya, za] = kHexNodes[a];
        N(a) = 0.125 * (1.0 + xa * xi) * (1.0 + ya * eta) * (1.0 + za * zeta);
      }
      return;
    case CellType::Hex27:
      for (int a = 0; a < 27; ++a) {
        const auto& [xa, ya, za] = kHexNodes[a];
        N(a) = lagrange2(xa, xi) * lagrange2(ya, eta) * lagrange2(za, zeta);
      }
      return;
  }
  require_finite_element(t);
}

void shape_gradients(CellType t, const Eigen::Vector3d& x, ShapeGradients& dN) {
  const double xi = x(0), eta = x(1), zeta = x(2);
  dN.resize(cell_dimension(t), nodes_per_cell(t));
  switch (t) {
    case CellType::Line2:
      dN << -0.5, 0.5;
      return;
    case CellType::Line3:
      for (int a = 0; a < 3; ++a) dN(0, a) = lagrange2_derivative(kLineXi[a], xi);
      return;
    case CellType::Tri3:
      dN << -1.0, 1.0, 0.0, -1.0, 0.0, 1.0;
      return;
    case CellType::Tri6: {
      const double l0 = 1.0 - xi - eta, l1 = xi, l2 = eta;
      // d/dxi and d/deta with dl0 = (-1, -1), dl1 = (1, 0), dl2 = (0, 1).
      dN << -(4.0 * l0 - 1.0), 4.0 * l1 - 1.0, 0.0, 4.0 * (l0 - l1), 4.0 * l2, -4.0 * l2,
          -(4.0 * l0 - 1.0), 0.0, 4.0 * l2 - 1.0, -4.0 * l1, 4.0 * l1, 4.0 * (l0 - l2);
      return;
    }
    case CellType::Quad4:
      for (int a = 0; a < 4; ++a) {
        dN(0, a) = 0.25 * kQuadXi[a] * (1.0 + kQuadEta[a] * eta);
        dN(1, a) = 0.25 * kQuadEta[a] * (1.0 + kQuadXi[a] * xi);
      }
      return;
    case CellType::Quad8:
      for (int a = 0; a < 4; ++a) {
        const double xa = kQuadXi[a], ya = kQuadEta[a];
        const double p = xa * xi, q = ya * eta;
        dN(0, a) = 0.25 * xa * (1.0 + q) * (2.0 * p + q);
        dN(1, a) = 0.25 * ya * (1.0 + p) * (p + 2.0 * q);
      }
      for (int a = 4; a < 8; ++a) {
        const double xa = kQuadXi[a], ya = kQuadEta[a];
        if (xa == 0.0) {
          dN(0, a) = -xi * (1.0 + ya * eta);
          dN(1, a) = 0.5 * ya * (1.0 - xi * xi);
        } else {
          dN(0, a) = 0.5 * xa * (1.0 - eta * eta);
          dN(1, a) = -eta * (1.0 + xa * xi);
        }
      }
      return;
    case CellType::Quad9:
      for (int a = 0; a < 9; ++a) {
        dN(0, a) = lagrange2_derivative(kQuadXi[a], xi) * lagrange2(kQuadEta[a], eta);
        dN(1, a) = lagrange2(kQuadXi[a], xi) * lagrange2_derivative(kQuadEta[a], eta);
      }
      return;
    case CellType::Tet4:
      dN << -1.0, 1.0, 0.0, 0.0, -1.0, 0.0, 1.0, 0.0, -1.0, 0.0, 0.0, 1.0;
      return;
    case CellType::Tet10: {
      // d(l_a (2 l_a - 1)) = (4 l_a - 1) dl_a and d(4 l_i l_j) = 4 (l_j dl_i + l_i dl_j).
      const std::array<double, 4> l = tet_barycentric(xi, eta, zeta);
      for (int k = 0; k < 3; ++k) {
        for (int a = 0; a < 4; ++a)
          dN(k, a) = (4.0 * l[a] - 1.0) * tet_barycentric_derivative(a, k);
        for (int e = 0; e < 6; ++e) {
          const int i = kTetEdges[e][0], j = kTetEdges[e][1];
          dN(k, 4 + e) = 4.0 * (l[j] * tet_barycentric_derivative(i, k) +
                                l[i] * tet_barycentric_derivative(j, k));
        }
      }
      return;
    }
    case CellType::Hex8:
      for (int a = 0; a < 8; ++a) {
        const auto& [xa, ya, za] = kHexNodes[a];
        const double p = 1.0 + xa * xi, q = 1.0 + ya * eta, r = 1.0 + za * zeta;
        dN(0, a) = 0.125 * xa * q * r;
        dN(1, a) = 0.125 * ya * p * r;
        dN(2, a) = 0.125 * za * p * q;
      }
      return;
    case CellType::Hex27:
      for (int a = 0; a < 27; ++a) {
        const auto& [xa, ya, za] = kHexNodes[a];
        const double p = lagrange2(xa, xi), q = lagrange2(ya, eta), r = lagrange2(za, zeta);
        dN(0, a) = lagrange2_derivative(xa, xi) * q * r;
        dN(1, a) = p * lagrange2_derivative(ya, eta) * r;
        dN(2, a) = p * q * lagrange2_derivative(za, zeta);
      }
      return;
  }
  require_finite_element(t);
}

Eigen::Vector3d reference_node(CellType t, int a) {
  if (a < 0 || a >= nodes_per_cell(t)) throw std::out_of_range("reference_node: no such node");
  const auto k = static_cast<std::size_t>(a);
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      return {kLineXi[k], 0.0, 0.0};
    case CellType::Tri3:
    case CellType::Tri6:
      return {kTriXi[k], kTriEta[k], 0.0};
    case CellType::Quad4:
    case CellType::Quad8:
    case CellType::Quad9:
      return {kQuadXi[k], kQuadEta[k], 0.0};
    case CellType::Tet4:
    case CellType::Tet10:
      return {kTetX[k], kTetY[k], kTetZ[k]};
    case CellType::Hex8:
    case CellType::Hex27:
      return {kHexNodes[k][0], kHexNodes[k][1], kHexNodes[k][2]};
  }
  require_finite_element(t);
  return Eigen::Vector3d::Zero();
}

std::vector<QuadraturePoint> cell_quadrature(CellType t, int quad4_points, int line_points) {
  std::vector<QuadraturePoint> rule;
  const auto tensor = [&rule](int n) {
    const auto g = gauss_legendre(n);
    for (const auto& qx : g)
      for (const auto& qy : g) rule.push_back({{qx.x, qy.x, 0.0}, qx.w * qy.w});
  };
  const auto tensor3 = [&rule](int n) {
    const auto g = gauss_legendre(n);
    for (const auto& qx : g)
      for (const auto& qy : g)
        for (const auto& qz : g) rule.push_back({{qx.x, qy.x, qz.x}, qx.w * qy.w * qz.w});
  };
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      for (const auto& q : gauss_legendre(line_points)) rule.push_back({{q.x, 0.0, 0.0}, q.w});
      return rule;
    case CellType::Tri3:  // degree 2: the three edge-midpoint-interior points
      for (const auto& [a, b] : {std::pair{1.0 / 6.0, 1.0 / 6.0}, std::pair{2.0 / 3.0, 1.0 / 6.0},
                                 std::pair{1.0 / 6.0, 2.0 / 3.0}})
        rule.push_back({{a, b, 0.0}, 1.0 / 6.0});
      return rule;
    case CellType::Tri6: {  // degree 4, 6 points (Dunavant 1985); weights sum to 1/2
      constexpr double a1 = 0.445948490915965, w1 = 0.223381589678011;
      constexpr double a2 = 0.091576213509771, w2 = 0.109951743655322;
      for (const auto& [a, w] : {std::pair{a1, w1}, std::pair{a2, w2}}) {
        const double b = 1.0 - 2.0 * a;
        rule.push_back({{a, a, 0.0}, 0.5 * w});
        rule.push_back({{b, a, 0.0}, 0.5 * w});
        rule.push_back({{a, b, 0.0}, 0.5 * w});
      }
      return rule;
    }
    case CellType::Quad4:
      tensor(quad4_points);
      return rule;
    case CellType::Quad8:
    case CellType::Quad9:
      tensor(3);
      return rule;
    case CellType::Tet4: {
      // Degree 2, 4 points (Hammer, Marlowe & Stroud 1956; Keast 1986): the corners pulled
      // towards the centroid, barycentric (b, a, a, a) and permutations; weights sum to 1/6.
      const double a = (5.0 - std::sqrt(5.0)) / 20.0, b = 1.0 - 3.0 * a;
      for (const Eigen::Vector3d& x : {Eigen::Vector3d(a, a, a), Eigen::Vector3d(b, a, a),
                                       Eigen::Vector3d(a, b, a), Eigen::Vector3d(a, a, b)})
        rule.push_back({x, 1.0 / 24.0});
      return rule;
    }
    case CellType::Tet10: {
      // Degree 5, 14 points, all weights positive and all points inside (Walkington 2000,
      // "Quadrature on simplices of arbitrary dimension", CMU report 00-CNA-023, p5 rule): exact
      // for the stiffness of straight P2 cells (degree 2) and their mass (degree 4), with margin
      // for curved cells and loads. Keast's 11-point degree-4 rule has a negative weight.
      // Weights sum to 1/6. Two orbits of 4 points, barycentric (1 - 3a, a, a, a) ...
      for (const auto& [a, w] : {std::pair{0.31088591926330060980, 0.018781320953002641800},
                                 std::pair{0.092735250310891226402, 0.012248840519393658257}}) {
        const double b = 1.0 - 3.0 * a;
        for (const Eigen::Vector3d& x : {Eigen::Vector3d(a, a, a), Eigen::Vector3d(b, a, a),
                                         Eigen::Vector3d(a, b, a), Eigen::Vector3d(a, a, b)})
          rule.push_back({x, w});
      }
      // ... and one of 6, barycentric (a, a, b, b) with b = 1/2 - a and its permutations.
      constexpr double a = 0.045503704125649649492, w = 0.0070910034628469110730;
      constexpr double b = 0.5 - a;
      for (const Eigen::Vector3d& x :
           {Eigen::Vector3d(a, b, b), Eigen::Vector3d(b, a, b), Eigen::Vector3d(b, b, a),
            Eigen::Vector3d(a, a, b), Eigen::Vector3d(a, b, a), Eigen::Vector3d(b, a, a)})
        rule.push_back({x, w});
      return rule;
    }
    case CellType::Hex8:
      tensor3(quad4_points);
      return rule;
    case CellType::Hex27:
      tensor3(3);
      return rule;
  }
  require_finite_element(t);
  return rule;
}

}  // namespace signorini

// The reference elements of every cell type, 1D to 3D: shape functions interpolate
// (N_a(x_b) = delta_ab), add up to one and reproduce the polynomials of their order (linear ones:
// isoparametric cells hold rigid motions and uniform strains exactly); their derivatives match
// central differences; the quadrature rules integrate the monomials they claim exactly; the 3D
// face tables of mesh/cell_type.cpp agree with the reference nodes.

#include "signorini/fem/reference_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <array>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

class ReferenceElement : public ::testing::TestWithParam<CellType> {};

bool is_simplex(CellType t) {
  return t == CellType::Tri3 || t == CellType::Tri6 || t == CellType::Tet4 || t == CellType::Tet10;
}

// Points inside the reference cell of t.
std::vector<Eigen::Vector3d> inner_points(CellType t) {
  if (cell_dimension(t) == 1) return {{-0.7, 0, 0}, {0.1, 0, 0}, {0.55, 0, 0}};
  if (t == CellType::Tri3 || t == CellType::Tri6)
    return {{0.2, 0.3, 0}, {0.05, 0.9, 0}, {0.6, 0.1, 0}};
  if (t == CellType::Tet4 || t == CellType::Tet10)
    return {{0.2, 0.3, 0.1}, {0.05, 0.1, 0.8}, {0.6, 0.1, 0.15}, {0.25, 0.25, 0.25}};
  if (cell_dimension(t) == 3)
    return {{-0.7, 0.3, 0.5}, {0.0, 0.0, 0.0}, {0.4, -0.9, -0.2}, {0.95, 0.6, -0.35}};
  return {{-0.7, 0.3, 0}, {0.0, 0.0, 0}, {0.4, -0.9, 0}};
}

// Exponents (i, j, k) of the monomials x^i y^j z^k that the element of t reproduces: total
// degree up to the order on simplices and on the serendipity Quad8, each exponent up to the order
// on the tensor-product cells (lines, Quad4, Quad9, Hex8, Hex27).
std::vector<std::array<int, 3>> reproduced_monomials(CellType t) {
  const int d = cell_dimension(t), order = cell_order(t);
  const bool total = is_simplex(t) || t == CellType::Quad8;
  std::vector<std::array<int, 3>> out;
  for (int i = 0; i <= order; ++i)
    for (int j = 0; j <= (d >= 2 ? order : 0); ++j)
      for (int k = 0; k <= (d >= 3 ? order : 0); ++k)
        if (!total || i + j + k <= order) out.push_back({i, j, k});
  return out;
}

double monomial(const std::array<int, 3>& e, const Eigen::Vector3d& x) {
  return std::pow(x(0), e[0]) * std::pow(x(1), e[1]) * std::pow(x(2), e[2]);
}

TEST_P(ReferenceElement, InterpolatesAtNodesAndReproducesLinearFunctions) {
  const CellType t = GetParam();
  const int n = nodes_per_cell(t);
  ShapeValues N;
  for (int b = 0; b < n; ++b) {
    shape_functions(t, reference_node(t, b), N);
    for (int a = 0; a < n; ++a) EXPECT_NEAR(N(a), a == b ? 1.0 : 0.0, 1e-15) << a << " at " << b;
  }
  for (const Eigen::Vector3d& x : inner_points(t)) {
    shape_functions(t, x, N);
    EXPECT_NEAR(N.sum(), 1.0, 1e-14);
    Eigen::Vector3d interpolated = Eigen::Vector3d::Zero();
    for (int a = 0; a < n; ++a) interpolated += N(a) * reference_node(t, a);
    EXPECT_LT((interpolated - x).norm(), 1e-14);
  }
}

TEST_P(ReferenceElement, ReproducesThePolynomialsOfItsOrder) {
  const CellType t = GetParam();
  const int n = nodes_per_cell(t);
  ShapeValues N;
  for (const std::array<int, 3>& e : reproduced_monomials(t))
    for (const Eigen::Vector3d& x : inner_points(t)) {
      shape_functions(t, x, N);
      double interpolated = 0.0;
      for (int a = 0; a < n; ++a) interpolated += monomial(e, reference_node(t, a)) * N(a);
      EXPECT_NEAR(interpolated, monomial(e, x), 1e-14)
          << "x^" << e[0] << " y^" << e[1] << " z^" << e[2] << " at " << x.transpose();
    }
}

TEST_P(ReferenceElement, GradientsMatchCentralDifferences) {
  const CellType t = GetParam();
  const int d = cell_dimension(t);
  const double h = 1e-6;
  ShapeValues Np, Nm;
  ShapeGradients dN;
  for (const Eigen::Vector3d& x : inner_points(t)) {
    shape_gradients(t, x, dN);
    ASSERT_EQ(dN.rows(), d);
    ASSERT_EQ(dN.cols(), nodes_per_cell(t));
    EXPECT_LT(dN.rowwise().sum().norm(), 1e-14);  // sum N_a = 1
    for (int i = 0; i < d; ++i) {
      const Eigen::Vector3d e = h * Eigen::Vector3d::Unit(i);
      shape_functions(t, x + e, Np);
      shape_functions(t, x - e, Nm);
      const ShapeValues fd = (Np - Nm) / (2.0 * h);
      for (int a = 0; a < nodes_per_cell(t); ++a) EXPECT_NEAR(dN(i, a), fd(a), 1e-8) << i << a;
    }
  }
}

// The measure of the reference cell: 2, 1/2, 4, 1/6, 8.
double reference_measure(CellType t) {
  const int d = cell_dimension(t);
  if (is_simplex(t)) return d == 2 ? 0.5 : 1.0 / 6.0;
  return std::pow(2.0, d);
}

// The exact integral of x^p y^q z^r over the reference cell: p! q! r! / (p + q + r + d)! on the
// simplices, the product of the integrals over [-1, 1] on lines, quadrilaterals and hexahedra.
double exact_monomial(CellType t, int p, int q, int r) {
  const auto factorial = [](int k) { return std::tgamma(k + 1.0); };
  const int d = cell_dimension(t);
  if (is_simplex(t)) return factorial(p) * factorial(q) * factorial(r) / factorial(p + q + r + d);
  const auto line = [](int k) { return k % 2 == 0 ? 2.0 / (k + 1) : 0.0; };
  return line(p) * (d >= 2 ? line(q) : 1.0) * (d >= 3 ? line(r) : 1.0);
}

// The integrals of the monomials x^p y^q z^r by `rule` against the exact ones: all p + q + r <=
// degree on simplices, each exponent up to degree on the tensor-product cells.
void expect_exact_to_degree(CellType t, const std::vector<QuadraturePoint>& rule, int degree) {
  const int d = cell_dimension(t);
  for (int p = 0; p <= degree; ++p)
    for (int q = 0; q <= (d >= 2 ? degree : 0); ++q)
      for (int r = 0; r <= (d >= 3 ? degree : 0); ++r) {
        if (is_simplex(t) && p + q + r > degree) continue;
        double sum = 0.0;
        for (const QuadraturePoint& pt : rule)
          sum += pt.w * std::pow(pt.xi(0), p) * std::pow(pt.xi(1), q) * std::pow(pt.xi(2), r);
        EXPECT_NEAR(sum, exact_monomial(t, p, q, r), 1e-14)
            << "x^" << p << " y^" << q << " z^" << r << " with " << rule.size() << " points";
      }
}

TEST_P(ReferenceElement, QuadratureWeightsAddUpToTheMeasure) {
  const CellType t = GetParam();
  double sum = 0.0;
  for (const QuadraturePoint& pt : cell_quadrature(t)) sum += pt.w;
  EXPECT_NEAR(sum, reference_measure(t), 1e-15 * reference_measure(t) * 4.0);
}

TEST_P(ReferenceElement, QuadratureIsExactToItsDegree) {
  const CellType t = GetParam();
  // Degrees and sizes claimed in reference_element.hpp: Gauss 2 (degree 3) on Q1 cells and
  // lines, Gauss 3 (degree 5) on quadratic quadrilaterals and Hex27, degree 2 on P1 and 4 on P2
  // triangles, degree 2 (4 points) on P1 and 5 (14 points) on P2 tetrahedra.
  int degree = 3;
  if (t == CellType::Quad8 || t == CellType::Quad9 || t == CellType::Hex27) degree = 5;
  if (t == CellType::Tri3 || t == CellType::Tet4) degree = 2;
  if (t == CellType::Tri6) degree = 4;
  if (t == CellType::Tet10) degree = 5;
  const auto rule = cell_quadrature(t);
  expect_exact_to_degree(t, rule, degree);
  if (cell_dimension(t) == 3) {
    const std::size_t points = t == CellType::Tet4    ? 4
                               : t == CellType::Tet10 ? 14
                               : t == CellType::Hex8  ? 8
                                                      : 27;
    EXPECT_EQ(rule.size(), points);
  }
}

TEST_P(ReferenceElement, QuadraturePointsAreInsideWithPositiveWeights) {
  const CellType t = GetParam();
  for (const QuadraturePoint& pt : cell_quadrature(t)) {
    EXPECT_GT(pt.w, 0.0);
    const Eigen::Vector3d& x = pt.xi;
    for (int i = cell_dimension(t); i < 3; ++i) EXPECT_EQ(x(i), 0.0);
    if (is_simplex(t))
      EXPECT_TRUE(x.minCoeff() >= 0.0 && x.sum() < 1.0) << x.transpose();
    else
      EXPECT_LT(x.cwiseAbs().maxCoeff(), 1.0) << x.transpose();
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, ReferenceElement,
                         ::testing::Values(CellType::Line2, CellType::Line3, CellType::Tri3,
                                           CellType::Tri6, CellType::Quad4, CellType::Quad8,
                                           CellType::Quad9, CellType::Tet4, CellType::Tet10,
                                           CellType::Hex8, CellType::Hex27),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

TEST(ReferenceElementTypes, EveryCellTypeHasAFiniteElement) {
  for (const auto& [t, name] : kCellTypeNames) {
    EXPECT_TRUE(has_finite_element(t)) << name;
    EXPECT_NO_THROW(require_finite_element(t)) << name;
  }
}

TEST(ReferenceElementTypes, HexahedronRuleFollowsTheQuadrilateralPointsPerDirection) {
  // `quad4_points` per direction on Hex8 as on Quad4: 3 gives the 27-point rule of degree 5.
  const auto rule = cell_quadrature(CellType::Hex8, 3);
  EXPECT_EQ(rule.size(), 27u);
  expect_exact_to_degree(CellType::Hex8, rule, 5);
  EXPECT_EQ(cell_quadrature(CellType::Hex8, 1).size(), 1u);
}

// The planes n . x = c holding the faces of the reference tetrahedron and hexahedron, n outward.
struct ReferencePlane {
  Eigen::Vector3d n;
  double c;
};
std::vector<ReferencePlane> reference_planes(CellType t) {
  std::vector<ReferencePlane> planes;
  if (t == CellType::Tet4 || t == CellType::Tet10) {
    for (int i = 0; i < 3; ++i) planes.push_back({-Eigen::Vector3d::Unit(i), 0.0});
    planes.push_back({Eigen::Vector3d::Ones(), 1.0});
  } else {
    for (int i = 0; i < 3; ++i)
      for (const double s : {-1.0, 1.0}) planes.push_back({s * Eigen::Vector3d::Unit(i), 1.0});
  }
  return planes;
}

class ReferenceFaces : public ::testing::TestWithParam<CellType> {};

// For each face of facet_local_nodes(): all its nodes on one face of the reference cell (one
// face each), every three consecutive corners turning so that the normal points outward, and on
// quadratic faces the mid-edge nodes at the midpoints of the face's edges in the face's order
// (mid(c0, c1), mid(c1, c2), ...), then the centre of a quadrilateral.
TEST_P(ReferenceFaces, FaceTablesAgreeWithTheReferenceNodes) {
  const CellType t = GetParam();
  const CellType ft = facet_type(t);
  const int corners = ft == CellType::Tri3 || ft == CellType::Tri6 ? 3 : 4;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  const int cell_corners = t == CellType::Tet4 || t == CellType::Tet10 ? 4 : 8;
  for (int a = 0; a < cell_corners; ++a) centroid += reference_node(t, a) / cell_corners;
  const std::vector<ReferencePlane> planes = reference_planes(t);
  ASSERT_EQ(static_cast<int>(planes.size()), facets_per_cell(t));
  std::set<int> planes_used;
  for (int f = 0; f < facets_per_cell(t); ++f) {
    const auto nodes = facet_local_nodes(t, f);
    ASSERT_EQ(static_cast<int>(nodes.size()), nodes_per_cell(ft)) << "face " << f;
    std::vector<Eigen::Vector3d> x;
    for (const int a : nodes) x.push_back(reference_node(t, a));
    for (int i = 0; i < corners; ++i) EXPECT_LT(nodes[i], cell_corners) << "face " << f;

    int plane = -1;
    for (int p = 0; p < static_cast<int>(planes.size()); ++p) {
      bool on = true;
      for (const Eigen::Vector3d& xa : x)
        on = on && std::abs(planes[p].n.dot(xa) - planes[p].c) < 1e-15;
      if (on) {
        EXPECT_EQ(plane, -1) << "face " << f << " on two planes";
        plane = p;
      }
    }
    ASSERT_NE(plane, -1) << "face " << f << " is on no face of the reference cell";
    EXPECT_TRUE(planes_used.insert(plane).second) << "face " << f << " repeats a face";

    for (int i = 0; i < corners; ++i) {
      const Eigen::Vector3d& x0 = x[i];
      const Eigen::Vector3d& x1 = x[(i + 1) % corners];
      const Eigen::Vector3d& x2 = x[(i + 2) % corners];
      const Eigen::Vector3d normal = (x1 - x0).cross(x2 - x0);
      EXPECT_GT(normal.dot(x0 - centroid), 0.0) << "face " << f << " corner " << i;
      EXPECT_GT(normal.dot(planes[plane].n), 0.0) << "face " << f << " corner " << i;
    }
    if (cell_order(t) == 2) {
      for (int i = 0; i < corners; ++i)
        EXPECT_LT((x[corners + i] - 0.5 * (x[i] + x[(i + 1) % corners])).norm(), 1e-15)
            << "face " << f << " edge " << i << " (node " << nodes[corners + i] << ")";
      if (corners == 4) {
        const Eigen::Vector3d centre = 0.25 * (x[0] + x[1] + x[2] + x[3]);
        EXPECT_LT((x[8] - centre).norm(), 1e-15) << "face " << f;
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, ReferenceFaces,
                         ::testing::Values(CellType::Tet4, CellType::Tet10, CellType::Hex8,
                                           CellType::Hex27),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

}  // namespace
}  // namespace signorini

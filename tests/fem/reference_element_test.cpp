// The reference elements of every 2D cell type and of the boundary lines: shape functions
// interpolate (N_a(x_b) = delta_ab), add up to one and reproduce linear functions (so
// isoparametric cells hold rigid motions and uniform strains exactly); their derivatives match
// central differences; the quadrature rules integrate the monomials they claim exactly.

#include "signorini/fem/reference_element.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

class ReferenceElement : public ::testing::TestWithParam<CellType> {};

// Points inside the reference cell of t.
std::vector<Eigen::Vector3d> inner_points(CellType t) {
  if (cell_dimension(t) == 1) return {{-0.7, 0, 0}, {0.1, 0, 0}, {0.55, 0, 0}};
  if (t == CellType::Tri3 || t == CellType::Tri6)
    return {{0.2, 0.3, 0}, {0.05, 0.9, 0}, {0.6, 0.1, 0}};
  return {{-0.7, 0.3, 0}, {0.0, 0.0, 0}, {0.4, -0.9, 0}};
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

// The exact integral of x^p y^q over the reference cell.
double exact_monomial(CellType t, int p, int q) {
  const auto factorial = [](int k) { return std::tgamma(k + 1.0); };
  if (cell_dimension(t) == 1) return q > 0 ? 0.0 : (p % 2 == 0 ? 2.0 / (p + 1) : 0.0);
  if (t == CellType::Tri3 || t == CellType::Tri6)
    return factorial(p) * factorial(q) / factorial(p + q + 2);
  const auto line = [](int k) { return k % 2 == 0 ? 2.0 / (k + 1) : 0.0; };
  return line(p) * line(q);
}

TEST_P(ReferenceElement, QuadratureIsExactToItsDegree) {
  const CellType t = GetParam();
  // Degrees claimed in reference_element.hpp: Gauss 2 (degree 3) on Q1 and lines, Gauss 3
  // (degree 5) on quadratic quadrilaterals, degree 2 on P1 and 4 on P2 triangles.
  int degree = 3;
  if (t == CellType::Quad8 || t == CellType::Quad9) degree = 5;
  if (t == CellType::Tri3) degree = 2;
  if (t == CellType::Tri6) degree = 4;
  const bool tensor = t == CellType::Quad4 || t == CellType::Quad8 || t == CellType::Quad9 ||
                      cell_dimension(t) == 1;
  const auto rule = cell_quadrature(t);
  for (int p = 0; p <= degree; ++p)
    for (int q = 0; q <= (cell_dimension(t) == 1 ? 0 : degree); ++q) {
      if (!tensor && p + q > degree) continue;
      double sum = 0.0;
      for (const QuadraturePoint& pt : rule)
        sum += pt.w * std::pow(pt.xi(0), p) * std::pow(pt.xi(1), q);
      EXPECT_NEAR(sum, exact_monomial(t, p, q), 1e-14) << "x^" << p << " y^" << q;
    }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, ReferenceElement,
                         ::testing::Values(CellType::Line2, CellType::Line3, CellType::Tri3,
                                           CellType::Tri6, CellType::Quad4, CellType::Quad8,
                                           CellType::Quad9),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

TEST(ReferenceElementTypes, ThreeDimensionalCellsAreRefusedByName) {
  EXPECT_FALSE(has_finite_element(CellType::Hex8));
  try {
    require_finite_element(CellType::Tet4);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'tet4' are not implemented yet"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signorini

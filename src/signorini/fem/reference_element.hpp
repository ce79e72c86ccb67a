#pragma once
// The finite elements on their reference cells: shape functions, their derivatives, the
// quadrature rule of each cell type and the reference coordinates of the nodes. Every element is
// isoparametric (the geometry is mapped by the same shape functions), so that quadratic cells
// follow curved boundaries. Reference cells: lines [-1, 1]; triangles (0,0), (1,0), (0,1);
// quadrilaterals [-1, 1]^2; tetrahedra (0,0,0), (1,0,0), (0,1,0), (0,0,1); hexahedra [-1, 1]^3.
// Node orders as in mesh/cell_type.hpp (Gmsh's).
//
// Lagrange P1 (Tri3) and P2 (Tri6) triangles; bilinear Q1 (Quad4), serendipity (Quad8) and
// biquadratic Q2 (Quad9) quadrilaterals; Line2 and Line3 for boundary integrals. In 3D: Lagrange
// P1 (Tet4) and P2 (Tet10) tetrahedra, trilinear Q1 (Hex8) and triquadratic Q2 (Hex27)
// hexahedra.

#include <Eigen/Core>
#include <array>
#include <vector>

#include "signorini/mesh/cell_type.hpp"

namespace signorini {

/// The most nodes of a cell that has a finite element here (Hex27).
inline constexpr int kMaxElementNodes = 27;

/// N_a at one reference point, a = 0 .. nodes - 1.
using ShapeValues = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxElementNodes, 1>;
/// dN_a / dxi_i: row i = reference coordinate, column a = node.
using ShapeGradients =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, 3, kMaxElementNodes>;

/// A quadrature point of a reference cell, with its weight (the weights of a rule add up to
/// the reference cell's measure: 2 for lines, 1/2 for triangles, 4 for quadrilaterals, 1/6 for
/// tetrahedra, 8 for hexahedra).
struct QuadraturePoint {
  Eigen::Vector3d xi = Eigen::Vector3d::Zero();
  double w = 0.0;
};

/// Whether shape functions exist for cells of this type.
bool has_finite_element(CellType t);
/// Throws InputError naming the type and the ones available unless has_finite_element(t).
void require_finite_element(CellType t);

/// N_a(xi).
void shape_functions(CellType t, const Eigen::Vector3d& xi, ShapeValues& N);
/// dN_a/dxi (cell_dimension(t) rows).
void shape_gradients(CellType t, const Eigen::Vector3d& xi, ShapeGradients& dN);
/// Reference coordinates of local node a.
Eigen::Vector3d reference_node(CellType t, int a);

/// The cell rule used for stiffness and body forces. Gauss rules of `quad4_points` per direction
/// on Q1 quadrilaterals (2: the paper's 2x2 rule) and Q1 hexahedra (2: 2x2x2), 3x3 on quadratic
/// quadrilaterals (exact for the stiffness of Q2 parallelograms) and 3x3x3 on Q2 hexahedra, the
/// 3-point degree-2 rule on P1 triangles and the 6-point degree-4 rule (Dunavant) on P2
/// triangles (exact for straight P2 stiffness, degree 2, with margin for curved cells and loads),
/// the 4-point degree-2 rule on P1 tetrahedra and the 14-point degree-5 rule (Walkington, all
/// weights positive) on P2 tetrahedra; Gauss rules of `line_points` on lines.
std::vector<QuadraturePoint> cell_quadrature(CellType t, int quad4_points = 2, int line_points = 2);

/// cell_quadrature() of each cell type, made once per type on first use: what the loops over the
/// cells of a mesh ask for cell by cell.
class CellRules {
 public:
  explicit CellRules(int quad4_points) : quad4_points_(quad4_points) {}
  const std::vector<QuadraturePoint>& operator()(CellType t) {
    std::vector<QuadraturePoint>& rule = rules_[static_cast<std::size_t>(t)];
    if (rule.empty()) rule = cell_quadrature(t, quad4_points_);
    return rule;
  }

 private:
  int quad4_points_;
  std::array<std::vector<QuadraturePoint>, kCellTypeNames.size()> rules_;
};

}  // namespace signorini

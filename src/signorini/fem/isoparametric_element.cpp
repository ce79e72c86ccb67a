#include "signorini/fem/isoparametric_element.hpp"

#include <Eigen/LU>
#include <stdexcept>
#include <string>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// B from the shape function gradients dN/dx (rows d/dx, d/dy): (e_xx, e_yy, 2 e_xy) = B u_e,
// element dofs node by node. B must be zero on entry.
template <class Gradients, class Strain>
void fill_strain_matrix(const Gradients& dNdx, Strain& B) {
  for (Index a = 0; a < dNdx.cols(); ++a) {
    B(0, 2 * a) = dNdx(0, a);
    B(1, 2 * a + 1) = dNdx(1, a);
    B(2, 2 * a) = dNdx(1, a);
    B(2, 2 * a + 1) = dNdx(0, a);
  }
}

// The kernels here are plane ones (2 x n coordinates, 2 x 2 Jacobians): 3D types, which have
// shape functions with three rows of derivatives, are refused before they reach them.
void require_plane_cell(CellType t) {
  if (cell_dimension(t) != 2)
    throw InputError("plane elasticity on a " + std::string(enum_to_string(kCellTypeNames, t)) +
                     " cell: expected a 2D cell type (tri3, tri6, quad4, quad8, quad9)");
}

}  // namespace

CellCoordinates cell_coordinates(const Mesh& mesh, Index c) {
  const auto nodes = mesh.cell(c);
  CellCoordinates X(2, static_cast<Index>(nodes.size()));
  for (std::size_t a = 0; a < nodes.size(); ++a) X.col(static_cast<Index>(a)) = mesh.node(nodes[a]);
  return X;
}

Eigen::Matrix2d cell_jacobian(CellType t, const CellCoordinates& X, const Eigen::Vector3d& xi) {
  require_plane_cell(t);
  ShapeGradients dN;
  shape_gradients(t, xi, dN);
  return dN * X.transpose();
}

StrainMatrix strain_matrix(CellType t, const CellCoordinates& X, const Eigen::Vector3d& xi,
                           double& det_j) {
  require_plane_cell(t);
  ShapeGradients dN;
  shape_gradients(t, xi, dN);
  const Eigen::Matrix2d J = dN * X.transpose();  // J(i, k) = d x_k / d xi_i
  det_j = J.determinant();
  const auto n = static_cast<Index>(X.cols());
  StrainMatrix B = StrainMatrix::Zero(3, 2 * n);
  if (!(det_j > 0.0)) return B;
  const ShapeGradients dNdx = J.inverse() * dN;  // rows: d/dx, d/dy
  fill_strain_matrix(dNdx, B);
  return B;
}

void check_cell_geometry(CellType t, const CellCoordinates& X) {
  for (int a = 0; a < nodes_per_cell(t); ++a) {
    const double det_j = cell_jacobian(t, X, reference_node(t, a)).determinant();
    if (!(det_j > 0.0))
      throw InputError("inverted or degenerate " + std::string(enum_to_string(kCellTypeNames, t)) +
                       " (det J = " + std::to_string(det_j) + " at its local node " +
                       std::to_string(a) +
                       "): expected counterclockwise cells, convex for quadrilaterals, mid-edge "
                       "nodes near the middle of their edges");
  }
}

namespace {

// K_e with the sizes fixed at compile time: fast, and for Q1 cells the same operations in the
// same order as the paper benchmark's reference implementation, so that Table 1's solutions
// reproduce to the last bits (the solution at 480x160 moves by 1e-10 relative when one rounding
// of the element matrix changes).
template <int NN>
ElementMatrix fixed_size_stiffness(CellType t, const CellCoordinates& Xd, const Eigen::Matrix3d& D,
                                   const std::vector<QuadraturePoint>& rule) {
  using Matrix2N = Eigen::Matrix<double, 2, NN>;
  using Strain = Eigen::Matrix<double, 3, 2 * NN>;
  using Stiffness = Eigen::Matrix<double, 2 * NN, 2 * NN>;
  const Matrix2N X = Xd;
  Stiffness K = Stiffness::Zero();
  ShapeGradients g;
  for (const QuadraturePoint& q : rule) {
    shape_gradients(t, q.xi, g);
    const Matrix2N dN = g;
    const Eigen::Matrix2d J = dN * X.transpose();  // J(i, k) = d x_k / d xi_i
    const double det_j = J.determinant();
    if (!(det_j > 0.0))
      throw InputError("inverted or degenerate " + std::string(enum_to_string(kCellTypeNames, t)) +
                       " (det J = " + std::to_string(det_j) + " at a quadrature point)");
    const Matrix2N dNdx = J.inverse() * dN;  // rows: d/dx, d/dy
    Strain B = Strain::Zero();
    fill_strain_matrix(dNdx, B);
    K.noalias() += B.transpose() * D * B * (det_j * q.w);
  }
  return K;
}

}  // namespace

ElementMatrix element_stiffness(CellType t, const CellCoordinates& X, const Eigen::Matrix3d& D,
                                const std::vector<QuadraturePoint>& rule) {
  check_cell_geometry(t, X);
  switch (nodes_per_cell(t)) {
    case 3:
      return fixed_size_stiffness<3>(t, X, D, rule);
    case 4:
      return fixed_size_stiffness<4>(t, X, D, rule);
    case 6:
      return fixed_size_stiffness<6>(t, X, D, rule);
    case 8:
      return fixed_size_stiffness<8>(t, X, D, rule);
    case 9:
      return fixed_size_stiffness<9>(t, X, D, rule);
    default:
      break;
  }
  require_finite_element(t);
  throw std::logic_error("element_stiffness: no kernel for this cell type");
}

}  // namespace signorini

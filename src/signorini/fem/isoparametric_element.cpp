#include "signorini/fem/isoparametric_element.hpp"

#include <Eigen/LU>
#include <stdexcept>
#include <string>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// B from the shape function gradients dN/dx (rows d/dx, d/dy[, d/dz]), element dofs node by node,
// strains in Voigt order (isoparametric_element.hpp). B must be zero on entry.
template <int Dim, class Gradients, class Strain>
void fill_strain_matrix(const Gradients& dNdx, Strain& B) {
  for (Index a = 0; a < dNdx.cols(); ++a) {
    if constexpr (Dim == 2) {
      B(0, 2 * a) = dNdx(0, a);
      B(1, 2 * a + 1) = dNdx(1, a);
      B(2, 2 * a) = dNdx(1, a);
      B(2, 2 * a + 1) = dNdx(0, a);
    } else {
      const Index i = 3 * a;
      B(0, i) = dNdx(0, a);      // e_xx
      B(1, i + 1) = dNdx(1, a);  // e_yy
      B(2, i + 2) = dNdx(2, a);  // e_zz
      B(3, i + 1) = dNdx(2, a);  // 2 e_yz
      B(3, i + 2) = dNdx(1, a);
      B(4, i) = dNdx(2, a);  // 2 e_xz
      B(4, i + 2) = dNdx(0, a);
      B(5, i) = dNdx(1, a);  // 2 e_xy
      B(5, i + 1) = dNdx(0, a);
    }
  }
}

std::string inverted_message(CellType t, double det_j, const std::string& where) {
  return "inverted or degenerate " + std::string(enum_to_string(kCellTypeNames, t)) +
         " (det J = " + std::to_string(det_j) + " at " + where + ")";
}

}  // namespace

template <int Dim>
CellCoordinatesOf<Dim> cell_coordinates(const Mesh& mesh, Index c) {
  const auto nodes = mesh.cell(c);
  CellCoordinatesOf<Dim> X(Dim, static_cast<Index>(nodes.size()));
  for (std::size_t a = 0; a < nodes.size(); ++a)
    X.col(static_cast<Index>(a)) = mesh.node(nodes[a]).template head<Dim>();
  return X;
}

template <int Dim>
void require_dimension(CellType t) {
  if (cell_dimension(t) != Dim)
    throw std::logic_error("a " + std::string(enum_to_string(kCellTypeNames, t)) +
                           " cell given as a " + std::to_string(Dim) + "D one");
}

template <int Dim>
JacobianOf<Dim> cell_jacobian(CellType t, const CellCoordinatesOf<Dim>& X,
                              const Eigen::Vector3d& xi) {
  require_dimension<Dim>(t);
  ShapeGradients dN;
  shape_gradients(t, xi, dN);
  return dN.topRows(Dim) * X.transpose();
}

template <int Dim>
StrainMatrixOf<Dim> strain_matrix(CellType t, const CellCoordinatesOf<Dim>& X,
                                  const Eigen::Vector3d& xi, double& det_j) {
  require_dimension<Dim>(t);
  ShapeGradients dN;
  shape_gradients(t, xi, dN);
  const JacobianOf<Dim> J = dN.topRows(Dim) * X.transpose();  // J(i, k) = d x_k / d xi_i
  det_j = J.determinant();
  const auto n = static_cast<Index>(X.cols());
  StrainMatrixOf<Dim> B = StrainMatrixOf<Dim>::Zero(ElementSizes<Dim>::kStrains, Dim * n);
  if (!(det_j > 0.0)) return B;
  const Eigen::Matrix<double, Dim, Eigen::Dynamic, 0, Dim, ElementSizes<Dim>::kMaxNodes> dNdx =
      J.inverse() * dN.topRows(Dim);  // rows: d/dx, d/dy[, d/dz]
  fill_strain_matrix<Dim>(dNdx, B);
  return B;
}

template <int Dim>
void check_cell_geometry(CellType t, const CellCoordinatesOf<Dim>& X) {
  for (int a = 0; a < nodes_per_cell(t); ++a) {
    const double det_j = cell_jacobian<Dim>(t, X, reference_node(t, a)).determinant();
    if (!(det_j > 0.0))
      throw InputError(inverted_message(t, det_j, "its local node " + std::to_string(a)) +
                       (Dim == 2 ? ": expected counterclockwise cells, convex for quadrilaterals, "
                                   "mid-edge nodes near the middle of their edges"
                                 : ": expected cells numbered as Gmsh numbers them (positive "
                                   "volume), convex hexahedra, mid-edge nodes near the middle of "
                                   "their edges"));
  }
}

namespace {

// K_e with the sizes fixed at compile time: fast, and for Q1 cells the same operations in the
// same order as the paper benchmark's reference implementation, so that Table 1's solutions
// reproduce to the last bits (the solution at 480x160 moves by 1e-10 relative when one rounding
// of the element matrix changes).
template <int Dim, int NN>
ElementMatrixOf<Dim> fixed_size_stiffness(CellType t, const CellCoordinatesOf<Dim>& Xd,
                                          const ElasticityMatrixOf<Dim>& D,
                                          const std::vector<QuadraturePoint>& rule) {
  constexpr int kStrains = ElementSizes<Dim>::kStrains;
  using MatrixDN = Eigen::Matrix<double, Dim, NN>;
  using Strain = Eigen::Matrix<double, kStrains, Dim * NN>;
  using Stiffness = Eigen::Matrix<double, Dim * NN, Dim * NN>;
  const MatrixDN X = Xd;
  Stiffness K = Stiffness::Zero();
  ShapeGradients g;
  for (const QuadraturePoint& q : rule) {
    shape_gradients(t, q.xi, g);
    const MatrixDN dN = g.topRows(Dim);
    const JacobianOf<Dim> J = dN * X.transpose();  // J(i, k) = d x_k / d xi_i
    const double det_j = J.determinant();
    if (!(det_j > 0.0)) throw InputError(inverted_message(t, det_j, "a quadrature point"));
    const MatrixDN dNdx = J.inverse() * dN;  // rows: d/dx, d/dy[, d/dz]
    Strain B = Strain::Zero();
    fill_strain_matrix<Dim>(dNdx, B);
    K.noalias() += B.transpose() * D * B * (det_j * q.w);
  }
  return K;
}

}  // namespace

template <int Dim>
ElementMatrixOf<Dim> element_stiffness(CellType t, const CellCoordinatesOf<Dim>& X,
                                       const ElasticityMatrixOf<Dim>& D,
                                       const std::vector<QuadraturePoint>& rule) {
  require_dimension<Dim>(t);
  check_cell_geometry<Dim>(t, X);
  if constexpr (Dim == 2) {
    switch (nodes_per_cell(t)) {
      case 3:
        return fixed_size_stiffness<2, 3>(t, X, D, rule);
      case 4:
        return fixed_size_stiffness<2, 4>(t, X, D, rule);
      case 6:
        return fixed_size_stiffness<2, 6>(t, X, D, rule);
      case 8:
        return fixed_size_stiffness<2, 8>(t, X, D, rule);
      case 9:
        return fixed_size_stiffness<2, 9>(t, X, D, rule);
      default:
        break;
    }
  } else {
    switch (nodes_per_cell(t)) {
      case 4:
        return fixed_size_stiffness<3, 4>(t, X, D, rule);
      case 8:
        return fixed_size_stiffness<3, 8>(t, X, D, rule);
      case 10:
        return fixed_size_stiffness<3, 10>(t, X, D, rule);
      case 27:
        return fixed_size_stiffness<3, 27>(t, X, D, rule);
      default:
        break;
    }
  }
  require_finite_element(t);
  throw std::logic_error("element_stiffness: no kernel for this cell type");
}

// The two dimensions, compiled here.
#define SIGNORINI_INSTANTIATE(Dim)                                                              \
  template CellCoordinatesOf<Dim> cell_coordinates<Dim>(const Mesh&, Index);                    \
  template JacobianOf<Dim> cell_jacobian<Dim>(CellType, const CellCoordinatesOf<Dim>&,          \
                                              const Eigen::Vector3d&);                          \
  template StrainMatrixOf<Dim> strain_matrix<Dim>(CellType, const CellCoordinatesOf<Dim>&,      \
                                                  const Eigen::Vector3d&, double&);             \
  template void check_cell_geometry<Dim>(CellType, const CellCoordinatesOf<Dim>&);              \
  template ElementMatrixOf<Dim> element_stiffness<Dim>(CellType, const CellCoordinatesOf<Dim>&, \
                                                       const ElasticityMatrixOf<Dim>&,          \
                                                       const std::vector<QuadraturePoint>&);
SIGNORINI_INSTANTIATE(2)
SIGNORINI_INSTANTIATE(3)
#undef SIGNORINI_INSTANTIATE

}  // namespace signorini

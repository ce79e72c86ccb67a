#pragma once
// Linear elasticity on one isoparametric cell of any type with a finite element
// (fem/reference_element.hpp), in Dim = 2 (plane) or 3 dimensions: the strain-displacement matrix
// B at a reference point and the element stiffness K_e = sum_q B^T D B det J w_q (method.md
// section 2, the discrete form of a(u, v)). Element dofs are ordered node by node: (u_x0, u_y0,
// [u_z0,] u_x1, ...). Strains in Voigt order: (e_xx, e_yy, 2 e_xy) in 2D, (e_xx, e_yy, e_zz,
// 2 e_yz, 2 e_xz, 2 e_xy) in 3D. The sizes are fixed at compile time per dimension (at most 9
// nodes in 2D, 27 in 3D), so that the 2D kernels are those of a 2D-only code; the unsuffixed names
// (CellCoordinates, StrainMatrix, ...) are the 2D ones.
#include <Eigen/Core>
#include <vector>

#include "signorini/fem/reference_element.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The sizes of the element arrays in Dim dimensions.
template <int Dim>
struct ElementSizes {
  static_assert(Dim == 2 || Dim == 3, "elements are 2D or 3D");
  static constexpr int kStrains = Dim == 2 ? 3 : 6;    ///< Voigt components
  static constexpr int kMaxNodes = Dim == 2 ? 9 : 27;  ///< Quad9, Hex27
  static constexpr int kMaxDofs = Dim * kMaxNodes;
};

/// Node coordinates of one cell: column a = node a.
template <int Dim>
using CellCoordinatesOf =
    Eigen::Matrix<double, Dim, Eigen::Dynamic, 0, Dim, ElementSizes<Dim>::kMaxNodes>;
/// B with the Voigt strain = B u_e.
template <int Dim>
using StrainMatrixOf = Eigen::Matrix<double, ElementSizes<Dim>::kStrains, Eigen::Dynamic, 0,
                                     ElementSizes<Dim>::kStrains, ElementSizes<Dim>::kMaxDofs>;
/// D with the Voigt stress = D strain (material.hpp).
template <int Dim>
using ElasticityMatrixOf =
    Eigen::Matrix<double, ElementSizes<Dim>::kStrains, ElementSizes<Dim>::kStrains>;
template <int Dim>
using ElementMatrixOf = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0,
                                      ElementSizes<Dim>::kMaxDofs, ElementSizes<Dim>::kMaxDofs>;
template <int Dim>
using ElementVectorOf = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, ElementSizes<Dim>::kMaxDofs, 1>;
/// J(i, k) = d x_k / d xi_i.
template <int Dim>
using JacobianOf = Eigen::Matrix<double, Dim, Dim>;

inline constexpr int kMaxElementDofs = ElementSizes<2>::kMaxDofs;
using CellCoordinates = CellCoordinatesOf<2>;
using StrainMatrix = StrainMatrixOf<2>;
using ElementMatrix = ElementMatrixOf<2>;
using ElementVector = ElementVectorOf<2>;

/// The coordinates of cell c of a mesh of dimension Dim.
template <int Dim = 2>
CellCoordinatesOf<Dim> cell_coordinates(const Mesh& mesh, Index c);

/// The Jacobian J(i, k) = d x_k / d xi_i of the map from the reference cell at xi.
template <int Dim>
JacobianOf<Dim> cell_jacobian(CellType t, const CellCoordinatesOf<Dim>& X,
                              const Eigen::Vector3d& xi);

/// B at xi and det J there. det J <= 0 means an inverted or degenerate cell (B is then zero);
/// the caller decides what to say.
template <int Dim>
StrainMatrixOf<Dim> strain_matrix(CellType t, const CellCoordinatesOf<Dim>& X,
                                  const Eigen::Vector3d& xi, double& det_j);

/// Throws InputError unless det J > 0 at every node of the cell (its corners and, for quadratic
/// cells, its mid-edge, face and centre nodes): a quadrilateral with det J > 0 at its corners is
/// convex, and a quadratic cell whose Jacobian changes sign between its nodes is folded even
/// where every quadrature point has det J > 0.
template <int Dim>
void check_cell_geometry(CellType t, const CellCoordinatesOf<Dim>& X);

/// K_e over `rule` (after check_cell_geometry) (cell_quadrature(t, ...)). Throws InputError if det
/// J <= 0 at a quadrature point, with the value found there.
template <int Dim>
ElementMatrixOf<Dim> element_stiffness(CellType t, const CellCoordinatesOf<Dim>& X,
                                       const ElasticityMatrixOf<Dim>& D,
                                       const std::vector<QuadraturePoint>& rule);

}  // namespace signorini

#pragma once
// Plane elasticity on one isoparametric cell of any 2D type (fem/reference_element.hpp): the
// strain-displacement matrix B at a reference point and the element stiffness
// K_e = sum_q B^T D B det J w_q (method.md section 2, the discrete form of a(u, v)). Element dofs
// are ordered node by node: (u_x0, u_y0, u_x1, u_y1, ...). Written for dim = 2 (three strain
// components); 3D cells bring their own B with six.

#include <Eigen/Core>
#include <vector>

#include "signorini/fem/reference_element.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The most nodes of a 2D cell (Quad9): the bound of the plane kernels' buffers, kept apart from
/// kMaxElementNodes (Hex27) so that 2D assembly does not carry 3D-sized element matrices.
inline constexpr int kMaxPlaneElementNodes = 9;
inline constexpr int kMaxElementDofs = 2 * kMaxPlaneElementNodes;

/// Node coordinates of one cell: column a = node a.
using CellCoordinates = Eigen::Matrix<double, 2, Eigen::Dynamic, 0, 2, kMaxPlaneElementNodes>;
/// B with (e_xx, e_yy, 2 e_xy) = B u_e.
using StrainMatrix = Eigen::Matrix<double, 3, Eigen::Dynamic, 0, 3, kMaxElementDofs>;
using ElementMatrix =
    Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxElementDofs, kMaxElementDofs>;
using ElementVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxElementDofs, 1>;

/// The coordinates of cell c of a 2D mesh.
CellCoordinates cell_coordinates(const Mesh& mesh, Index c);

/// The Jacobian J(i, k) = d x_k / d xi_i of the map from the reference cell at xi. This function,
/// strain_matrix, check_cell_geometry and element_stiffness throw InputError for 3D cell types.
Eigen::Matrix2d cell_jacobian(CellType t, const CellCoordinates& X, const Eigen::Vector3d& xi);

/// B at xi and det J there. det J <= 0 means an inverted or degenerate cell (B is then zero);
/// the caller decides what to say.
StrainMatrix strain_matrix(CellType t, const CellCoordinates& X, const Eigen::Vector3d& xi,
                           double& det_j);

/// Throws InputError unless det J > 0 at every node of the cell (its corners and, for quadratic
/// cells, its mid-edge and centre nodes): a quadrilateral with det J > 0 at its corners is convex,
/// and a quadratic cell whose Jacobian changes sign between its nodes is folded even where every
/// quadrature point has det J > 0.
void check_cell_geometry(CellType t, const CellCoordinates& X);

/// K_e over `rule` (after check_cell_geometry) (cell_quadrature(t, ...)). Throws InputError if det
/// J <= 0 at a quadrature point, with the value found there.
ElementMatrix element_stiffness(CellType t, const CellCoordinates& X, const Eigen::Matrix3d& D,
                                const std::vector<QuadraturePoint>& rule);

}  // namespace signorini

#pragma once
// The bilinear quadrilateral (Q1) for plane elasticity (paper Section 4: "piecewise bilinear basis
// functions"). Element dofs are ordered node by node: (u_x0, u_y0, u_x1, u_y1, ...).

#include <Eigen/Core>

namespace signorini {

using Q1Coordinates = Eigen::Matrix<double, 2, 4>;  ///< columns: the 4 nodes, counterclockwise
using Q1Stiffness = Eigen::Matrix<double, 8, 8>;
using Q1Strain = Eigen::Matrix<double, 3, 8>;  ///< B: (e_xx, e_yy, 2 e_xy) = B u_e

/// Shape functions at reference point (xi, eta) in [-1, 1]^2.
Eigen::Vector4d q1_shape(double xi, double eta);
/// Their derivatives: column a = (dN_a/dxi, dN_a/deta).
Eigen::Matrix<double, 2, 4> q1_shape_gradients(double xi, double eta);

/// Strain-displacement matrix B at (xi, eta), and det J there. det J <= 0 means an inverted or
/// degenerate cell; the caller decides what to say.
Q1Strain q1_strain_matrix(const Q1Coordinates& X, double xi, double eta, double& det_j);

/// K_e = sum over the n x n Gauss points of B^T D B det J w (n = 2: the paper's 2x2 rule).
/// Throws InputError if det J <= 0 at a quadrature point.
Q1Stiffness q1_stiffness(const Q1Coordinates& X, const Eigen::Matrix3d& D, int gauss_points = 2);

}  // namespace signorini

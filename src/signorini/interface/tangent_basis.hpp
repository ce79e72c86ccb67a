#pragma once
// The tangent directions of a contact node (docs/method.md, "Friction"): the frame in which a
// frictional law's tangential components are given (friction_law.hpp, the rows of N).

#include <Eigen/Dense>

namespace signorini {

/// An orthonormal basis of the plane normal to the unit vector nu, as the columns of a
/// dim x (dim - 1) matrix: in 2D t = (-nu_y, nu_x), so that (nu, t) turns as (x, y); in 3D
/// t_1 = e x nu / |e x nu| with e the axis least aligned with nu, and t_2 = nu x t_1, so that
/// (nu, t_1, t_2) is right-handed.
[[nodiscard]] Eigen::MatrixXd tangent_basis(const Eigen::VectorXd& nu);

/// Tangential values per node ((d - 1) x nodes, each in the tangent_basis of its column of the
/// unit normals, d x nodes; ContactResult::tangential) as Cartesian vectors, d x nodes.
[[nodiscard]] Eigen::MatrixXd cartesian_tangential(const Eigen::MatrixXd& normals,
                                                   const Eigen::MatrixXd& tangential);

}  // namespace signorini

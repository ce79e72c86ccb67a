#pragma once
// Basic numeric types shared by every module.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>

namespace signorini {

using Index = std::int64_t;  // node, cell and dof numbers: meshes beyond 2^31 dofs fit.
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
// Column-major (CSC) with 32-bit indices: the stiffness of a 10-million-dof 2D problem has about
// 1.8e8 nonzeros, well below 2^31. Linear solvers convert to their own index width if needed.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// A point in physical space; 2D problems leave z = 0.
using Point = Eigen::Vector3d;

}  // namespace signorini

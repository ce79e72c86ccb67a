#pragma once
// Basic numeric types shared by every module.

#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <cstdint>

namespace signorini {

// Node, cell and dof numbers. 64-bit, but the matrices below use 32-bit indices, so a problem is
// limited by its number of matrix entries (< 2^31, sparsity_pattern.cpp refuses more).
using Index = std::int64_t;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
// Column-major (CSC) with 32-bit indices: the stiffness of a 10-million-dof 2D problem has about
// 1.8e8 nonzeros, well below 2^31. Linear solvers convert to their own index width if needed.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;
/// A SparseMatrix's layout over arrays held elsewhere (another library's CSR arrays of a
/// symmetric matrix are its CSC ones), for the kernels that read a matrix without copying it.
using SparseView = Eigen::Map<const SparseMatrix>;

/// The view of A itself (compressed or not).
inline SparseView view_of(const SparseMatrix& A) {
  return {A.rows(),          A.cols(),     A.nonZeros(),       A.outerIndexPtr(),
          A.innerIndexPtr(), A.valuePtr(), A.innerNonZeroPtr()};
}

/// A point in physical space; 2D problems leave z = 0.
using Point = Eigen::Vector3d;

}  // namespace signorini

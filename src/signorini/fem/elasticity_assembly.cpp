#include "signorini/fem/elasticity_assembly.hpp"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>

#include "signorini/core/error.hpp"
#include "signorini/fem/q1_element.hpp"
#include "signorini/fem/quadrature.hpp"
#include "signorini/fem/sparsity_pattern.hpp"

namespace signorini {

namespace {

Q1Coordinates cell_coordinates(const Mesh& mesh, Index c) {
  Q1Coordinates X;
  const auto nodes = mesh.cell(c);
  for (int a = 0; a < 4; ++a) X.col(a) = mesh.node(nodes[static_cast<std::size_t>(a)]);
  return X;
}

}  // namespace

void require_supported_cells(const Mesh& mesh) {
  if (mesh.cell_type() != CellType::Quad4)
    throw InputError("finite elements for cell type '" +
                     std::string(enum_to_string(kCellTypeNames, mesh.cell_type())) +
                     "' are not implemented yet (only quad4)");
}

SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options) {
  require_supported_cells(mesh);
  const Eigen::Matrix3d D = plane_elasticity_matrix(options.material, options.plane_model);
  const SparsityPattern pattern(mesh, dofs);
  SparseMatrix A = pattern.zero_matrix();
  double* values = A.valuePtr();
  // Cells that are translates of the previous one (all of them on a structured mesh) share its
  // element matrix: compare the node coordinates relative to the first node.
  Q1Coordinates previous = Q1Coordinates::Constant(std::numeric_limits<double>::quiet_NaN());
  Q1Stiffness K;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Q1Coordinates X = cell_coordinates(mesh, c);
    const Q1Coordinates relative = X.colwise() - X.col(0);
    const double size = relative.cwiseAbs().maxCoeff();
    if (!((relative - previous).cwiseAbs().maxCoeff() <= 1e-13 * size)) {
      try {
        K = q1_stiffness(X, D, options.gauss_points);
      } catch (const InputError& e) {
        throw InputError("mesh cell " + std::to_string(c) + ": " + e.what());
      }
      previous = relative;
    }
    const auto nodes = mesh.cell(c);
    std::array<Index, 4> block{};
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        pattern.block_positions(nodes[static_cast<std::size_t>(a)],
                                nodes[static_cast<std::size_t>(b)], block.data());
        for (int ka = 0; ka < 2; ++ka)
          for (int kb = 0; kb < 2; ++kb) {
            const Index pos = block[static_cast<std::size_t>(ka * 2 + kb)];
            if (pos >= 0) values[pos] += K(2 * a + ka, 2 * b + kb);  // clamped: eliminated
          }
      }
  }
  return A;
}

Vector internal_forces(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                       const std::function<bool(Index)>& needed) {
  require_supported_cells(mesh);
  const Eigen::Matrix3d D = plane_elasticity_matrix(options.material, options.plane_model);
  Vector f = Vector::Zero(u.size());
  Eigen::Matrix<double, 8, 1> ue;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (needed && !needed(c)) continue;
    const auto nodes = mesh.cell(c);
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 2; ++k) ue(2 * a + k) = u(nodes[static_cast<std::size_t>(a)] * 2 + k);
    const Eigen::Matrix<double, 8, 1> fe =
        q1_stiffness(cell_coordinates(mesh, c), D, options.gauss_points) * ue;
    for (int a = 0; a < 4; ++a)
      for (int k = 0; k < 2; ++k) f(nodes[static_cast<std::size_t>(a)] * 2 + k) += fe(2 * a + k);
  }
  return f;
}

}  // namespace signorini

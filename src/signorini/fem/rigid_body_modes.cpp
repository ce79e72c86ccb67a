#include "signorini/fem/rigid_body_modes.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

Matrix rigid_body_modes(const Mesh& mesh, const DofMap& dofs, Index first, Index end,
                        const Eigen::VectorXd* centre_given) {
  if (mesh.dim() != dofs.dim() || mesh.num_nodes() != dofs.num_nodes())
    throw NumericalError("rigid_body_modes: the dof map does not match the mesh");
  const int dim = dofs.dim();
  if (dim != 2 && dim != 3)
    throw NumericalError(fmt::format("rigid_body_modes: {}D meshes are not supported", dim));
  const int count = dim == 2 ? 3 : 6;
  if (end < 0) end = dofs.num_free();
  if (first < 0 || first > end || end > dofs.num_free())
    throw NumericalError(fmt::format("rigid_body_modes: rows [{}, {}) of {} free dofs", first, end,
                                     dofs.num_free()));
  // The rotations about the centroid keep their columns as well scaled as the translations'.
  const Eigen::VectorXd centre = centre_given != nullptr
                                     ? *centre_given
                                     : Eigen::VectorXd(mesh.coordinates().rowwise().mean());
  Matrix B = Matrix::Zero(end - first, count);
  Eigen::Matrix<double, 3, 6> modes;
  for (Index node = 0; node < dofs.num_nodes(); ++node) {
    const Eigen::VectorXd x = mesh.node(node) - centre;
    if (dim == 2) {
      // Translations along x and y, and the rotation about the z axis, u = (-y, x); at a node
      // with local axes, their components along them.
      Eigen::Matrix<double, 2, 3> m2;
      m2 << 1.0, 0.0, -x[1], 0.0, 1.0, x[0];
      if (dofs.has_frame(node)) m2 = (dofs.frame(node).transpose() * m2).eval();
      modes.topLeftCorner<2, 3>() = m2;
    } else {
      // Translations along x, y, z, and the rotations about the three axes, u = e_k x r.
      modes.leftCols<3>().setIdentity();
      modes.col(3) << 0.0, -x[2], x[1];
      modes.col(4) << x[2], 0.0, -x[0];
      modes.col(5) << -x[1], x[0], 0.0;
    }
    for (int k = 0; k < dim; ++k) {
      const Index f = dofs.free_index(node, k);
      if (f < first || f >= end) continue;  // (f < 0: not free)
      B.row(f - first) = modes.row(k).head(count);
    }
  }
  return B;
}

std::vector<Index> free_dof_nodes(const DofMap& dofs) {
  std::vector<Index> node(static_cast<std::size_t>(dofs.num_free()));
  for (Index a = 0; a < dofs.num_nodes(); ++a)
    for (int k = 0; k < dofs.dim(); ++k) {
      const Index f = dofs.free_index(a, k);
      if (f >= 0) node[static_cast<std::size_t>(f)] = a;
    }
  return node;
}

}  // namespace signorini

#include "signorini/fem/rigid_body_modes.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

Matrix rigid_body_modes(const Mesh& mesh, const DofMap& dofs) {
  if (mesh.dim() != dofs.dim() || mesh.num_nodes() != dofs.num_nodes())
    throw NumericalError("rigid_body_modes: the dof map does not match the mesh");
  // Only plane elasticity exists so far; 3D would add three translations and three rotations.
  if (dofs.dim() != 2)
    throw NumericalError(
        fmt::format("rigid_body_modes: {}D meshes are not supported yet", dofs.dim()));
  // The rotation about the centroid keeps its column as well scaled as the translations'.
  const Eigen::Vector2d centre = mesh.coordinates().topRows(2).rowwise().mean();
  Matrix B = Matrix::Zero(dofs.num_free(), 3);
  for (Index node = 0; node < dofs.num_nodes(); ++node) {
    const Eigen::Vector2d x = mesh.node(node).head(2) - centre;
    // Translations along x and y, and the rotation about the z axis, u = (-y, x); at a node with
    // local axes, their components along them.
    Eigen::Matrix<double, 2, 3> modes;
    modes << 1.0, 0.0, -x[1], 0.0, 1.0, x[0];
    if (dofs.has_frame(node)) modes = (dofs.frame(node).transpose() * modes).eval();
    for (int k = 0; k < 2; ++k) {
      const Index f = dofs.free_index(node, k);
      if (f < 0) continue;
      B.row(f) = modes.row(k);
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

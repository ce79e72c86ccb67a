#include "signorini/fem/nodal_stress.hpp"

#include <cmath>

#include "signorini/fem/isoparametric_element.hpp"

namespace signorini {

double von_mises_stress(double sxx, double syy, double szz, double sxy) {
  const double d =
      (sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx);
  return std::sqrt(0.5 * d + 3.0 * sxy * sxy);
}

NodalStress nodal_stress(const Mesh& mesh, const ElasticityOptions& options, const Vector& u_full) {
  require_supported_cells(mesh);
  const std::vector<Eigen::Matrix3d> region_D = region_elasticity_matrices(mesh, options);
  const bool plane_strain = options.plane_model == PlaneModel::PlaneStrain;
  NodalStress out;
  out.sigma = Eigen::MatrixXd::Zero(4, mesh.num_nodes());
  Vector count = Vector::Zero(mesh.num_nodes());
  ElementVector ue;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType type = mesh.cell_type(c);
    const auto nodes = mesh.cell(c);
    const auto n = static_cast<int>(nodes.size());
    const CellCoordinates X = cell_coordinates(mesh, c);
    const Eigen::Matrix3d& D = region_D[static_cast<std::size_t>(mesh.cell_region(c))];
    const double nu = material_of_region(options, mesh.cell_region(c)).nu;
    ue.resize(2 * n);
    for (int a = 0; a < n; ++a) {
      const Index v = nodes[static_cast<std::size_t>(a)];
      ue(2 * a) = u_full(2 * v);
      ue(2 * a + 1) = u_full(2 * v + 1);
    }
    // The strain of the cell at each of its nodes (the cell's own polynomial, not a recovery).
    for (int a = 0; a < n; ++a) {
      double det_j = 0.0;
      const StrainMatrix B = strain_matrix(type, X, reference_node(type, a), det_j);
      const Eigen::Vector3d s = D * (B * ue);
      const Index v = nodes[static_cast<std::size_t>(a)];
      out.sigma(0, v) += s(0);
      out.sigma(1, v) += s(1);
      out.sigma(2, v) += plane_strain ? nu * (s(0) + s(1)) : 0.0;
      out.sigma(3, v) += s(2);
      count(v) += 1.0;
    }
  }
  out.von_mises.resize(mesh.num_nodes());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    if (count(n) > 0.0) out.sigma.col(n) /= count(n);
    out.von_mises(n) =
        von_mises_stress(out.sigma(0, n), out.sigma(1, n), out.sigma(2, n), out.sigma(3, n));
  }
  return out;
}

}  // namespace signorini

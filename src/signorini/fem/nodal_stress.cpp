#include "signorini/fem/nodal_stress.hpp"

#include <cmath>

#include "signorini/fem/q1_element.hpp"

namespace signorini {

double von_mises_stress(double sxx, double syy, double szz, double sxy) {
  const double d =
      (sxx - syy) * (sxx - syy) + (syy - szz) * (syy - szz) + (szz - sxx) * (szz - sxx);
  return std::sqrt(0.5 * d + 3.0 * sxy * sxy);
}

NodalStress nodal_stress(const Mesh& mesh, const ElasticityOptions& options, const Vector& u_full) {
  const Eigen::Matrix3d D = plane_elasticity_matrix(options.material, options.plane_model);
  const double nu = options.material.nu;
  const bool plane_strain = options.plane_model == PlaneModel::PlaneStrain;
  NodalStress out;
  out.sigma = Eigen::MatrixXd::Zero(4, mesh.num_nodes());
  Vector count = Vector::Zero(mesh.num_nodes());
  constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};
  constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell(c);
    Q1Coordinates X;
    Eigen::Matrix<double, 8, 1> ue;
    for (int a = 0; a < 4; ++a) {
      const Index n = nodes[static_cast<std::size_t>(a)];
      X.col(a) = mesh.node(n);
      ue(2 * a) = u_full(2 * n);
      ue(2 * a + 1) = u_full(2 * n + 1);
    }
    for (int a = 0; a < 4; ++a) {
      double det_j = 0.0;
      const Q1Strain B = q1_strain_matrix(X, kXi[a], kEta[a], det_j);
      const Eigen::Vector3d s = D * (B * ue);
      const Index n = nodes[static_cast<std::size_t>(a)];
      out.sigma(0, n) += s(0);
      out.sigma(1, n) += s(1);
      out.sigma(2, n) += plane_strain ? nu * (s(0) + s(1)) : 0.0;
      out.sigma(3, n) += s(2);
      count(n) += 1.0;
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

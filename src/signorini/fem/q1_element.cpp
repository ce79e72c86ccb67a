#include "signorini/fem/q1_element.hpp"

#include <Eigen/LU>

#include "signorini/core/error.hpp"
#include "signorini/fem/quadrature.hpp"

namespace signorini {

namespace {
constexpr double kXiNode[4] = {-1.0, 1.0, 1.0, -1.0};
constexpr double kEtaNode[4] = {-1.0, -1.0, 1.0, 1.0};
}  // namespace

Eigen::Vector4d q1_shape(double xi, double eta) {
  Eigen::Vector4d N;
  for (int a = 0; a < 4; ++a) N(a) = 0.25 * (1.0 + kXiNode[a] * xi) * (1.0 + kEtaNode[a] * eta);
  return N;
}

Eigen::Matrix<double, 2, 4> q1_shape_gradients(double xi, double eta) {
  Eigen::Matrix<double, 2, 4> G;
  for (int a = 0; a < 4; ++a) {
    G(0, a) = 0.25 * kXiNode[a] * (1.0 + kEtaNode[a] * eta);
    G(1, a) = 0.25 * kEtaNode[a] * (1.0 + kXiNode[a] * xi);
  }
  return G;
}

Q1Strain q1_strain_matrix(const Q1Coordinates& X, double xi, double eta, double& det_j) {
  const Eigen::Matrix<double, 2, 4> dN = q1_shape_gradients(xi, eta);
  const Eigen::Matrix2d J = dN * X.transpose();  // J(i, k) = d x_k / d xi_i
  det_j = J.determinant();
  Q1Strain B = Q1Strain::Zero();
  if (!(det_j > 0.0)) return B;
  const Eigen::Matrix<double, 2, 4> dNdx = J.inverse() * dN;  // rows: d/dx, d/dy
  for (int a = 0; a < 4; ++a) {
    B(0, 2 * a) = dNdx(0, a);
    B(1, 2 * a + 1) = dNdx(1, a);
    B(2, 2 * a) = dNdx(1, a);
    B(2, 2 * a + 1) = dNdx(0, a);
  }
  return B;
}

Q1Stiffness q1_stiffness(const Q1Coordinates& X, const Eigen::Matrix3d& D, int gauss_points) {
  const auto rule = gauss_legendre(gauss_points);
  Q1Stiffness K = Q1Stiffness::Zero();
  for (const auto& qx : rule)
    for (const auto& qy : rule) {
      double det_j = 0.0;
      const Q1Strain B = q1_strain_matrix(X, qx.x, qy.x, det_j);
      if (!(det_j > 0.0))
        throw InputError("inverted or degenerate quadrilateral (det J = " + std::to_string(det_j) +
                         " at a quadrature point): expected counterclockwise, convex cells");
      K.noalias() += B.transpose() * D * B * (det_j * qx.w * qy.w);
    }
  return K;
}

}  // namespace signorini

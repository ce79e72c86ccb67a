#include "signorini/fem/material.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "signorini/core/error.hpp"

namespace signorini {

void validate(const IsotropicMaterial& m) {
  if (!std::isfinite(m.E) || m.E <= 0.0)
    throw InputError(fmt::format("material.E = {:g}: expected a positive modulus", m.E));
  if (!std::isfinite(m.nu) || m.nu <= -1.0 || m.nu >= 0.5)
    throw InputError(
        fmt::format("material.nu = {:g}: expected a Poisson ratio in (-1, 0.5)", m.nu));
}

Eigen::Matrix3d plane_elasticity_matrix(const IsotropicMaterial& m, PlaneModel model) {
  validate(m);
  const double E = m.E;
  const double nu = m.nu;
  Eigen::Matrix3d D = Eigen::Matrix3d::Zero();
  if (model == PlaneModel::PlaneStrain) {
    const double c = E / ((1.0 + nu) * (1.0 - 2.0 * nu));
    D << c * (1.0 - nu), c * nu, 0.0,  //
        c * nu, c * (1.0 - nu), 0.0,   //
        0.0, 0.0, c * (1.0 - 2.0 * nu) / 2.0;
  } else {
    const double c = E / (1.0 - nu * nu);
    D << c, c * nu, 0.0,  //
        c * nu, c, 0.0,   //
        0.0, 0.0, c * (1.0 - nu) / 2.0;
  }
  return D;
}

Eigen::Matrix<double, 6, 6> elasticity_matrix_3d(const IsotropicMaterial& m) {
  validate(m);
  const double lambda = m.E * m.nu / ((1.0 + m.nu) * (1.0 - 2.0 * m.nu));
  const double mu = m.E / (2.0 * (1.0 + m.nu));
  Eigen::Matrix<double, 6, 6> D = Eigen::Matrix<double, 6, 6>::Zero();
  D.topLeftCorner<3, 3>().setConstant(lambda);
  D.topLeftCorner<3, 3>().diagonal().array() += 2.0 * mu;
  D.bottomRightCorner<3, 3>().diagonal().setConstant(mu);  // shear: tau = mu (2 e)
  return D;
}

}  // namespace signorini

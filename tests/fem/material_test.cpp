#include "signorini/fem/material.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

TEST(Material, RejectsBadModulusAndPoissonRatio) {
  EXPECT_THROW(validate(IsotropicMaterial{-1.0, 0.3}), InputError);
  EXPECT_THROW(validate(IsotropicMaterial{0.0, 0.3}), InputError);
  EXPECT_THROW(validate(IsotropicMaterial{1.0, 0.5}), InputError);
  EXPECT_THROW(validate(IsotropicMaterial{1.0, -1.0}), InputError);
  EXPECT_THROW(validate(IsotropicMaterial{std::nan(""), 0.3}), InputError);
  EXPECT_NO_THROW(validate(IsotropicMaterial{1.0, 0.49}));
}

TEST(Material, PlaneStrainAndStressMatrices) {
  const double E = 210.0, nu = 0.25;
  const Eigen::Matrix3d Ds = plane_elasticity_matrix({E, nu}, PlaneModel::PlaneStress);
  // Uniaxial stress: s_xx = E e_xx when e_yy = -nu e_xx.
  EXPECT_NEAR((Ds * Eigen::Vector3d(1.0, -nu, 0.0))(0), E, 1e-12);
  EXPECT_NEAR((Ds * Eigen::Vector3d(1.0, -nu, 0.0))(1), 0.0, 1e-12);
  const Eigen::Matrix3d De = plane_elasticity_matrix({E, nu}, PlaneModel::PlaneStrain);
  const double mu = E / (2.0 * (1.0 + nu));
  const double lambda = E * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
  EXPECT_NEAR(De(0, 0), lambda + 2.0 * mu, 1e-10);
  EXPECT_NEAR(De(0, 1), lambda, 1e-10);
  EXPECT_NEAR(De(2, 2), mu, 1e-10);
}

}  // namespace
}  // namespace signorini

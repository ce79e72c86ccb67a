#include "signorini/fem/q1_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "signorini/core/error.hpp"
#include "signorini/fem/material.hpp"

namespace signorini {
namespace {

Q1Coordinates distorted_quad() {
  Q1Coordinates X;
  X << 0.0, 2.0, 2.3, -0.2,  //
      0.0, 0.3, 1.6, 1.1;
  return X;
}

TEST(Q1Element, ShapeFunctionsPartitionUnityAndInterpolateNodes) {
  for (double xi : {-0.7, 0.0, 0.4})
    for (double eta : {-0.3, 0.9}) {
      EXPECT_NEAR(q1_shape(xi, eta).sum(), 1.0, 1e-15);
      EXPECT_NEAR(q1_shape_gradients(xi, eta).rowwise().sum().norm(), 0.0, 1e-15);
    }
  EXPECT_NEAR(q1_shape(1.0, 1.0)(2), 1.0, 1e-15);
  EXPECT_NEAR(q1_shape(1.0, 1.0)(0), 0.0, 1e-15);
}

TEST(Q1Element, StiffnessSymmetricPsdWithExactlyThreeRigidBodyModes) {
  for (const auto model : {PlaneModel::PlaneStrain, PlaneModel::PlaneStress}) {
    const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, model);
    const Q1Stiffness K = q1_stiffness(distorted_quad(), D);
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    const Eigen::SelfAdjointEigenSolver<Q1Stiffness> eig(K);
    const auto& ev = eig.eigenvalues();  // ascending
    const double top = ev(7);
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(ev(i)), 1e-12 * top) << "eigenvalue " << i;
    for (int i = 3; i < 8; ++i) EXPECT_GT(ev(i), 1e-3 * top) << "eigenvalue " << i;

    // The kernel is spanned by the two translations and the infinitesimal rotation.
    const Q1Coordinates X = distorted_quad();
    Eigen::Matrix<double, 8, 3> rigid;
    for (int a = 0; a < 4; ++a) {
      rigid.row(2 * a) << 1.0, 0.0, -X(1, a);
      rigid.row(2 * a + 1) << 0.0, 1.0, X(0, a);
    }
    EXPECT_LT((K * rigid).norm(), 1e-12 * top * rigid.norm());
  }
}

TEST(Q1Element, InvertedCellIsReported) {
  Q1Coordinates X = distorted_quad();
  X.col(1).swap(X.col(3));  // clockwise
  const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, PlaneModel::PlaneStrain);
  EXPECT_THROW(q1_stiffness(X, D), InputError);
}

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

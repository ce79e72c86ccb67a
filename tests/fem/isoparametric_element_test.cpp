// Element stiffness of every cell type on a distorted (and, for quadratic cells, curved) cell:
// symmetric, positive semidefinite, with exactly the rigid motions in its kernel (three in 2D, six
// in 3D); uniform strains reproduced; an inverted cell is reported.

#include "signorini/fem/isoparametric_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <algorithm>
#include <stdexcept>

#include "signorini/core/error.hpp"
#include "signorini/fem/material.hpp"

namespace signorini {
namespace {

// The reference nodes mapped by a smooth, orientation-preserving distortion: straight edges
// become curved ones where the cell has mid-edge nodes.
CellCoordinates distorted_cell(CellType t) {
  const int n = nodes_per_cell(t);
  CellCoordinates X(2, n);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d r = reference_node(t, a);
    X(0, a) = 1.3 * r(0) + 0.2 * r(1) + 0.08 * r(1) * r(1);
    X(1, a) = 0.1 * r(0) + 0.9 * r(1) + 0.06 * r(0) * r(0);
  }
  return X;
}

class IsoparametricElement : public ::testing::TestWithParam<CellType> {};

TEST_P(IsoparametricElement, StiffnessSymmetricPsdWithExactlyThreeRigidBodyModes) {
  const CellType t = GetParam();
  const int n = nodes_per_cell(t);
  for (const auto model : {PlaneModel::PlaneStrain, PlaneModel::PlaneStress}) {
    const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, model);
    const CellCoordinates X = distorted_cell(t);
    const Eigen::MatrixXd K = element_stiffness(t, X, D, cell_quadrature(t));
    ASSERT_EQ(K.rows(), 2 * n);
    EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
    const Eigen::VectorXd& ev = eig.eigenvalues();  // ascending
    const double top = ev(2 * n - 1);
    for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(ev(i)), 1e-12 * top) << "eigenvalue " << i;
    // Quad8 and P2 with their rules have no spurious zero-energy modes either.
    for (int i = 3; i < 2 * n; ++i) EXPECT_GT(ev(i), 1e-6 * top) << "eigenvalue " << i;
    Eigen::MatrixXd rigid(2 * n, 3);
    for (int a = 0; a < n; ++a) {
      rigid.row(2 * a) << 1.0, 0.0, -X(1, a);
      rigid.row(2 * a + 1) << 0.0, 1.0, X(0, a);
    }
    EXPECT_LT((K * rigid).norm(), 1e-12 * top * rigid.norm());
  }
}

TEST_P(IsoparametricElement, InvertedCellIsReported) {
  const CellType t = GetParam();
  CellCoordinates X = distorted_cell(t);
  X.row(1) *= -1.0;  // mirrored: clockwise
  const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, PlaneModel::PlaneStrain);
  try {
    (void)element_stiffness(t, X, D, cell_quadrature(t));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inverted or degenerate"), std::string::npos);
  }
}

// 3D: a distorted (curved, for quadratic cells) cell of each type has a symmetric, positive
// semidefinite stiffness with exactly the six rigid motions in its kernel, and a mirrored one is
// reported as inverted.
CellCoordinatesOf<3> distorted_solid(CellType t) {
  const int n = nodes_per_cell(t);
  CellCoordinatesOf<3> X(3, n);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d r = reference_node(t, a);
    X(0, a) = 1.3 * r(0) + 0.2 * r(1) + 0.05 * r(2) + 0.08 * r(1) * r(1);
    X(1, a) = 0.1 * r(0) + 0.9 * r(1) - 0.1 * r(2) + 0.06 * r(0) * r(0);
    X(2, a) = 0.05 * r(0) + 0.1 * r(1) + 1.1 * r(2) + 0.04 * r(0) * r(1);
  }
  return X;
}

class SolidElement : public ::testing::TestWithParam<CellType> {};

TEST_P(SolidElement, StiffnessSymmetricPsdWithExactlySixRigidBodyModes) {
  const CellType t = GetParam();
  const int n = nodes_per_cell(t);
  const ElasticityMatrixOf<3> D = elasticity_matrix_3d({1000.0, 0.3});
  const CellCoordinatesOf<3> X = distorted_solid(t);
  const Eigen::MatrixXd K = element_stiffness<3>(t, X, D, cell_quadrature(t));
  ASSERT_EQ(K.rows(), 3 * n);
  EXPECT_LT((K - K.transpose()).norm(), 1e-12 * K.norm());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const Eigen::VectorXd& ev = eig.eigenvalues();  // ascending
  const double top = ev(3 * n - 1);
  for (int i = 0; i < 6; ++i) EXPECT_LT(std::abs(ev(i)), 1e-11 * top) << "eigenvalue " << i;
  for (int i = 6; i < 3 * n; ++i) EXPECT_GT(ev(i), 1e-8 * top) << "eigenvalue " << i;
  Eigen::MatrixXd rigid = Eigen::MatrixXd::Zero(3 * n, 6);
  for (int a = 0; a < n; ++a) {
    const Eigen::Vector3d x = X.col(a);
    rigid.block<3, 3>(3 * a, 0).setIdentity();
    for (int k = 0; k < 3; ++k) rigid.block<3, 1>(3 * a, 3 + k) = Eigen::Vector3d::Unit(k).cross(x);
  }
  EXPECT_LT((K * rigid).norm(), 1e-11 * top * rigid.norm());
}

TEST_P(SolidElement, UniformStrainGivesItsStressEverywhere) {
  // u = E x with a constant, symmetric E: B u_e is E's Voigt vector at every point.
  const CellType t = GetParam();
  const CellCoordinatesOf<3> X = distorted_solid(t);
  Eigen::Matrix3d E;
  E << 1.0, 0.2, -0.3,  //
      0.2, -0.5, 0.4,   //
      -0.3, 0.4, 0.7;
  ElementVectorOf<3> ue(3 * X.cols());
  for (Index a = 0; a < X.cols(); ++a) ue.segment<3>(3 * a) = E * X.col(a);
  for (const QuadraturePoint& q : cell_quadrature(t)) {
    double det_j = 0.0;
    const StrainMatrixOf<3> B = strain_matrix<3>(t, X, q.xi, det_j);
    ASSERT_GT(det_j, 0.0);
    Eigen::Matrix<double, 6, 1> expected;
    expected << E(0, 0), E(1, 1), E(2, 2), 2 * E(1, 2), 2 * E(0, 2), 2 * E(0, 1);
    EXPECT_LT((B * ue - expected).norm(), 1e-12) << "at " << q.xi.transpose();
  }
}

TEST_P(SolidElement, InvertedCellIsReported) {
  const CellType t = GetParam();
  CellCoordinatesOf<3> X = distorted_solid(t);
  X.row(2) *= -1.0;  // mirrored
  try {
    (void)element_stiffness<3>(t, X, elasticity_matrix_3d({1000.0, 0.3}), cell_quadrature(t));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inverted or degenerate"), std::string::npos);
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, SolidElement,
                         ::testing::Values(CellType::Tet4, CellType::Tet10, CellType::Hex8,
                                           CellType::Hex27),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

TEST(IsoparametricElementTypes, CellsOfAnotherDimensionAreALogicError) {
  const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, PlaneModel::PlaneStrain);
  const CellCoordinates X = CellCoordinates::Zero(2, 4);
  EXPECT_THROW((void)element_stiffness(CellType::Tet4, X, D, cell_quadrature(CellType::Tet4)),
               std::logic_error);
}

INSTANTIATE_TEST_SUITE_P(CellTypes, IsoparametricElement,
                         ::testing::Values(CellType::Tri3, CellType::Tri6, CellType::Quad4,
                                           CellType::Quad8, CellType::Quad9),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

}  // namespace
}  // namespace signorini

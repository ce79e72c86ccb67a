// Element stiffness of every 2D cell type on a distorted (and, for quadratic cells, curved)
// cell: symmetric, positive semidefinite, with exactly the three rigid motions in its kernel;
// an inverted cell is reported.

#include "signorini/fem/isoparametric_element.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>

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

TEST(IsoparametricElementTypes, ThreeDimensionalCellsAreRefused) {
  // 3D types have shape functions (reference_element.hpp) but no plane kernel here.
  const Eigen::Matrix3d D = plane_elasticity_matrix({1000.0, 0.3}, PlaneModel::PlaneStrain);
  for (const CellType t : {CellType::Tet4, CellType::Tet10, CellType::Hex8, CellType::Hex27}) {
    const CellCoordinates X = CellCoordinates::Zero(2, std::min(nodes_per_cell(t), 9));
    try {
      (void)element_stiffness(t, X, D, cell_quadrature(t));
      FAIL() << enum_to_string(kCellTypeNames, t);
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("expected a 2D cell type"), std::string::npos)
          << e.what();
    }
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, IsoparametricElement,
                         ::testing::Values(CellType::Tri3, CellType::Tri6, CellType::Quad4,
                                           CellType::Quad8, CellType::Quad9),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

}  // namespace
}  // namespace signorini

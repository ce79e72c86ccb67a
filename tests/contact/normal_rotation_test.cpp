// The rotation of each contact node's unknowns onto its normal (src/signorini/contact/
// normal_rotation.hpp): Q^T A Q in place, also on a partitioned problem's A, which holds only
// its rank's columns (ContactProblem::column_of).

#include "signorini/contact/normal_rotation.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "signorini/interface/contact_set.hpp"

namespace signorini {
namespace {

// Three 2D nodes (unknowns 2 v, 2 v + 1), nodes 0 and 2 in contact with oblique normals; A
// dense, symmetric and positive definite, so every node block has the same columns.
struct Rotated {
  ContactSet contact;
  SparseMatrix A;
  Rotated() {
    contact.nodes = {0, 2};
    contact.weights = Vector::Ones(2);
    contact.gaps = Vector::Zero(2);
    contact.movable = {true, true};
    std::vector<Eigen::Triplet<double, int>> n = {
        {0, 0, 0.6}, {0, 1, 0.8}, {1, 4, -0.8}, {1, 5, 0.6}};
    contact.N.resize(2, 6);
    contact.N.setFromTriplets(n.begin(), n.end());
    Matrix M = Matrix::Random(6, 6);
    const Matrix spd = M * M.transpose() + 6.0 * Matrix::Identity(6, 6);
    A = spd.sparseView();
  }
};

TEST(NormalRotation, RotatedMatrixIsQTransposeAQ) {
  const Rotated r;
  const NormalRotation rotation = make_normal_rotation(r.contact, 6);
  ASSERT_FALSE(rotation.identity());
  const Matrix Q = Matrix(rotation.Q);
  const Matrix expected = Q.transpose() * Matrix(r.A) * Q;
  EXPECT_LT((Matrix(rotate_matrix(r.A, rotation)) - expected).norm(), 1e-13 * expected.norm());
  // The normal unknown of each contact node carries its normal: (N Q) e_normal_dof = scale.
  const Matrix NQ = Matrix(r.contact.N) * Q;
  for (Index j = 0; j < 2; ++j)
    EXPECT_NEAR(NQ(j, rotation.normal_dof[static_cast<std::size_t>(j)]), rotation.scale(j), 1e-15);
}

TEST(NormalRotation, HeldColumnsRotateAsTheirColumnsOfTheWhole) {
  const Rotated r;
  const NormalRotation rotation = make_normal_rotation(r.contact, 6);
  const Matrix whole = Matrix(rotate_matrix(r.A, rotation));
  // A rank holding nodes 1 and 2 (unknowns [2, 6)), and one holding node 0 ([0, 2)): each
  // rotates its columns, the other nodes' rows included.
  const SparseMatrix right = r.A.rightCols(4);
  const SparseMatrix rotated_right = rotate_matrix(right, rotation, 2);
  ASSERT_EQ(rotated_right.cols(), 4);
  EXPECT_LT((Matrix(rotated_right) - whole.rightCols(4)).norm(), 1e-13 * whole.norm());
  const SparseMatrix left = r.A.leftCols(2);
  EXPECT_LT((Matrix(rotate_matrix(left, rotation, 0)) - whole.leftCols(2)).norm(),
            1e-13 * whole.norm());
  // A pattern that the in-place rotation cannot take (node 2's columns differ) goes through
  // the sparse product, with the same result.
  Matrix sparse_pattern = Matrix(r.A);
  sparse_pattern(0, 5) = sparse_pattern(5, 0) = 0.0;
  const SparseMatrix B = sparse_pattern.sparseView();
  const Matrix Q = Matrix(rotation.Q);
  const Matrix expected = Q.transpose() * sparse_pattern * Q;
  EXPECT_LT(
      (Matrix(rotate_matrix(SparseMatrix(B.rightCols(4)), rotation, 2)) - expected.rightCols(4))
          .norm(),
      1e-13 * expected.norm());
}

}  // namespace
}  // namespace signorini

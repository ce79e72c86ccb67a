// The contact zone's eigenvalue estimate (iterative/contact_zone_estimate.hpp) against dense
// eigensolvers: it is lambda_max(D_ZZ^-1 H_ZZ) of the principal submatrix on the unknowns that the
// active contact rows touch, and by interlacing below H's own.

#include "signorini/iterative/contact_zone_estimate.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

// The paper's problem on 30 x 10 with oblique normals (0.6, -0.8) (both components of each
// contact node's row) and the first half of the contact nodes active, with the paper's r = 1e8
// (stiff against A).
struct Case {
  const Model& model = testing::paper_model(30);
  SparseMatrix N = model.problem.contact.N;
  Vector c;
  Matrix H;
  std::vector<Index> zone;  // the unknowns that the active rows touch, found here independently
  Case() {
    for (Index j = 0; j < N.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(N, j); it; ++it) it.valueRef() = j % 2 == 0 ? 0.6 : -0.8;
    c = Vector::Zero(N.rows());
    for (Index j = 0; j < N.rows() / 2; ++j)
      if (model.problem.contact.movable[static_cast<std::size_t>(j)])
        c(j) = 1e8 * model.problem.contact.weights(j);
    H = Matrix(model.problem.A) + Matrix(N).transpose() * c.asDiagonal() * Matrix(N);
    const Matrix Nd(N);
    for (Index i = 0; i < Nd.cols(); ++i) {
      bool touched = false;
      for (Index j = 0; j < Nd.rows(); ++j) touched = touched || (c(j) > 0.0 && Nd(j, i) != 0.0);
      if (touched) zone.push_back(i);
    }
  }
};

TEST(ContactZoneEstimate, IsTheZonesLargestEigenvalueAndBelowTheWholeOperators) {
  const Case k;
  ASSERT_GT(k.zone.size(), 10U);
  Matrix Hzz(static_cast<Index>(k.zone.size()), static_cast<Index>(k.zone.size()));
  for (std::size_t a = 0; a < k.zone.size(); ++a)
    for (std::size_t b = 0; b < k.zone.size(); ++b)
      Hzz(static_cast<Index>(a), static_cast<Index>(b)) = k.H(k.zone[a], k.zone[b]);
  const double zone = testing::dense_jacobi_lambda_max(Hzz);
  const double whole = testing::dense_jacobi_lambda_max(k.H);
  const SparseMatrix Nt = k.N.transpose();
  const double estimate = contact_zone_lambda_max(k.model.problem.A, Nt, k.c, 12);
  EXPECT_LE(estimate, zone * (1.0 + 1e-10));  // a Ritz value of the zone's matrix
  EXPECT_GT(estimate, 0.99 * zone);
  EXPECT_LE(zone, whole * (1.0 + 1e-10));  // Cauchy's interlacing
  // The rule of the multigrid's refresh: A's or the zone's, whichever is larger, is H's.
  const double stiffness = testing::dense_jacobi_lambda_max(Matrix(k.model.problem.A));
  EXPECT_GT(std::max(stiffness, estimate), 0.98 * whole) << stiffness << ", " << estimate;
}

TEST(ContactZoneEstimate, NoActiveRowIsNoZone) {
  const Case k;
  const SparseMatrix Nt = k.N.transpose();
  EXPECT_EQ(contact_zone_lambda_max(k.model.problem.A, Nt, Vector::Zero(Nt.cols()), 12), 0.0);
}

TEST(ContactZoneEstimate, RefusesMismatchedSizes) {
  const Case k;
  const SparseMatrix Nt = k.N.transpose();
  EXPECT_THROW(
      (void)contact_zone_lambda_max(k.model.problem.A, Nt, Vector::Ones(Nt.cols() + 1), 12),
      NumericalError);
  EXPECT_THROW((void)contact_zone_lambda_max(k.model.problem.A,
                                             SparseMatrix(Nt.rows() + 1, Nt.cols()), k.c, 12),
               NumericalError);
}

}  // namespace
}  // namespace signorini

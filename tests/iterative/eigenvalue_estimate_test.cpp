// The one spectral estimate (Lanczos from the coefficients of PCG), against eigenvalues known in
// closed form or computed densely.

#include "signorini/iterative/eigenvalue_estimate.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <numbers>
#include <vector>

#include "signorini/backend/host_backend.hpp"
#include "signorini/core/error.hpp"
#include "signorini/iterative/jacobi_preconditioner.hpp"

namespace signorini {
namespace {

// The 1D Laplacian tridiag(-1, 2, -1) of order n, scaled row and column by s (so that Jacobi
// preconditioning has something to undo): eigenvalues of D^{-1} A are those of tridiag(-1/2, 1,
// -1/2), 1 - cos(k pi / (n + 1)).
SparseMatrix scaled_laplacian(Index n, const Vector& s) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(i, i, 2.0 * s(i) * s(i));
    if (i + 1 < n) {
      t.emplace_back(i, i + 1, -s(i) * s(i + 1));
      t.emplace_back(i + 1, i, -s(i) * s(i + 1));
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

TEST(EigenvalueEstimate, LaplacianWithIdentityIsJustBelowTheLargestEigenvalue) {
  const Index n = 400;
  const SparseMatrix A = scaled_laplacian(n, Vector::Ones(n));
  HostBackend host;
  SymmetricMatrixOperator op(A);
  IdentityPreconditioner identity;
  const DeviceVector start = to_device(host, eigenvalue_estimate_start(n));
  const double exact = 2.0 + 2.0 * std::cos(std::numbers::pi / static_cast<double>(n + 1));
  const double few = estimate_largest_eigenvalue(op, identity, start, 12);
  const double more = estimate_largest_eigenvalue(op, identity, start, 60);
  EXPECT_LE(few, exact * (1.0 + 1e-12));  // a Ritz value: from below
  EXPECT_LE(more, exact * (1.0 + 1e-12));
  EXPECT_GT(few, 0.97 * exact);
  EXPECT_LE(few, more * (1.0 + 1e-12));  // more steps, a larger Krylov space: closer
  EXPECT_LT(exact - more, 1e-3 * exact);
}

TEST(EigenvalueEstimate, JacobiPreconditioningUndoesADiagonalScaling) {
  const Index n = 300;
  Vector s(n);
  for (Index i = 0; i < n; ++i)
    s(i) = 1.0 + 9.0 * std::abs(std::sin(0.37 * static_cast<double>(i)));
  const SparseMatrix A = scaled_laplacian(n, s);
  HostBackend host;
  SymmetricMatrixOperator op(A);
  const DeviceVector dinv = to_device(host, Vector(A.diagonal().cwiseInverse()));
  DiagonalPreconditioner jacobi(dinv);
  const DeviceVector start = to_device(host, eigenvalue_estimate_start(n));
  const double exact = 1.0 + std::cos(std::numbers::pi / static_cast<double>(n + 1));
  const double estimate = estimate_largest_eigenvalue(op, jacobi, start, 60);
  EXPECT_LE(estimate, exact * (1.0 + 1e-12));
  EXPECT_LT(exact - estimate, 1e-3 * exact);
  // Unpreconditioned, the same matrix has a far larger top eigenvalue (about 4 max s^2).
  IdentityPreconditioner identity;
  const double plain = estimate_largest_eigenvalue(op, identity, start, 60);
  const double dense = Eigen::SelfAdjointEigenSolver<Matrix>(Matrix(A), Eigen::EigenvaluesOnly)
                           .eigenvalues()
                           .maxCoeff();
  EXPECT_LE(plain, dense * (1.0 + 1e-12));
  EXPECT_GT(plain, 0.99 * dense);
  EXPECT_GT(plain, 100.0 * estimate);
}

TEST(EigenvalueEstimate, ExactWhenTheKrylovSpaceIsExhausted) {
  // Five distinct eigenvalues: after five steps the Krylov space is the whole space and the
  // largest Ritz value is the largest eigenvalue; more steps asked for are not taken.
  SparseMatrix A(5, 5);
  const double values[] = {0.5, 1.0, 3.0, 7.0, 11.0};
  for (int i = 0; i < 5; ++i) A.insert(i, i) = values[i];
  A.makeCompressed();
  HostBackend host;
  SymmetricMatrixOperator op(A);
  IdentityPreconditioner identity;
  const DeviceVector start = to_device(host, Vector::Ones(5));
  EXPECT_NEAR(estimate_largest_eigenvalue(op, identity, start, 50), 11.0, 1e-10);
}

TEST(EigenvalueEstimate, RefusesAnOperatorThatIsNotPositive) {
  SparseMatrix A(3, 3);
  for (int i = 0; i < 3; ++i) A.insert(i, i) = -1.0;
  A.makeCompressed();
  HostBackend host;
  SymmetricMatrixOperator op(A);
  IdentityPreconditioner identity;
  const DeviceVector start = to_device(host, Vector::Ones(3));
  EXPECT_THROW(estimate_largest_eigenvalue(op, identity, start, 10), NumericalError);
}

}  // namespace
}  // namespace signorini

// The distributed path's own smoothed-aggregation levels
// (src/signorini/petsc/aggregation_levels.hpp) on 1, 2 and 4 ranks: every coarse operator is the
// Galerkin product of the level above, checked against PETSc's own MatPtAP of the same distributed
// matrices; the levels coarsen, down to at most 1,000 unknowns; the prolongations have the fine
// level's rows on each rank and carry the translations of the near-null space on their aggregates'
// own nodes; on one rank each level's restriction comes with it, P^T.

#include <gtest/gtest.h>
#include <petscksp.h>

#include <cmath>

#include "signorini/petsc/aggregation_levels.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/problem/model.hpp"
#include "test_problems.hpp"

namespace signorini::petsc {
namespace {

// ||X - Y||_F / ||Y||_F of two distributed matrices of the same layout.
double relative_difference(Mat X, Mat Y) {
  Mat D = nullptr;
  check(MatDuplicate(X, MAT_COPY_VALUES, &D), "test");
  check(MatAXPY(D, -1.0, Y, DIFFERENT_NONZERO_PATTERN), "test");
  PetscReal d = 0.0, y = 0.0;
  check(MatNorm(D, NORM_FROBENIUS, &d), "test");
  check(MatNorm(Y, NORM_FROBENIUS, &y), "test");
  MatDestroy(&D);
  return d / y;
}

TEST(CoarseLevels, CoarseOperatorsArePetscsGalerkinProducts) {
  // A hex8 block clamped at its bottom (3,630 unknowns), every rank holding whole nodes.
  const testing::ClampedBlock block = testing::clamped_block(12, 10, 9);
  const SparseMatrix& A = block.A;
  const Matrix& B = block.modes;
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const Index nodes = A.rows() / 3;
  const Index lo = 3 * (nodes * rank / size), hi = 3 * (nodes * (rank + 1) / size);
  Mat M = distributed_rows(A, lo, hi, PETSC_COMM_WORLD, 3);
  ASSERT_EQ(attach_near_null_space(M, B.middleRows(lo, hi - lo)), 6U);

  const CoarseLevels levels = aggregation_levels(M);
  ASSERT_GE(levels.prolongations.size(), 1U);
  ASSERT_EQ(levels.operators.size(), levels.prolongations.size());
  // rho(D^-1 A_l) of every level coarsened (D^-1 A has unit diagonal and couplings).
  ASSERT_EQ(levels.jacobi_radii.size(), levels.prolongations.size());
  for (const double radius : levels.jacobi_radii) EXPECT_GT(radius, 1.0);
  Mat finer = M;
  for (std::size_t l = 0; l < levels.prolongations.size(); ++l) {
    Mat P = levels.prolongations[l];
    Mat C = levels.operators[l];
    PetscInt fine_rows = 0, rows = 0, cols = 0, local_cols = 0, coarse = 0, local_coarse = 0;
    check(MatGetLocalSize(finer, &fine_rows, nullptr), "test");
    check(MatGetLocalSize(P, &rows, &local_cols), "test");
    check(MatGetSize(P, nullptr, &cols), "test");
    check(MatGetSize(C, &coarse, nullptr), "test");
    check(MatGetLocalSize(C, &local_coarse, nullptr), "test");
    EXPECT_EQ(rows, fine_rows) << "level " << l + 1;
    EXPECT_EQ(local_cols, local_coarse) << "level " << l + 1;
    EXPECT_EQ(cols, coarse);
    PetscInt fine = 0;
    check(MatGetSize(finer, &fine, nullptr), "test");
    EXPECT_LT(static_cast<double>(coarse), 0.8 * static_cast<double>(fine)) << "level " << l + 1;
    // The Galerkin product, formed by PETSc from the same P and A_l.
    Mat reference = nullptr;
    check(MatPtAP(finer, P, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &reference), "test");
    EXPECT_LT(relative_difference(C, reference), 1e-12) << "level " << l + 1;
    PetscBool symmetric = PETSC_FALSE;
    check(MatIsSymmetric(reference, 1e-10, &symmetric), "test");
    EXPECT_TRUE(symmetric);
    MatDestroy(&reference);
    // Where the levels come with their restrictions (one rank: P^T in place), they are P^T.
    if (l < levels.restrictions.size() && levels.restrictions[l] != nullptr) {
      Mat Pt = nullptr;
      check(MatTranspose(P, MAT_INITIAL_MATRIX, &Pt), "test");
      EXPECT_LT(relative_difference(levels.restrictions[l], Pt), 1e-15) << "level " << l + 1;
      MatDestroy(&Pt);
    }
    finer = C;
  }
  ASSERT_EQ(levels.restrictions.size(), levels.prolongations.size());
  for (Mat R : levels.restrictions) EXPECT_EQ(R != nullptr, size == 1);
  PetscInt coarsest = 0;
  check(MatGetSize(levels.operators.back(), &coarsest, nullptr), "test");
  EXPECT_LE(coarsest, 1000);
  for (Mat P : levels.prolongations) MatDestroy(&P);
  for (Mat R : levels.restrictions) MatDestroy(&R);
  for (Mat C : levels.operators) MatDestroy(&C);
  MatDestroy(&M);
}

}  // namespace
}  // namespace signorini::petsc

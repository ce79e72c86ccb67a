// petsc_algebra.hpp's sequential_matrix: S^T as a PETSc SeqAIJ matrix on S's own arrays, its
// columns sorted where S's were not, with the block size asked for, and S's arrays freed with
// the matrix (run under the sanitizers' leak checks too), which held_matrix finds again; and
// sequential_view, on the caller's arrays without taking them. On PETSC_COMM_SELF on each rank.

#include <gtest/gtest.h>
#include <petscmat.h>

#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"

namespace signorini::petsc {
namespace {

// y = M x for a PETSc matrix on one process and an Eigen vector.
Vector product(Mat M, const Vector& x) {
  Vec vx = nullptr, vy = nullptr;
  check(MatCreateVecs(M, &vx, &vy), "test");
  set_owned(vx, x);
  check(MatMult(M, vx, vy), "test");
  const Vector y = gather(vy);
  VecDestroy(&vx);
  VecDestroy(&vy);
  return y;
}

TEST(SequentialMatrix, IsTheTransposeOnItsOwnArrays) {
  // A 4 x 3 S (not square, not symmetric): the matrix is 3 x 4, S^T.
  SparseMatrix S(4, 3);
  std::vector<Eigen::Triplet<double>> t = {{0, 0, 1.0}, {2, 0, -2.0}, {1, 1, 3.0},
                                           {3, 1, 0.5}, {0, 2, 4.0},  {3, 2, -1.5}};
  S.setFromTriplets(t.begin(), t.end());
  const SparseMatrix copy = S;
  Mat M = sequential_matrix(SparseMatrix(S), PETSC_COMM_SELF);
  PetscInt rows = 0, cols = 0;
  check(MatGetSize(M, &rows, &cols), "test");
  EXPECT_EQ(rows, 3);
  EXPECT_EQ(cols, 4);
  const Vector x = Vector::LinSpaced(4, 1.0, 4.0);
  const Vector expected = copy.transpose() * x;
  EXPECT_LT((product(M, x) - expected).norm(), 1e-15 * expected.norm());
  // The matrix it holds is S, its arrays PETSc's.
  const SparseMatrix* held = held_matrix(M);
  ASSERT_NE(held, nullptr);
  EXPECT_EQ((*held - copy).norm(), 0.0);
  PetscBool done = PETSC_FALSE;
  PetscInt n = 0;
  const PetscInt* ia = nullptr;
  const PetscInt* ja = nullptr;
  check(MatGetRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done), "test");
  if constexpr (std::is_same_v<PetscInt, int>) {
    EXPECT_EQ(ia, held->outerIndexPtr());
    EXPECT_EQ(ja, held->innerIndexPtr());
  }
  check(MatRestoreRowIJ(M, 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done), "test");
  MatDestroy(&M);
}

TEST(SequentialMatrix, OtherMatricesHoldNoneOfOurs) {
  SparseMatrix S(3, 3);
  S.setIdentity();
  Mat M = distributed_rows(S, 0, 3, PETSC_COMM_SELF);
  EXPECT_EQ(held_matrix(M), nullptr);
  MatDestroy(&M);
}

TEST(SequentialMatrix, SortsTheColumnsAndTakesTheBlockSize) {
  // A symmetric 6 x 6 (two node blocks of 3) whose column 0 is stored unsorted.
  SparseMatrix S(6, 6);
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < 6; ++i) t.emplace_back(i, i, 4.0 + i);
  for (int i = 0; i + 3 < 6; ++i) {
    t.emplace_back(i, i + 3, -1.0 - i);
    t.emplace_back(i + 3, i, -1.0 - i);
  }
  S.setFromTriplets(t.begin(), t.end());
  const SparseMatrix reference = S;
  // Column 0 holds rows 0 and 3: swapped in place, values with them.
  int* inner = S.innerIndexPtr();
  double* values = S.valuePtr();
  ASSERT_EQ(S.outerIndexPtr()[1] - S.outerIndexPtr()[0], 2);
  std::swap(inner[0], inner[1]);
  std::swap(values[0], values[1]);
  Mat M = sequential_matrix(std::move(S), PETSC_COMM_SELF, 3);
  PetscInt block = 0;
  check(MatGetBlockSize(M, &block), "test");
  EXPECT_EQ(block, 3);
  PetscInt n = 0;
  const PetscInt* c = nullptr;
  const PetscScalar* v = nullptr;
  check(MatGetRow(M, 0, &n, &c, &v), "test");
  ASSERT_EQ(n, 2);
  EXPECT_EQ(c[0], 0);
  EXPECT_EQ(c[1], 3);
  EXPECT_EQ(v[0], 4.0);
  EXPECT_EQ(v[1], -1.0);
  check(MatRestoreRow(M, 0, &n, &c, &v), "test");
  const Vector x = Vector::LinSpaced(6, -1.0, 2.0);
  const Vector expected = reference * x;
  EXPECT_LT((product(M, x) - expected).norm(), 1e-15 * expected.norm());
  MatDestroy(&M);
}

TEST(SequentialMatrix, RefusesACommunicatorOfSeveralProcesses) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size == 1) GTEST_SKIP() << "one process: PETSC_COMM_WORLD is a one-process communicator";
  EXPECT_THROW((void)sequential_matrix(SparseMatrix(2, 2), PETSC_COMM_WORLD), std::logic_error);
  EXPECT_THROW((void)sequential_view(SparseMatrix(2, 2), PETSC_COMM_WORLD), std::logic_error);
}

// sequential_view: S^T on the caller's arrays, not taken (S intact after the matrix is gone),
// and a sorted copy where S's columns are not sorted or S not compressed.
TEST(SequentialMatrix, AViewReadsTheCallersArraysOrSortsACopy) {
  SparseMatrix S(4, 3);
  const std::vector<Eigen::Triplet<double>> t{{0, 0, 2.0}, {2, 0, -1.0}, {1, 1, 3.0},
                                              {3, 1, 0.5}, {0, 2, 4.0},  {3, 2, -1.5}};
  S.setFromTriplets(t.begin(), t.end());
  const SparseMatrix copy = S;
  const Vector x = Vector::LinSpaced(4, 1.0, 4.0);
  const Vector expected = copy.transpose() * x;
  Mat M = sequential_view(S, PETSC_COMM_SELF, 1);
  EXPECT_LT((product(M, x) - expected).norm(), 1e-15 * expected.norm());
  if constexpr (std::is_same_v<PetscInt, int>) {
    EXPECT_EQ(held_matrix(M), &S);  // (in place)
  }
  MatDestroy(&M);
  EXPECT_EQ((S - copy).norm(), 0.0);  // (not freed, not changed)
  // Column 0's entries out of order: a sorted copy, S left as it is.
  std::swap(S.innerIndexPtr()[0], S.innerIndexPtr()[1]);
  std::swap(S.valuePtr()[0], S.valuePtr()[1]);
  Mat C = sequential_view(S, PETSC_COMM_SELF, 1);
  EXPECT_NE(held_matrix(C), &S);
  EXPECT_LT((product(C, x) - expected).norm(), 1e-15 * expected.norm());
  EXPECT_EQ(S.innerIndexPtr()[0], 2);
  MatDestroy(&C);
}

}  // namespace
}  // namespace signorini::petsc

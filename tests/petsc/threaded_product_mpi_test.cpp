// A PETSc matrix's product on the rank's OpenMP threads (src/signorini/petsc/threaded_product.hpp),
// against PETSc's own MatMult and MatMultAdd, on 1, 2 and 4 ranks with 1 and 3 threads: node
// blocks of 2 and 3 (their own loops) and 4 (the generic one), scalar rows (AIJ), and a matrix
// that is not square (a prolongation, and its transpose).

#include <gtest/gtest.h>
#include <omp.h>
#include <petscksp.h>

#include <cmath>

#include "signorini/core/error.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/threaded_product.hpp"

namespace signorini::petsc {
namespace {

// A symmetric, diagonally dominant matrix of `nodes` node blocks of `bs` unknowns, every entry
// of a block different, the blocks coupling nodes near each other and some far apart (so that on
// several ranks a rank's rows reach its neighbours' columns).
SparseMatrix block_matrix(Index nodes, Index bs) {
  std::vector<Eigen::Triplet<double>> entries;
  for (Index a = 0; a < nodes; ++a)
    for (Index b = 0; b < nodes; ++b) {
      const bool coupled = std::abs(a - b) <= 2 || (a + b) % 7 == 0;
      if (!coupled) continue;
      for (Index r = 0; r < bs; ++r)
        for (Index c = 0; c < bs; ++c) {
          const Index i = a * bs + r, j = b * bs + c;
          const double v = i == j ? 40.0 + static_cast<double>(i % 5)
                                  : 1.0 / (2.0 + static_cast<double>((i * j) % 13 + i + j));
          entries.emplace_back(i, j, v);
        }
    }
  SparseMatrix A(nodes * bs, nodes * bs);
  A.setFromTriplets(entries.begin(), entries.end());
  return A;
}

struct Rows {
  Index lo = 0, hi = 0;
};

// This rank's rows: whole nodes, the ranks' shares as equal as they come.
Rows rank_rows(Index nodes, Index bs) {
  int rank = 0, size = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return {nodes * rank / size * bs, nodes * (rank + 1) / size * bs};
}

// max |y1 - y2| / max |y1| over the ranks.
double relative_difference(Vec y1, Vec y2) {
  Vec d = nullptr;
  check(VecDuplicate(y1, &d), "test");
  check(VecWAXPY(d, -1.0, y1, y2), "test");
  PetscReal diff = 0.0, size = 0.0;
  check(VecNorm(d, NORM_INFINITY, &diff), "test");
  check(VecNorm(y1, NORM_INFINITY, &size), "test");
  VecDestroy(&d);
  return diff / size;
}

// x_i = sin(i + 1), by global index.
void fill(Vec x) {
  PetscInt lo = 0, hi = 0;
  check(VecGetOwnershipRange(x, &lo, &hi), "test");
  for (PetscInt i = lo; i < hi; ++i)
    check(VecSetValue(x, i, std::sin(static_cast<double>(i + 1)), INSERT_VALUES), "test");
  check(VecAssemblyBegin(x), "test");
  check(VecAssemblyEnd(x), "test");
}

class ThreadedProductTest : public ::testing::TestWithParam<std::tuple<int, int>> {
 protected:
  void SetUp() override { threads_ = omp_get_max_threads(); }
  void TearDown() override { omp_set_num_threads(threads_); }
  int threads_ = 1;
};

// y1 = M x by PETSc and y2 by the shell, then z1 = y + M x and z2 likewise (MatMultAdd, into a
// third vector and in place): all to 1e-14.
void expect_same_products(Mat M, const ThreadedProduct& product) {
  Vec x = nullptr, y1 = nullptr, y2 = nullptr, z1 = nullptr, z2 = nullptr;
  check(MatCreateVecs(M, &x, &y1), "test");
  for (Vec* v : {&y2, &z1, &z2}) check(VecDuplicate(y1, v), "test");
  fill(x);
  check(VecSet(y2, 7.0), "test");  // overwritten, not added to
  check(MatMult(M, x, y1), "test");
  check(MatMult(product.shell(), x, y2), "test");
  EXPECT_LT(relative_difference(y1, y2), 1e-14);
  check(MatMultAdd(M, x, y1, z1), "test");
  check(MatMultAdd(product.shell(), x, y1, z2), "test");
  EXPECT_LT(relative_difference(z1, z2), 1e-14);
  check(MatMultAdd(product.shell(), x, y2, y2), "test");
  EXPECT_LT(relative_difference(z1, y2), 1e-14);
  for (Vec* v : {&x, &y1, &y2, &z1, &z2}) VecDestroy(v);
}

TEST_P(ThreadedProductTest, AgreesWithPetscsProduct) {
  const auto [bs, threads] = GetParam();
  omp_set_num_threads(threads);
  const Index nodes = 37;
  const SparseMatrix A = block_matrix(nodes, bs);
  const auto [lo, hi] = rank_rows(nodes, bs);
  Mat M = bs == 1 ? distributed_rows(A, lo, hi, PETSC_COMM_WORLD)
                  : block_rows(A, lo, hi, PETSC_COMM_WORLD, bs);
  EXPECT_EQ(ThreadedProduct::worthwhile(M), threads > 1);
  const ThreadedProduct product(M);
  expect_same_products(M, product);
  // The diagonal is M's.
  Vec d1 = nullptr, d2 = nullptr;
  check(MatCreateVecs(M, nullptr, &d1), "test");
  check(VecDuplicate(d1, &d2), "test");
  check(MatGetDiagonal(M, d1), "test");
  check(MatGetDiagonal(product.shell(), d2), "test");
  EXPECT_EQ(relative_difference(d1, d2), 0.0);
  VecDestroy(&d1);
  VecDestroy(&d2);
  MatDestroy(&M);
}

// A prolongation's shape: 111 rows, 20 columns, a few entries per row; and its transpose (the
// restriction), 20 rows of 111.
TEST(ThreadedProduct, AgreesWithPetscsProductOffTheSquare) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(3);
  Mat P = nullptr;
  check(MatCreateAIJ(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, 111, 20, 4, nullptr, 4, nullptr,
                     &P),
        "test");
  PetscInt lo = 0, hi = 0;
  check(MatGetOwnershipRange(P, &lo, &hi), "test");
  for (PetscInt i = lo; i < hi; ++i)
    for (const PetscInt j : {(3 * i) % 20, (7 * i + 1) % 20, (i + 5) % 20})
      check(MatSetValue(P, i, j, 1.0 + 0.01 * static_cast<double>(i + j), ADD_VALUES), "test");
  check(MatAssemblyBegin(P, MAT_FINAL_ASSEMBLY), "test");
  check(MatAssemblyEnd(P, MAT_FINAL_ASSEMBLY), "test");
  Mat R = nullptr;
  check(MatTranspose(P, MAT_INITIAL_MATRIX, &R), "test");
  {
    const ThreadedProduct prolongation(P), restriction(R);
    expect_same_products(P, prolongation);
    expect_same_products(R, restriction);
  }
  MatDestroy(&P);
  MatDestroy(&R);
  omp_set_num_threads(threads);
}

INSTANTIATE_TEST_SUITE_P(BlockSizesAndThreads, ThreadedProductTest,
                         ::testing::Combine(::testing::Values(1, 2, 3, 4),
                                            ::testing::Values(1, 3)));

// New values in M (its pattern kept) are the shell's at once, and refresh() makes a KSP with
// the shell as its operator set its preconditioner up again: Jacobi alone (preonly) on 2 M gives
// half of what it gave on M, where a preconditioner left as it was would give the same.
TEST(ThreadedProduct, NewValuesReachTheProductAndTheKsp) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(2);
  const Index nodes = 29, bs = 3;
  const SparseMatrix A = block_matrix(nodes, bs);
  const auto [lo, hi] = rank_rows(nodes, bs);
  Mat M = block_rows(A, lo, hi, PETSC_COMM_WORLD, bs);
  ThreadedProduct product(M);
  Vec b = nullptr, x1 = nullptr, x2 = nullptr;
  check(MatCreateVecs(M, &x1, &b), "test");
  check(VecDuplicate(x1, &x2), "test");
  fill(b);
  KSP ksp = nullptr;
  check(KSPCreate(PETSC_COMM_WORLD, &ksp), "test");
  check(KSPSetType(ksp, KSPPREONLY), "test");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "test");
  check(PCSetType(pc, PCJACOBI), "test");
  check(KSPSetOperators(ksp, product.shell(), product.shell()), "test");
  check(KSPSolve(ksp, b, x1), "test");
  check(MatScale(M, 2.0), "test");
  product.refresh();
  check(KSPSetOperators(ksp, product.shell(), product.shell()), "test");
  check(KSPSolve(ksp, b, x2), "test");
  check(VecScale(x2, 2.0), "test");
  EXPECT_LT(relative_difference(x1, x2), 1e-15);
  // And the product itself: (2 M) x = 2 (M x).
  Vec y1 = nullptr, y2 = nullptr;
  check(VecDuplicate(b, &y1), "test");
  check(VecDuplicate(b, &y2), "test");
  check(MatMult(M, b, y1), "test");
  check(MatMult(product.shell(), b, y2), "test");
  EXPECT_LT(relative_difference(y1, y2), 1e-14);
  KSPDestroy(&ksp);
  for (Vec* v : {&b, &x1, &x2, &y1, &y2}) VecDestroy(v);
  MatDestroy(&M);
  omp_set_num_threads(threads);
}

TEST(ThreadedProduct, RefusesAnotherType) {
  Mat M = nullptr;
  check(MatCreateDense(PETSC_COMM_WORLD, PETSC_DECIDE, PETSC_DECIDE, 8, 8, nullptr, &M), "test");
  check(MatAssemblyBegin(M, MAT_FINAL_ASSEMBLY), "test");
  check(MatAssemblyEnd(M, MAT_FINAL_ASSEMBLY), "test");
  EXPECT_FALSE(ThreadedProduct::worthwhile(M));
  EXPECT_THROW(ThreadedProduct{M}, NumericalError);
  MatDestroy(&M);
}

}  // namespace
}  // namespace signorini::petsc

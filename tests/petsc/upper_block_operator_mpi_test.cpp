// petsc/upper_block_operator.hpp: one rank's A and H = A + the contact blocks as PETSc shells on
// A's upper node blocks, against Eigen's products of the same matrices (on PETSC_COMM_SELF on
// each rank): MatMult, MatMultAdd into another vector and into y itself, the diagonals, a KSP's
// Jacobi set up again after new contact blocks; nothing for a matrix not in whole node blocks.

#include <gtest/gtest.h>
#include <petscmat.h>

#include <vector>

#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/upper_block_operator.hpp"
#include "test_problems.hpp"

namespace signorini::petsc {
namespace {

Vec vec_of(const Vector& v) {
  Vec x = nullptr;
  check(VecCreateSeq(PETSC_COMM_SELF, static_cast<PetscInt>(v.size()), &x), "test");
  PetscScalar* a = nullptr;
  check(VecGetArray(x, &a), "test");
  for (Index i = 0; i < v.size(); ++i) a[i] = v(i);
  check(VecRestoreArray(x, &a), "test");
  return x;
}

Vector eigen_of(Vec x) {
  PetscInt n = 0;
  check(VecGetLocalSize(x, &n), "test");
  const PetscScalar* a = nullptr;
  check(VecGetArrayRead(x, &a), "test");
  Vector v(n);
  for (PetscInt i = 0; i < n; ++i) v(i) = a[i];
  check(VecRestoreArrayRead(x, &a), "test");
  return v;
}

TEST(UpperBlockOperator, ShellsGiveTheProductsOfAAndOfTheNewtonMatrix) {
  const testing::ClampedBlock block = testing::clamped_block(6, 5, 4);
  const SparseMatrix& A = block.A;
  const Index n = A.rows();
  const auto op = UpperBlockOperator::make(A, PETSC_COMM_SELF);
  ASSERT_NE(op, nullptr);
  // Two contact blocks: one node's z (1 x 1), another's x and z (2 x 2).
  const std::vector<std::vector<PetscInt>> dofs{{5}, {9, 11}};
  const std::vector<std::vector<double>> values{{40.0}, {3.0, 1.5, 1.5, 2.0}};
  SparseMatrix E(n, n);
  E.insert(5, 5) = 40.0;
  E.insert(9, 9) = 3.0;
  E.insert(9, 11) = 1.5;
  E.insert(11, 9) = 1.5;
  E.insert(11, 11) = 2.0;
  const SparseMatrix H = A + E;
  // A KSP given H before and after new contact blocks: its Jacobi, set up again, takes H's new
  // diagonal.
  KSP ksp = nullptr;
  check(KSPCreate(PETSC_COMM_SELF, &ksp), "test");
  PC pc = nullptr;
  check(KSPGetPC(ksp, &pc), "test");
  check(PCSetType(pc, PCJACOBI), "test");
  check(KSPSetOperators(ksp, op->newton(), op->newton()), "test");
  check(KSPSetUp(ksp), "test");
  op->set_contact_blocks(dofs, values);
  check(KSPSetOperators(ksp, op->newton(), op->newton()), "test");
  check(KSPSetUp(ksp), "test");
  {
    Vec ones = vec_of(Vector::Ones(n)), z = vec_of(Vector::Zero(n));
    check(PCApply(pc, ones, z), "test");
    const Vector inverse = Vector(H.diagonal()).cwiseInverse();
    EXPECT_LT((eigen_of(z) - inverse).norm(), 1e-15 * inverse.norm());
    VecDestroy(&ones);
    VecDestroy(&z);
  }
  KSPDestroy(&ksp);

  const Vector x = Vector::LinSpaced(n, -1.0, 2.0).array().sin();
  const Vector y0 = Vector::LinSpaced(n, 0.5, 1.5);
  for (const bool newton : {false, true}) {
    const SparseMatrix& M = newton ? H : A;
    Mat shell = newton ? op->newton() : op->stiffness();
    Vec vx = vec_of(x), vy = vec_of(y0), vw = vec_of(Vector::Zero(n));
    const Vector expected = M * x;
    check(MatMult(shell, vx, vw), "test");
    EXPECT_LT((eigen_of(vw) - expected).norm(), 1e-13 * expected.norm()) << newton;
    check(MatMultAdd(shell, vx, vy, vw), "test");  // w = y + M x
    EXPECT_LT((eigen_of(vw) - (y0 + expected)).norm(), 1e-13 * expected.norm()) << newton;
    check(MatMultAdd(shell, vx, vy, vy), "test");  // y += M x
    EXPECT_LT((eigen_of(vy) - (y0 + expected)).norm(), 1e-13 * expected.norm()) << newton;
    check(MatGetDiagonal(shell, vw), "test");
    EXPECT_LT((eigen_of(vw) - Vector(M.diagonal())).norm(), 1e-15 * M.diagonal().norm()) << newton;
    for (Vec* v : {&vx, &vy, &vw}) VecDestroy(v);
  }
  // A matrix without whole node blocks (groups of one): no shells, PETSc's blocks instead.
  SparseMatrix D(4, 4);
  D.setIdentity();
  D.coeffRef(0, 1) = D.coeffRef(1, 0) = 0.5;
  D.coeffRef(2, 3) = D.coeffRef(3, 2) = 0.25;
  D.coeffRef(1, 2) = D.coeffRef(2, 1) = 0.1;
  D.makeCompressed();
  EXPECT_EQ(UpperBlockOperator::make(D, PETSC_COMM_SELF), nullptr);
}

}  // namespace
}  // namespace signorini::petsc

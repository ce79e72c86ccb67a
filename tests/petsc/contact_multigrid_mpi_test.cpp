// The multigrid of the Newton matrices on the distributed path's own levels, with each level's
// prolongation smoothed with its Newton matrix at the active contact unknowns
// (src/signorini/petsc/level_contact_prolongation.hpp), on 1, 2 and 4 ranks: on one rank the
// changes P_H - P and the coarse contact rows are the serial multigrid's (the same levels); on
// any number of ranks the V-cycle stays symmetric and CG reaches the answer, and a multigrid that
// has seen other active sets (and none) preconditions as one made for the current set.

#include <gtest/gtest.h>
#include <petscksp.h>

#include <cmath>
#include <optional>
#include <vector>

#include "signorini/backend/host_backend.hpp"
#include "signorini/iterative/multigrid_preconditioner.hpp"
#include "signorini/iterative/penalized_operator.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "signorini/petsc/petsc_algebra.hpp"
#include "signorini/petsc/petsc_check.hpp"
#include "signorini/petsc/petsc_contact_multigrid.hpp"
#include "test_problems.hpp"

namespace signorini::petsc {
namespace {

// A hex8 block clamped at its bottom, pressed at its top by contact rows (normal (0, 0, 1), or
// with `oblique` (0.6, 0, 0.8): two unknowns of each node), every rank holding whole nodes.
class PressedBlock {
 public:
  explicit PressedBlock(bool oblique = false, Index n = 24)
      : block_(testing::clamped_block(n, n, n / 2)) {
    MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
    MPI_Comm_size(PETSC_COMM_WORLD, &size_);
    const Index nodes = block_.A.rows() / 3;
    lo_ = 3 * (nodes * rank_ / size_);
    hi_ = 3 * (nodes * (rank_ + 1) / size_);
    for (const Index node : block_.mesh.boundary_part_nodes("zmax")) {
      const Index x = block_.dofs.free_index(node, 0), z = block_.dofs.free_index(node, 2);
      const Index j = static_cast<Index>(place_.size());
      place_.push_back(block_.mesh.node(node)(0));
      if (z < lo_ || z >= hi_) continue;
      if (oblique)
        rows_.push_back(
            ContactRow{j, {static_cast<PetscInt>(x), static_cast<PetscInt>(z)}, {0.6, 0.8}});
      else
        rows_.push_back(ContactRow{j, {static_cast<PetscInt>(z)}, {1.0}});
    }
  }
  ~PressedBlock() {
    for (Mat* M : {&A_, &H_}) MatDestroy(M);
  }
  PressedBlock(const PressedBlock&) = delete;
  PressedBlock& operator=(const PressedBlock&) = delete;

  // c_j = `factor` max diag(A) (r h) where the node's x lies in [from, to].
  [[nodiscard]] Vector weights(double from, double to, double factor = 100.0) const {
    const double w = factor * block_.A.diagonal().maxCoeff();
    Vector c = Vector::Zero(static_cast<Index>(place_.size()));
    for (std::size_t j = 0; j < place_.size(); ++j)
      if (place_[j] >= from && place_[j] <= to) c(static_cast<Index>(j)) = w;
    return c;
  }
  // A (AIJ in node blocks, the rigid-body modes attached; on one rank held in place, as the
  // one-rank path's, so that its levels are the serial hierarchy) and H = A + N^T diag(c) N.
  Mat setup() {
    if (A_ == nullptr) {
      A_ = size_ == 1 ? sequential_matrix(SparseMatrix(block_.A), PETSC_COMM_WORLD, 3)
                      : distributed_rows(block_.A, lo_, hi_, PETSC_COMM_WORLD, 3);
      EXPECT_EQ(attach_near_null_space(A_, block_.modes.middleRows(lo_, hi_ - lo_)), 6U);
    }
    return A_;
  }
  // (One matrix changed in place, as the Newton space's: PCMG gives its fine smoother the KSP's
  // operator again only if it is the same object.)
  Mat newton(const Vector& c) {
    if (H_ == nullptr) check(MatDuplicate(setup(), MAT_COPY_VALUES, &H_), "test");
    check(MatCopy(setup(), H_, SAME_NONZERO_PATTERN), "test");
    for (const ContactRow& row : rows_) {
      const auto k = static_cast<PetscInt>(row.dofs.size());
      double block[4];
      for (PetscInt p = 0; p < k; ++p)
        for (PetscInt q = 0; q < k; ++q)
          block[k * p + q] = c(row.j) * row.normal[static_cast<std::size_t>(p)] *
                             row.normal[static_cast<std::size_t>(q)];
      check(MatSetValues(H_, k, row.dofs.data(), k, row.dofs.data(), block, ADD_VALUES), "test");
    }
    check(MatAssemblyBegin(H_, MAT_FINAL_ASSEMBLY), "test");
    check(MatAssemblyEnd(H_, MAT_FINAL_ASSEMBLY), "test");
    return H_;
  }
  [[nodiscard]] const std::vector<ContactRow>& rows() const { return rows_; }
  [[nodiscard]] const testing::ClampedBlock& block() const { return block_; }
  // The whole N (every rank's rows; one rank's test).
  [[nodiscard]] SparseMatrix contact_matrix() const {
    std::vector<Eigen::Triplet<double, int>> t;
    for (const ContactRow& row : rows_)
      for (std::size_t q = 0; q < row.dofs.size(); ++q)
        t.emplace_back(static_cast<int>(row.j), static_cast<int>(row.dofs[q]), row.normal[q]);
    SparseMatrix N(static_cast<Index>(place_.size()), block_.A.cols());
    N.setFromTriplets(t.begin(), t.end());
    return N;
  }

 private:
  testing::ClampedBlock block_;
  int rank_ = 0, size_ = 1;
  Index lo_ = 0, hi_ = 0;
  std::vector<double> place_;  // per contact node, its x
  std::vector<ContactRow> rows_;
  Mat A_ = nullptr, H_ = nullptr;
};

// A sequential PETSc matrix as an Eigen one (of `rows` x `cols`; a null one is zero).
SparseMatrix eigen_of(Mat M, Index rows, Index cols) {
  SparseMatrix out(rows, cols);
  if (M == nullptr) return out;
  std::vector<Eigen::Triplet<double, int>> t;
  for (PetscInt r = 0; r < rows; ++r) {
    PetscInt n = 0;
    const PetscInt* c = nullptr;
    const PetscScalar* v = nullptr;
    check(MatGetRow(M, r, &n, &c, &v), "test");
    for (PetscInt k = 0; k < n; ++k)
      t.emplace_back(static_cast<int>(r), static_cast<int>(c[k]), v[k]);
    check(MatRestoreRow(M, r, &n, &c, &v), "test");
  }
  out.setFromTriplets(t.begin(), t.end());
  return out;
}

double max_abs(const SparseMatrix& M) {
  double m = 0.0;
  for (Index k = 0; k < M.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(M, k); it; ++it) m = std::max(m, std::abs(it.value()));
  return m;
}

// CG with the multigrid on H x = b (b from a fixed x, the same on any number of ranks), to 1e-10.
struct Solve {
  PetscInt iterations = 0;
  double error = 0.0;  // ||x - x_true|| / ||x_true||
};

class Cg {
 public:
  Cg(PressedBlock& problem, bool contact_prolongation) {
    check(KSPCreate(PETSC_COMM_WORLD, &ksp_), "test");
    check(KSPSetType(ksp_, KSPCG), "test");
    check(KSPSetNormType(ksp_, KSP_NORM_UNPRECONDITIONED), "test");
    check(KSPSetTolerances(ksp_, 1e-10, 0.0, PETSC_DEFAULT, 500), "test");
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "test");
    multigrid_.emplace(pc, problem.setup(), problem.rows(), PETSC_COMM_WORLD,
                       ContactMultigrid::Levels::Aggregation, contact_prolongation);
  }
  ~Cg() {  // (the KSP, the shells' user, first: as the Newton space does)
    KSPDestroy(&ksp_);
    multigrid_.reset();
  }
  Cg(const Cg&) = delete;
  Cg& operator=(const Cg&) = delete;

  ContactMultigrid& multigrid() { return *multigrid_; }

  Solve solve(PressedBlock& problem, const Vector& c) {
    multigrid_->set_weights(c);
    Mat H = problem.newton(c);
    check(KSPSetOperators(ksp_, H, H), "test");
    Vec x = nullptr, b = nullptr, truth = nullptr;
    check(MatCreateVecs(H, &x, &b), "test");
    check(VecDuplicate(x, &truth), "test");
    PetscInt lo = 0, hi = 0;
    check(VecGetOwnershipRange(truth, &lo, &hi), "test");
    for (PetscInt i = lo; i < hi; ++i)
      check(
          VecSetValue(truth, i, 1.0 + 0.1 * std::sin(0.37 * static_cast<double>(i)), INSERT_VALUES),
          "test");
    check(VecAssemblyBegin(truth), "test");
    check(VecAssemblyEnd(truth), "test");
    check(MatMult(H, truth, b), "test");
    check(VecSet(x, 0.0), "test");
    check(KSPSolve(ksp_, b, x), "test");
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    check(KSPGetConvergedReason(ksp_, &reason), "test");
    EXPECT_GT(reason, 0) << "CG did not converge";
    Solve out;
    check(KSPGetIterationNumber(ksp_, &out.iterations), "test");
    PetscReal t = 0.0, e = 0.0;
    check(VecNorm(truth, NORM_2, &t), "test");
    check(VecAXPY(x, -1.0, truth), "test");
    check(VecNorm(x, NORM_2, &e), "test");
    out.error = e / t;
    for (Vec* v : {&x, &b, &truth}) VecDestroy(v);
    return out;
  }

  // |v.Mu - u.Mv| / |v.Mu| for the preconditioner M as set up by the last solve, two fixed u, v.
  double asymmetry() {
    PC pc = nullptr;
    check(KSPGetPC(ksp_, &pc), "test");
    Mat H = nullptr;
    check(KSPGetOperators(ksp_, &H, nullptr), "test");
    Vec u = nullptr, v = nullptr, Mu = nullptr, Mv = nullptr;
    check(MatCreateVecs(H, &u, &v), "test");
    check(VecDuplicate(u, &Mu), "test");
    check(VecDuplicate(u, &Mv), "test");
    PetscInt lo = 0, hi = 0;
    check(VecGetOwnershipRange(u, &lo, &hi), "test");
    for (PetscInt i = lo; i < hi; ++i) {
      const auto s = static_cast<double>(i);
      check(VecSetValue(u, i, std::cos(1.3 * s) + 0.1, INSERT_VALUES), "test");
      check(VecSetValue(v, i, std::sin(0.7 * s * s), INSERT_VALUES), "test");
    }
    for (Vec w : {u, v}) {
      check(VecAssemblyBegin(w), "test");
      check(VecAssemblyEnd(w), "test");
    }
    check(PCApply(pc, u, Mu), "test");
    check(PCApply(pc, v, Mv), "test");
    PetscScalar vMu = 0.0, uMv = 0.0;
    check(VecDot(v, Mu, &vMu), "test");
    check(VecDot(u, Mv, &uMv), "test");
    for (Vec* w : {&u, &v, &Mu, &Mv}) VecDestroy(w);
    return std::abs(vMu - uMv) / std::abs(vMu);
  }

 private:
  KSP ksp_ = nullptr;
  std::optional<ContactMultigrid> multigrid_;
};

TEST(ContactMultigrid, OnOneRankTheChangesAndContactRowsAreTheSerialMultigrids) {
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  if (size > 1) GTEST_SKIP() << "one rank's levels are the serial hierarchy";
  PressedBlock problem(true, 16);  // (oblique: two unknowns per row)
  const Vector c = problem.weights(0.0, 0.6, 10.0);
  Cg petsc(problem, true);
  petsc.solve(problem, c);
  // The serial multigrid on the same A, N and c (its hierarchy: the same aggregates, omegas and
  // prolongations).
  const testing::ClampedBlock& block = problem.block();
  const Index n = block.A.rows();
  std::vector<Index> node_of(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) node_of[static_cast<std::size_t>(i)] = i / 3;
  // (The modes as the PETSc path has them: made orthonormal when attached.)
  MatNullSpace space = nullptr;
  check(MatGetNearNullSpace(problem.setup(), &space), "test");
  PetscBool constant = PETSC_FALSE;
  PetscInt count = 0;
  const Vec* vectors = nullptr;
  check(MatNullSpaceGetVecs(space, &constant, &count, &vectors), "test");
  Matrix modes(n, count);
  for (PetscInt k = 0; k < count; ++k) {
    const PetscScalar* v = nullptr;
    check(VecGetArrayRead(vectors[k], &v), "test");
    for (Index i = 0; i < n; ++i) modes(i, k) = v[i];
    check(VecRestoreArrayRead(vectors[k], &v), "test");
  }
  MultigridHierarchy h = smoothed_aggregation_hierarchy(block.A, modes, node_of, {});
  const SparseMatrix N = problem.contact_matrix();
  HostBackend be;
  PenalizedOperator H(be, block.A, N);
  MultigridOptions o;
  o.lambda_max = h.jacobi_radii;
  o.tentatives = &h.tentatives;
  o.omegas = h.omegas;
  MultigridPreconditioner serial(H, block.A, N, h.prolongations, o, h.coarse_operators);
  H.set_weights(c);
  serial.refresh();
  ASSERT_EQ(petsc.multigrid().level_sizes().size(), h.prolongations.size() + 1);
  ASSERT_EQ(petsc.multigrid().contact_prolongation_levels(), h.prolongations.size());
  for (std::size_t l = 0; l < h.prolongations.size(); ++l) {
    const SparseMatrix& expected = serial.prolongation_change(l);
    const SparseMatrix change = eigen_of(petsc.multigrid().prolongation_change(l),
                                         h.prolongations[l].rows(), h.prolongations[l].cols());
    ASSERT_GT(max_abs(expected), 0.0) << l;
    EXPECT_LT(max_abs(SparseMatrix(change - expected)), 1e-12 * max_abs(expected)) << l;
    const SparseMatrix rows_expected = serial.contact_rows(l + 1);
    const SparseMatrix rows =
        eigen_of(petsc.multigrid().contact_rows(l + 1), N.rows(), h.prolongations[l].cols());
    // (The serial rows are the active ones; the others' weights are 0 in either.)
    Vector active = Vector::Zero(N.rows());
    for (Index j = 0; j < N.rows(); ++j) active(j) = c(j) > 0.0 ? 1.0 : 0.0;
    EXPECT_LT(max_abs(SparseMatrix(active.asDiagonal() * rows - rows_expected)),
              1e-12 * max_abs(rows_expected))
        << l + 1;
  }
}

// On any number of ranks: the transfers P + dP and (P + dP)^T keep the V-cycle symmetric, as CG
// needs, and CG reaches the answer with them as without. (On a block this small the iterations
// are about the same either way; the gain is at scale: on Hertz's ball at a million unknowns,
// one rank, 66 CG iterations without and 40 with, docs/distributed.md.)
TEST(ContactMultigrid, ProlongationsSmoothedWithTheNewtonMatrixKeepTheVCycleSymmetric) {
  PressedBlock problem;
  const Vector c = problem.weights(0.0, 0.3);
  Cg plain(problem, false);
  const Solve without = plain.solve(problem, c);
  EXPECT_EQ(plain.multigrid().contact_prolongation_levels(), 0U);
  Cg smoothed(problem, true);
  const Solve with = smoothed.solve(problem, c);
  // At least the finest prolongation (every contact row lies on one rank's unknowns); on one
  // rank every level's.
  int size = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &size);
  const std::size_t levels = smoothed.multigrid().level_sizes().size() - 1;
  EXPECT_GE(smoothed.multigrid().contact_prolongation_levels(), 1U);
  if (size == 1) {
    EXPECT_EQ(smoothed.multigrid().contact_prolongation_levels(), levels);
  }
  EXPECT_NE(smoothed.multigrid().prolongation_change(0), nullptr);
  EXPECT_LT(without.error, 1e-6);
  EXPECT_LT(with.error, 1e-6);
  EXPECT_LE(with.iterations, without.iterations + 3)
      << with.iterations << " CG iterations against " << without.iterations;
  EXPECT_LT(smoothed.asymmetry(), 1e-10);
  EXPECT_LT(plain.asymmetry(), 1e-10);
}

TEST(ContactMultigrid, ContactProlongationFollowsTheActiveSet) {
  // One multigrid through other active sets and none, then back: the CG iterations and answer
  // of a multigrid made for the last set (rows no longer active written back to A's).
  PressedBlock problem(true, 14);
  const Vector first = problem.weights(0.0, 0.6, 10.0), second = problem.weights(0.3, 1.0, 10.0);
  Cg reused(problem, true);
  const Solve a = reused.solve(problem, first);
  reused.solve(problem, second);
  reused.solve(problem, Vector::Zero(first.size()));
  const Solve b = reused.solve(problem, second);
  const Solve again = reused.solve(problem, first);
  Cg fresh_second(problem, true);
  const Solve b_fresh = fresh_second.solve(problem, second);
  EXPECT_EQ(b.iterations, b_fresh.iterations);
  EXPECT_NEAR(b.error, b_fresh.error, 1e-6 * b_fresh.error + 1e-14);
  EXPECT_EQ(again.iterations, a.iterations);
  EXPECT_NEAR(again.error, a.error, 1e-6 * a.error + 1e-14);
}

}  // namespace
}  // namespace signorini::petsc

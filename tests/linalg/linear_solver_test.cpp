#include "signorini/linalg/linear_solver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/linalg/cholmod_solver.hpp"

namespace signorini {
namespace {

double relative_difference(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

// 1D Laplacian plus a diagonal shift: SPD, tridiagonal.
SparseMatrix laplacian(Index n, double shift) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(static_cast<int>(i), static_cast<int>(i), 2.0 + shift);
    if (i + 1 < n) {
      t.emplace_back(static_cast<int>(i), static_cast<int>(i + 1), -1.0);
      t.emplace_back(static_cast<int>(i + 1), static_cast<int>(i), -1.0);
    }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

class LinearSolverTest : public ::testing::TestWithParam<LinearSolverType> {};

TEST_P(LinearSolverTest, SolvesAndReusesTheAnalysis) {
  LinearSolverOptions o;
  o.type = GetParam();
  auto solver = make_linear_solver(o);
  const Index n = 200;
  SparseMatrix A = laplacian(n, 0.01);
  solver->analyze(A);
  const Vector x_true = Vector::LinSpaced(n, -1.0, 3.0);
  for (const double shift : {0.01, 1.0}) {  // same pattern, new values
    A = laplacian(n, shift);
    solver->factorize(A);
    Vector x = Vector::Zero(n);
    const LinearSolveStats st = solver->solve(A * x_true, x);
    EXPECT_TRUE(st.converged);
    EXPECT_LT((x - x_true).norm() / x_true.norm(), 1e-10);
    if (GetParam() == LinearSolverType::ConjugateGradient) {
      EXPECT_GT(st.iterations, 0);
    }
  }
  EXPECT_GT(solver->timings().seconds("linear factorization"), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Types, LinearSolverTest,
                         ::testing::Values(LinearSolverType::Cholmod,
                                           LinearSolverType::ConjugateGradient,
                                           LinearSolverType::Dense),
                         [](const auto& param_info) {
                           return std::string(
                               enum_to_string(kLinearSolverTypeNames, param_info.param));
                         });

TEST(CholmodSolver, IndefiniteMatrixIsANumericalError) {
  CholmodSolver s;
  const SparseMatrix A = laplacian(10, -3.0);
  s.analyze(A);
  EXPECT_THROW(s.factorize(A), NumericalError);
}

TEST(CholmodSolver, PatternChangeIsDetected) {
  CholmodSolver s;
  s.analyze(laplacian(10, 0.0));
  EXPECT_THROW(s.factorize(laplacian(11, 0.0)), NumericalError);
}

// Same size and the same number of entries, but one coupling moved: its values would land in the
// wrong places of CHOLMOD's copy, so factorize() refuses it.
TEST(CholmodSolver, SameCountOtherPatternIsDetected) {
  const Index n = 6;
  auto matrix = [n](int far) {
    std::vector<Eigen::Triplet<double, int>> t;
    for (int i = 0; i < n; ++i) t.emplace_back(i, i, 4.0);
    t.emplace_back(0, far, -1.0);
    t.emplace_back(far, 0, -1.0);
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    A.makeCompressed();
    return A;
  };
  const SparseMatrix A = matrix(2), B = matrix(4);
  ASSERT_EQ(A.nonZeros(), B.nonZeros());
  CholmodSolver s;
  s.analyze(A);
  EXPECT_NO_THROW(s.factorize(A));
  EXPECT_THROW(s.factorize(B), NumericalError);
}

TEST(CholmodSolver, ReportsVersionAndFactorSize) {
  CholmodSolver s;
  const SparseMatrix A = laplacian(50, 0.1);
  s.analyze(A);
  s.factorize(A);
  EXPECT_GE(s.factor_nonzeros(), 50.0);
  EXPECT_FALSE(cholmod_version().empty());
}

// A 7-point Laplacian on an m x m x m grid plus a shift: large enough in flops per entry that
// CHOLMOD factorises it supernodally, so that an update has to convert the factor.
SparseMatrix grid_laplacian(int m, double shift) {
  std::vector<Eigen::Triplet<double, int>> t;
  auto id = [m](int i, int j, int k) { return (k * m + j) * m + i; };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) {
        t.emplace_back(id(i, j, k), id(i, j, k), 6.0 + shift);
        if (i + 1 < m) t.emplace_back(id(i, j, k), id(i + 1, j, k), -1.0);
        if (j + 1 < m) t.emplace_back(id(i, j, k), id(i, j + 1, k), -1.0);
        if (k + 1 < m) t.emplace_back(id(i, j, k), id(i, j, k + 1), -1.0);
        if (i > 0) t.emplace_back(id(i, j, k), id(i - 1, j, k), -1.0);
        if (j > 0) t.emplace_back(id(i, j, k), id(i, j - 1, k), -1.0);
        if (k > 0) t.emplace_back(id(i, j, k), id(i, j, k - 1), -1.0);
      }
  SparseMatrix A(m * m * m, m * m * m);
  A.setFromTriplets(t.begin(), t.end());
  A.makeCompressed();
  return A;
}

// Columns with two entries on coupled rows (i, i + 1), as a contact node's normal touches the
// dofs of one node: C C^T stays inside A's pattern.
SparseMatrix update_columns(Index n, const std::vector<Index>& first_rows, double value) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (std::size_t c = 0; c < first_rows.size(); ++c) {
    t.emplace_back(static_cast<int>(first_rows[c]), static_cast<int>(c), value);
    t.emplace_back(static_cast<int>(first_rows[c] + 1), static_cast<int>(c), -0.5 * value);
  }
  SparseMatrix C(n, static_cast<Index>(first_rows.size()));
  C.setFromTriplets(t.begin(), t.end());
  return C;
}

Vector solve_with(CholmodSolver& s, const Vector& b) {
  Vector x;
  s.solve(b, x);
  return x;
}

// An update and a downdate give the factors of A + C C^T and of A again: the solves agree with
// fresh factorisations to rounding, and a later factorize() runs from the analysis as before.
TEST(CholmodSolver, UpdateAndDowndateMatchAFreshFactorisation) {
  const SparseMatrix A = grid_laplacian(14, 0.05);
  const Index n = A.rows();
  const SparseMatrix C = update_columns(n, {3, 700, 1500, 2700}, 2.0);
  const SparseMatrix AC = SparseMatrix(A + C * SparseMatrix(C.transpose())).pruned();
  const Vector b = Vector::LinSpaced(n, -1.0, 2.0);

  CholmodSolver fresh;
  fresh.factorize(AC);
  const Vector x_updated = solve_with(fresh, b);
  fresh.factorize(A);
  const Vector x_plain = solve_with(fresh, b);
  ASSERT_GT((x_updated - x_plain).norm(), 1e-3 * x_plain.norm());  // the update matters

  CholmodSolver s;
  s.analyze(A);
  s.factorize(A);
  EXPECT_GT(s.last_factorization_seconds(), 0.0);
  EXPECT_GT(s.predicted_conversion_seconds(), 0.0);  // still supernodal: the first update converts
  ASSERT_TRUE(s.update(C, true));
  EXPECT_EQ(s.predicted_conversion_seconds(), 0.0);  // converted now
  EXPECT_LT(relative_difference(solve_with(s, b), x_updated), 1e-12);
  ASSERT_TRUE(s.update(C, false));
  EXPECT_LT(relative_difference(solve_with(s, b), x_plain), 1e-12);
  s.factorize(AC);  // back to the supernodal factorisation
  EXPECT_GT(s.predicted_conversion_seconds(), 0.0);
  EXPECT_LT(relative_difference(solve_with(s, b), x_updated), 1e-12);
  EXPECT_GT(s.timings().seconds("linear factor update"), 0.0);
}

// A with the rows and columns of `fixed` replaced by the identity's.
SparseMatrix with_identity_rows(const SparseMatrix& A, const std::vector<Index>& fixed) {
  std::vector<bool> is_fixed(static_cast<std::size_t>(A.rows()), false);
  for (const Index i : fixed) is_fixed[static_cast<std::size_t>(i)] = true;
  SparseMatrix K = A;
  for (Index col = 0; col < K.cols(); ++col)
    for (SparseMatrix::InnerIterator it(K, col); it; ++it)
      if (is_fixed[static_cast<std::size_t>(it.row())] || is_fixed[static_cast<std::size_t>(col)])
        it.valueRef() = it.row() == col ? 1.0 : 0.0;
  return K;
}

// Column k of A without the rows in `fixed` (the diagonal kept).
std::vector<std::pair<Index, double>> column_without(const SparseMatrix& A, Index k,
                                                     const std::vector<Index>& fixed) {
  std::vector<std::pair<Index, double>> column;
  for (SparseMatrix::InnerIterator it(A, k); it; ++it)
    if (it.row() == k || std::find(fixed.begin(), fixed.end(), it.row()) == fixed.end())
      column.emplace_back(it.row(), it.value());
  return column;
}

// Row deletions and additions give the factors of A with some rows and columns made the
// identity's and of A again: the solves agree with fresh factorisations of those matrices.
TEST(CholmodSolver, RowDeletionsAndAdditionsMatchAFreshFactorisation) {
  const SparseMatrix A = grid_laplacian(14, 0.05);
  const Index n = A.rows();
  const Vector b = Vector::LinSpaced(n, -1.0, 2.0);
  const std::vector<Index> rows = {5, 700, 701, 2000};  // 700 and 701 are coupled
  const auto fresh_solve = [&](const SparseMatrix& K) {
    CholmodSolver fresh;
    fresh.factorize(K);
    return solve_with(fresh, b);
  };

  CholmodSolver s;
  EXPECT_THROW((void)s.delete_row(0), NumericalError);
  s.factorize(A);
  const Vector x_plain = solve_with(s, b);
  for (const Index k : rows) ASSERT_TRUE(s.delete_row(k));
  EXPECT_EQ(s.predicted_conversion_seconds(), 0.0);  // converted to L D L^T
  const Vector x_fixed = solve_with(s, b);
  EXPECT_LT(relative_difference(x_fixed, fresh_solve(with_identity_rows(A, rows))), 1e-12);
  for (const Index k : rows) EXPECT_EQ(x_fixed(k), b(k));        // the identity's rows: x_k = b_k
  ASSERT_GT((x_fixed - x_plain).norm(), 1e-3 * x_plain.norm());  // the deletions matter

  // Row 700 back, 701 still fixed: its entry must stay out of the new column.
  ASSERT_TRUE(s.add_row(700, column_without(A, 700, {5, 701, 2000})));
  EXPECT_LT(
      relative_difference(solve_with(s, b), fresh_solve(with_identity_rows(A, {5, 701, 2000}))),
      1e-12);
  for (const Index k : {Index{5}, Index{701}, Index{2000}}) {
    std::vector<Index> still;
    for (const Index r : {Index{5}, Index{701}, Index{2000}})
      if (r > k) still.push_back(r);
    ASSERT_TRUE(s.add_row(k, column_without(A, k, still)));
  }
  EXPECT_LT(relative_difference(solve_with(s, b), x_plain), 1e-12);
  EXPECT_GT(s.row_modification_flops(700), 0.0);
  EXPECT_GT(s.timings().seconds("linear factor update"), 0.0);
}

// The cost estimate walks the elimination tree: positive, at most 4 flops per entry of L, and the
// same for any of a column's rows that lie on one path.
TEST(CholmodSolver, UpdateFlopsFollowTheEliminationTree) {
  const SparseMatrix A = grid_laplacian(10, 0.05);
  CholmodSolver s;
  EXPECT_THROW((void)s.update_flops({0}), NumericalError);
  s.factorize(A);
  EXPECT_EQ(s.update_flops({}), 0.0);
  double largest = 0.0;
  for (Index r = 0; r < A.rows(); r += 97) {
    const double f = s.update_flops({r});
    EXPECT_GT(f, 0.0);
    EXPECT_LE(f, 4.0 * s.factor_nonzeros());
    largest = std::max(largest, f);
  }
  EXPECT_LT(largest, 4.0 * s.factor_nonzeros());  // a path, not the whole factor
}

// A downdate that leaves an indefinite matrix reports it; the next factorize() still works.
TEST(CholmodSolver, DowndateBelowDefinitenessReturnsFalse) {
  const SparseMatrix A = grid_laplacian(8, 0.05);
  CholmodSolver s;
  s.factorize(A);
  EXPECT_FALSE(s.update(update_columns(A.rows(), {10}, 10.0), false));
  s.factorize(A);
  const Vector b = Vector::Ones(A.rows());
  EXPECT_LT((A * solve_with(s, b) - b).norm(), 1e-12 * b.norm());
}

}  // namespace
}  // namespace signorini

#include "signorini/linalg/linear_solver.hpp"

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "signorini/linalg/cholmod_solver.hpp"

namespace signorini {
namespace {

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

}  // namespace
}  // namespace signorini

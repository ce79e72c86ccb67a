// The condensation onto a set C of unknowns (linalg/schur_complement.hpp): S, the condensed load
// and the solves against the dense formulas, and the two-part factorisation (two interiors and a
// separator, factorised on two threads) against the one-part one on the paper's stiffness.

#include "signorini/linalg/schur_complement.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <algorithm>

#include "signorini/core/error.hpp"
#include "signorini/linalg/dense_storage.hpp"
#include "signorini/linalg/vertex_separator.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

/// A 2D Laplacian-like stencil on a 6-wide strip plus a diagonal shift: SPD.
SparseMatrix strip_matrix(Index n) {
  std::vector<Eigen::Triplet<double, int>> t;
  for (Index i = 0; i < n; ++i) {
    t.emplace_back(static_cast<int>(i), static_cast<int>(i), 4.5);
    for (const Index d : {Index{1}, Index{6}})
      if (i + d < n) {
        t.emplace_back(static_cast<int>(i), static_cast<int>(i + d), -1.0);
        t.emplace_back(static_cast<int>(i + d), static_cast<int>(i), -1.0);
      }
  }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  return A;
}

class SchurComplementParts : public ::testing::TestWithParam<Index> {};

TEST_P(SchurComplementParts, MatchesTheDenseFormulas) {
  const Index n = 60;
  const SparseMatrix A = strip_matrix(n);
  const std::vector<Index> last{3, 17, 29, 8, 44, 59};
  SchurComplement sc(A, last, GetParam());
  EXPECT_EQ(sc.parts(), GetParam());
  std::vector<Index> interior;
  for (Index i = 0; i < n; ++i)
    if (std::find(last.begin(), last.end(), i) == last.end()) interior.push_back(i);
  const Eigen::MatrixXd D(A);
  const Eigen::MatrixXd Aii = D(interior, interior), Aic = D(interior, last), Acc = D(last, last);
  const Eigen::MatrixXd S = Acc - Aic.transpose() * Aii.llt().solve(Aic);
  ASSERT_TRUE(dense_view(sc.matrix()).has_value());  // S is kept once, every entry stored
  EXPECT_LT((*dense_view(sc.matrix()) - S).norm(), 1e-12 * S.norm());
  const Eigen::MatrixXd S_kept = *dense_view(sc.matrix());
  EXPECT_TRUE(S_kept == S_kept.transpose());  // exactly symmetric
  const Vector b = Vector::LinSpaced(n, -2.0, 5.0);
  const Vector g = b(last) - Aic.transpose() * Aii.llt().solve(Vector(b(interior)));
  EXPECT_LT((sc.condensed_load(b) - g).norm(), 1e-12 * g.norm());
  EXPECT_LT((A * sc.solve(b) - b).norm(), 1e-12 * b.norm());
  // x = A^-1 (b + E_C f) by a back substitution after condensed_load(b).
  const Vector f = Vector::LinSpaced(static_cast<Index>(last.size()), 1.0, -3.0);
  Vector rhs = b;
  for (std::size_t k = 0; k < last.size(); ++k) rhs(last[k]) += f(static_cast<Index>(k));
  EXPECT_LT((A * sc.solve_with_condensed_forces(f) - rhs).norm(), 1e-12 * rhs.norm());
}

INSTANTIATE_TEST_SUITE_P(OneAndTwo, SchurComplementParts, ::testing::Values(Index{1}, Index{2}));

TEST(SchurComplement, ASplitThatDoesNotPayFallsBackToOnePart) {
  // A 5-point Laplacian on a 20 x 20 grid condensed onto its whole boundary: the separator and
  // the boundary make a dense interface whose factorisation would cost more than a quarter of
  // the two parts' sparse ones, so one factorisation runs, with the same S.
  const Index m = 20, n = m * m;
  std::vector<Eigen::Triplet<double, int>> t;
  std::vector<Index> last;
  for (Index i = 0; i < m; ++i)
    for (Index j = 0; j < m; ++j) {
      const auto v = static_cast<int>(i * m + j);
      t.emplace_back(v, v, 4.0 + 1e-3);
      if (i + 1 < m) {
        t.emplace_back(v, v + static_cast<int>(m), -1.0);
        t.emplace_back(v + static_cast<int>(m), v, -1.0);
      }
      if (j + 1 < m) {
        t.emplace_back(v, v + 1, -1.0);
        t.emplace_back(v + 1, v, -1.0);
      }
      if (i == 0 || j == 0 || i == m - 1 || j == m - 1) last.push_back(v);
    }
  SparseMatrix A(n, n);
  A.setFromTriplets(t.begin(), t.end());
  SchurComplement two(A, last, 2);
  SchurComplement one(A, last, 1);
  EXPECT_EQ(two.parts(), 1);
  EXPECT_TRUE(Eigen::MatrixXd(*dense_view(two.matrix())) ==
              Eigen::MatrixXd(*dense_view(one.matrix())));
}

TEST(SchurComplement, SolveBeforeCondensedLoadIsRefused) {
  for (const Index parts : {Index{1}, Index{2}}) {
    SchurComplement sc(strip_matrix(60), {5, 40}, parts);
    EXPECT_THROW(static_cast<void>(sc.solve_with_condensed_forces(Vector::Zero(2))),
                 NumericalError);
  }
}

TEST(SchurComplement, AutomaticPartsFollowSizeAndThreads) {
  const Index big = SchurComplement::kTwoPartUnknowns;
  EXPECT_EQ(SchurComplement::automatic_parts(big - 1, 2), 1);
  EXPECT_EQ(SchurComplement::automatic_parts(big, 2), 2);
  EXPECT_EQ(SchurComplement::automatic_parts(big, 1), 1);
}

/// The normal unknowns of the paper's contact nodes (the normals are -e_y: one unknown each; N
/// stores the zero x-entries too).
std::vector<Index> contact_unknowns(const ContactProblem& p) {
  std::vector<Index> last;
  const SparseMatrix Nt = p.contact.N.transpose();
  for (Index j = 0; j < p.contact.size(); ++j)
    if (p.contact.movable[static_cast<std::size_t>(j)])
      for (SparseMatrix::InnerIterator it(Nt, j); it; ++it)
        if (it.value() != 0.0) last.push_back(it.row());
  return last;
}

TEST(SchurComplement, TwoPartsAgreeWithOneOnThePaperStiffness) {
  const ContactProblem& p = testing::paper_model(120).problem;
  const std::vector<Index> last = contact_unknowns(p);
  ASSERT_EQ(static_cast<Index>(last.size()), 120);  // one contact node is clamped
  SchurComplement one(p.A, last, 1);
  SchurComplement two(p.A, last, 2);
  ASSERT_EQ(two.parts(), 2);
  const Eigen::MatrixXd S1 = *dense_view(one.matrix());
  const Eigen::MatrixXd S2 = *dense_view(two.matrix());
  EXPECT_LT((S2 - S1).norm(), 1e-12 * S1.norm());
  const Vector g1 = one.condensed_load(p.b);
  const Vector g2 = two.condensed_load(p.b);
  EXPECT_LT(relative_difference(g2, g1), 1e-12);
  // The solves: backward errors at rounding level, and the two paths' solutions equal to what
  // A's condition number allows.
  const Vector f = Vector::LinSpaced(static_cast<Index>(last.size()), 1.0, -3.0) * g1.norm();
  Vector rhs = p.b;
  for (std::size_t k = 0; k < last.size(); ++k) rhs(last[k]) += f(static_cast<Index>(k));
  // Normwise backward error ||A x - r|| / (||A|| ||x|| + ||r||).
  const double norm_A = p.A.norm();
  auto backward_error = [&](const Vector& x, const Vector& r) {
    return (p.A * x - r).norm() / (norm_A * x.norm() + r.norm());
  };
  const Vector x1 = one.solve_with_condensed_forces(f);
  const Vector x2 = two.solve_with_condensed_forces(f);
  EXPECT_LT(backward_error(x2, rhs), 1e-15) << backward_error(x1, rhs);
  EXPECT_LT(relative_difference(x2, x1), 1e-10);
  const Vector y2 = two.solve(p.b);
  EXPECT_LT(backward_error(y2, p.b), 1e-15) << backward_error(one.solve(p.b), p.b);
  EXPECT_LT(relative_difference(y2, one.solve(p.b)), 1e-10);
  // The phases are timed on either path.
  for (const char* phase : {"condensation analysis", "condensation factorization",
                            "condensation Schur complement", "condensation solve"})
    EXPECT_GT(two.timings().seconds(phase), 0.0) << phase;
}

TEST(VertexSeparator, SplitsThePaperStiffnessInTwoUncoupledHalves) {
  const ContactProblem& p = testing::paper_model(120).problem;  // 121 x 41 nodes
  const VertexSeparator s = vertex_separator(p.A);
  ASSERT_EQ(static_cast<Index>(s.part.size()), p.A.rows());
  EXPECT_EQ(s.part_size[0] + s.part_size[1] + s.separator_size, p.A.rows());
  // About half each, and a separator about one column of nodes across (41 nodes, 2 unknowns each).
  for (const Index size : s.part_size) EXPECT_GT(size, p.A.rows() / 3);
  EXPECT_LE(s.separator_size, 2 * 2 * 41);
  // No entry of A couples the two parts.
  for (Index j = 0; j < p.A.cols(); ++j)
    for (SparseMatrix::InnerIterator it(p.A, j); it; ++it) {
      const int a = s.part[static_cast<std::size_t>(it.row())];
      const int b = s.part[static_cast<std::size_t>(j)];
      EXPECT_FALSE((a == 0 && b == 1) || (a == 1 && b == 0)) << it.row() << " " << j;
    }
}

}  // namespace
}  // namespace signorini

// The condensed (Schur complement) path solves the same discrete problem as the plain sparse path:
// same u and l to round-off, same iteration counts on the paper's meshes, for every method, also
// with oblique normals and contact nodes that are clamped in one direction only.

#include "signorini/contact/condensed_problem.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "signorini/fem/contact_boundary.hpp"
#include "signorini/linalg/dense_storage.hpp"
#include "signorini/linalg/schur_complement.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

ContactResult solve(const ContactProblem& p, ContactMethod method, bool schur) {
  ContactSolverOptions o;
  o.method = method;
  o.schur_complement = schur;
  o.uzawa_tolerance = method == ContactMethod::ClassicalUzawa ? 1e-14 : 1e-12;
  return solve_contact(p, o);
}

TEST(SchurComplement, MatchesTheDenseFormulas) {
  // A small SPD matrix: a 2D Laplacian-like stencil plus a diagonal shift.
  const Index n = 30;
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
  const std::vector<Index> last{3, 17, 29, 8};
  SchurComplement sc(A, last);
  std::vector<Index> interior;
  for (Index i = 0; i < n; ++i)
    if (std::find(last.begin(), last.end(), i) == last.end()) interior.push_back(i);
  const Eigen::MatrixXd D(A);
  const Eigen::MatrixXd Aii = D(interior, interior), Aic = D(interior, last), Acc = D(last, last);
  const Eigen::MatrixXd S = Acc - Aic.transpose() * Aii.llt().solve(Aic);
  ASSERT_TRUE(dense_view(sc.matrix()).has_value());  // S is kept once, every entry stored
  EXPECT_LT((*dense_view(sc.matrix()) - S).norm(), 1e-12 * S.norm());
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

class CondensedVsPlain : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(CondensedVsPlain, PaperProblemGivesTheSameSolution) {
  const ContactProblem& p = testing::paper_model(60).problem;
  const ContactResult plain = solve(p, GetParam(), false);
  const ContactResult condensed = solve(p, GetParam(), true);
  ASSERT_TRUE(plain.summary.converged()) << plain.summary.message;
  ASSERT_TRUE(condensed.summary.converged()) << condensed.summary.message;
  EXPECT_LT(relative_difference(condensed.u, plain.u), 1e-10);
  EXPECT_LT(relative_difference(condensed.l, plain.l), 1e-9);
  EXPECT_EQ(condensed.summary.num_active, plain.summary.num_active);
  if (GetParam() != ContactMethod::ClassicalUzawa) {
    EXPECT_EQ(condensed.summary.outer_iterations, plain.summary.outer_iterations);
  }
  EXPECT_LT(condensed.summary.kkt.max(), 1e-8);
}

TEST_P(CondensedVsPlain, ObliqueNormalsAndPartlyClampedContactNodes) {
  // Contact on the bottom and right edges together: the corner (3, 0) gets the normal
  // (1, -1)/sqrt(2). With the right edge free, the corner's two dofs are rotated (Householder);
  // with the right edge clamped in x, the corner moves in y only and the right-edge nodes cannot
  // move along their normal. The load pushes down and to the right; the gap grows with y.
  for (const bool right_clamped : {false, true}) {
    SCOPED_TRACE(right_clamped ? "right edge clamped in x" : "right edge free");
    ProblemSpec spec = paper_benchmark(30, 10);
    spec.clamps = {{"left", {true, true, true}}};
    if (right_clamped) spec.clamps.push_back({"right", {true, false, false}});
    spec.tractions = {{"top",
                       [](const Point& x) { return Eigen::Vector3d(0.2, -1.0 - x(0), 0.0); },
                       "oblique",
                       {}}};
    Model model = build_model(spec);
    Mesh& mesh = model.mesh;
    auto facets = mesh.boundary_part("bottom").facets;
    for (const Facet& f : mesh.boundary_part("right").facets) facets.push_back(f);
    mesh.set_boundary_part("bottom_right", facets);
    model.problem.contact = make_contact_set(mesh, mesh.boundary_part("bottom_right"), model.dofs,
                                             [](const Point& x) { return 1e-6 * x(1); });
    const ContactProblem& p = model.problem;
    const ContactResult plain = solve(p, GetParam(), false);
    const ContactResult condensed = solve(p, GetParam(), true);
    ASSERT_TRUE(plain.summary.converged()) << plain.summary.message;
    ASSERT_TRUE(condensed.summary.converged()) << condensed.summary.message;
    EXPECT_GT(plain.summary.num_active, 0);
    EXPECT_LT(relative_difference(condensed.u, plain.u), 1e-9);
    EXPECT_LT(relative_difference(condensed.l, plain.l), 1e-8);
    EXPECT_LT(condensed.summary.kkt.max(), 1e-8);
  }
}

INSTANTIATE_TEST_SUITE_P(Methods, CondensedVsPlain,
                         ::testing::Values(ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton,
                                           ContactMethod::ClassicalUzawa),
                         [](const auto& param_info) {
                           return std::string(
                               enum_to_string(kContactMethodNames, param_info.param));
                         });

TEST(CondensedProblem, ReducedProblemHasOneUnknownPerMovableContactNode) {
  const ContactProblem& p = testing::paper_model(60).problem;
  const CondensedProblem c(p);
  EXPECT_EQ(c.reduced().A.rows(), p.contact.num_movable());
  EXPECT_EQ(c.reduced().contact.size(), p.contact.size());
  // Expanding the condensed solution of the unconstrained problem gives A^-1 b.
  const Vector v = Eigen::MatrixXd(c.reduced().A).llt().solve(c.reduced().b);
  const Vector u = c.expand(v);
  EXPECT_LT((p.A * u - p.b).norm(), 1e-10 * p.b.norm());
}

}  // namespace
}  // namespace signorini

// The condensed (Schur complement) path solves the same discrete problem as the plain sparse path:
// same u and l to round-off, same iteration counts on the paper's meshes, for every method, also
// with oblique normals and contact nodes that are clamped in one direction only.

#include "signorini/contact/condensed_problem.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>

#include "signorini/interface/contact_boundary.hpp"
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

namespace signorini {
namespace {

TEST(CondensedProblem, TwoThreadsGiveTheSolutionOfOneOnTable1sLargestMesh) {
  // 480x160 (154,882 unknowns) is above SchurComplement::kTwoPartUnknowns: with two threads the
  // condensation factorises two parts at once; the counts are Table 1's and the solution is the
  // one-thread solution up to rounding.
  const ContactProblem& p = testing::paper_model(480).problem;
  ASSERT_GE(p.A.rows(), SchurComplement::kTwoPartUnknowns);
  ContactSolverOptions o;
  o.threads = 1;
  const ContactResult one = solve_contact(p, o);
  o.threads = 2;
  const ContactResult two = solve_contact(p, o);
  ASSERT_TRUE(one.summary.converged()) << one.summary.message;
  ASSERT_TRUE(two.summary.converged()) << two.summary.message;
  EXPECT_EQ(two.summary.outer_iterations, one.summary.outer_iterations);
  EXPECT_EQ(two.summary.inner_iterations(), one.summary.inner_iterations());
  EXPECT_EQ(two.summary.num_active, one.summary.num_active);
  EXPECT_LT(relative_difference(two.u, one.u), 1e-10);  // as the condensed against the plain path
  EXPECT_LT(relative_difference(two.l, one.l), 1e-9);
}

}  // namespace
}  // namespace signorini

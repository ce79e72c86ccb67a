// Problems beyond the paper's data: a positive gap, a body pulled away from the foundation, and
// a curved gap; the methods must still agree and satisfy the KKT conditions.

#include <gtest/gtest.h>

#include "test_problems.hpp"

namespace signorini {
namespace {

ContactResult run(const ProblemSpec& spec, ContactMethod method) {
  const Model model = build_model(spec);
  ContactSolverOptions o = spec.solver;
  o.method = method;
  o.uzawa_tolerance = 1e-12;
  return solve_contact(model.problem, o);
}

TEST(GapAndLoads, PositiveGapReducesContactAndMethodsAgree) {
  ProblemSpec spec = paper_benchmark(60, 20);
  const ContactResult touching = run(spec, ContactMethod::SemismoothNewton);
  spec.contacts[0].gap = [](const Point& x) { return 2e-6 * (1.0 + x(0)); };
  const ContactResult ssn = run(spec, ContactMethod::SemismoothNewton);
  const ContactResult gnm = run(spec, ContactMethod::UzawaGnm);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  ASSERT_TRUE(gnm.summary.converged()) << gnm.summary.message;
  EXPECT_LT(ssn.summary.kkt.max(), 1e-9);
  EXPECT_LT(gnm.summary.kkt.max(), 1e-8);
  EXPECT_LT(testing::relative_difference(gnm.u, ssn.u), 1e-8);
  EXPECT_LT(testing::relative_difference(gnm.l, ssn.l), 1e-8);
  EXPECT_LT(ssn.summary.contact_force, touching.summary.contact_force);
  EXPECT_GT(ssn.summary.num_active, 0);
}

// A negative gap is an initial interference: the foundation starts inside the body and pushes it
// out. Without loads, clamped on the left, the strip is lifted: where it touches u . nu = g < 0.
TEST(GapAndLoads, NegativeGapIsAnInterferenceThatPushesTheBodyOut) {
  ProblemSpec spec = paper_benchmark(60, 20);
  spec.tractions.clear();
  spec.contacts[0].gap = [](const Point&) { return -1e-6; };
  const Model model = build_model(spec);
  const ContactResult ssn = run(spec, ContactMethod::SemismoothNewton);
  const ContactResult gnm = run(spec, ContactMethod::UzawaGnm);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  ASSERT_TRUE(gnm.summary.converged()) << gnm.summary.message;
  EXPECT_LT(testing::relative_difference(gnm.u, ssn.u), 1e-8);
  EXPECT_GT(ssn.summary.num_active, 0);
  EXPECT_GT(ssn.summary.contact_force, 0.0);
  const Vector Nu = model.problem.contact.N * ssn.u;
  for (Index j = 0; j < Nu.size(); ++j) {
    if (ssn.l(j) > 0.0) {
      EXPECT_NEAR(Nu(j), -1e-6, 1e-15) << "node " << j;  // pushed out by |g|
    }
  }
}

TEST(GapAndLoads, BodyPulledAwayHasNoContact) {
  ProblemSpec spec = paper_benchmark(30, 10);
  spec.tractions = {{"top", [](const Point&) { return Eigen::Vector3d(0.0, 1.0, 0.0); }, "up", {}}};
  for (const auto method :
       {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton, ContactMethod::ClassicalUzawa}) {
    const ContactResult r = run(spec, method);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_EQ(r.summary.num_active, 0);
    EXPECT_EQ(r.l.norm(), 0.0);
    EXPECT_EQ(r.summary.outer_iterations, 1);
    // Without contact the solution is the linear-elastic one, with M = J.
    EXPECT_DOUBLE_EQ(r.summary.lagrangian, r.summary.energy);
  }
}

TEST(GapAndLoads, TotalContactForceBalancesTheLoadsWithTheClampReaction) {
  // Vertical equilibrium of the whole body: clamp reaction + tractions + contact force = 0.
  // The tractions give +1 (right edge) - 3 (top edge) = -2 MN/m; the contact force is positive
  // and smaller than 2, the clamp taking the rest.
  const ContactResult r = run(paper_benchmark(60, 20), ContactMethod::SemismoothNewton);
  EXPECT_GT(r.summary.contact_force, 0.0);
  EXPECT_LT(r.summary.contact_force, 2.0);
  EXPECT_NEAR(r.summary.contact_force_vector(1), r.summary.contact_force, 1e-12);
  EXPECT_NEAR(r.summary.contact_force_vector(0), 0.0, 1e-12);
}

}  // namespace
}  // namespace signorini

// Solvers never fail silently: limits that are too tight end in a reported termination reason
// with the residuals in the message, and bad options are rejected before any work.

#include <gtest/gtest.h>

#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

TEST(Termination, UzawaIterationLimitIsReported) {
  ContactSolverOptions o;
  o.max_uzawa_iterations = 2;
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_FALSE(r.summary.converged());
  EXPECT_EQ(r.summary.termination, Termination::IterationLimit);
  EXPECT_EQ(r.summary.outer_iterations, 2);
  EXPECT_NE(r.summary.message.find("did not converge"), std::string::npos) << r.summary.message;
}

TEST(Termination, GnmIterationLimitIsReported) {
  ContactSolverOptions o;
  o.max_gnm_iterations = 3;  // the first Uzawa step needs 7
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_EQ(r.summary.termination, Termination::IterationLimit);
  EXPECT_NE(r.summary.message.find("GNM did not converge"), std::string::npos);
  // Only what would help: GNM's limit is no case for semismooth Newton, whose active set moves
  // the same way.
  EXPECT_NE(r.summary.message.find("raise solver.max_gnm_iterations (it was 3)"), std::string::npos)
      << r.summary.message;
  EXPECT_EQ(r.summary.message.find("semismooth_newton"), std::string::npos) << r.summary.message;
}

TEST(Termination, SemismoothNewtonIterationLimitIsReported) {
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  o.max_newton_iterations = 2;
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_EQ(r.summary.termination, Termination::IterationLimit);
  // Its active set never returns to an earlier one, so more steps end it; Uzawa-GNM's would
  // move the same way, so it is not advised.
  EXPECT_NE(r.summary.message.find("raise solver.max_newton_iterations (it was 2)"),
            std::string::npos)
      << r.summary.message;
  EXPECT_EQ(r.summary.message.find("uzawa_gnm"), std::string::npos) << r.summary.message;
}

TEST(Termination, ConjugateGradientLimitIsALinearSolverFailure) {
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.cg_max_iterations = 5;
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_EQ(r.summary.termination, Termination::LinearSolverFailure);
}

// solver.time_limit: every method stops at its first iteration past the limit with termination
// "time_limit", the iterate it had and its KKT residuals; a user's callback still runs.
TEST(Termination, TimeLimitStopsEveryMethod) {
  for (const ContactMethod method :
       {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton, ContactMethod::ClassicalUzawa}) {
    SCOPED_TRACE(std::string(enum_to_string(kContactMethodNames, method)));
    ContactSolverOptions o;
    o.method = method;
    o.time_limit = 1e-9;
    int calls = 0;
    o.callback = [&](const IterationEvent&) {
      ++calls;
      return CallbackAction::Continue;
    };
    const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
    EXPECT_EQ(r.summary.termination, Termination::TimeLimit);
    EXPECT_FALSE(r.summary.converged());
    EXPECT_EQ(calls, 1);
    EXPECT_NE(r.summary.message.find("stopped at solver.time_limit = 1e-09 s"), std::string::npos)
        << r.summary.message;
    EXPECT_NE(r.summary.message.find("KKT residuals: equilibrium"), std::string::npos);
    EXPECT_NE(r.summary.message.find("raise solver.time_limit"), std::string::npos);
    // Classical Uzawa's linear steps are what Uzawa-GNM's Newton steps replace.
    EXPECT_EQ(r.summary.message.find("solver.method = \"uzawa_gnm\"") != std::string::npos,
              method == ContactMethod::ClassicalUzawa)
        << r.summary.message;
    EXPECT_EQ(r.u.size(), testing::paper_model(60).problem.A.rows());
  }
  // A limit that is not reached changes nothing.
  ContactSolverOptions o;
  const ContactResult free = solve_contact(testing::paper_model(60).problem, o);
  o.time_limit = 1e6;
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_EQ(r.summary.outer_iterations, free.summary.outer_iterations);
  EXPECT_EQ(r.u, free.u);
  o.time_limit = -1.0;
  EXPECT_THROW((void)solve_contact(testing::paper_model(60).problem, o), InputError);
}

// The paper's strip on 1600 x 1 cells (aspect 530, 1,601 contact nodes, automatic r): each
// active-set step releases a few nodes only, and the first Uzawa step needs 125 GNM steps, more
// than the fixed limit of 100 that stopped it. The automatic limits (a quarter of the contact
// nodes: 400 for GNM and semismooth Newton) let both converge, to the same energy.
TEST(Termination, AutomaticLimitsLetAThinStripConverge) {
  ProblemSpec spec = paper_benchmark(1600, 1);
  spec.solver.r.reset();
  const Model model = build_model(spec);
  const Index nodes = model.problem.contact.size();
  ASSERT_EQ(nodes, 1601);
  ContactSolverOptions o = spec.solver;  // the paper's settings, r automatic
  EXPECT_EQ(gnm_iteration_limit(o, nodes), 400);
  EXPECT_EQ(newton_iteration_limit(o, nodes), 400);
  EXPECT_EQ(gnm_iteration_limit(o, 40), 100);     // at least 100
  EXPECT_EQ(newton_iteration_limit(o, 40), 200);  // at least 200
  EXPECT_EQ(gnm_iteration_limit(o, 1'000'000), 2000);
  ContactSolverOptions given = o;
  given.max_gnm_iterations = 7;
  EXPECT_EQ(gnm_iteration_limit(given, nodes), 7);  // given: as given

  const ContactResult gnm = solve_contact(model.problem, o);
  ASSERT_TRUE(gnm.summary.converged()) << gnm.summary.message;
  EXPECT_GT(gnm.summary.steps.front().inner_iterations, 100);
  ContactSolverOptions ssn_options = o;
  ssn_options.method = ContactMethod::SemismoothNewton;
  const ContactResult ssn = solve_contact(model.problem, ssn_options);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  EXPECT_GT(ssn.summary.outer_iterations, 100);
  EXPECT_NEAR(ssn.summary.energy, gnm.summary.energy, 1e-9 * std::abs(gnm.summary.energy));
}

TEST(Termination, InvalidOptionsAreRejectedWithTheFieldName) {
  ContactSolverOptions o;
  o.r = -1.0;
  try {
    (void)solve_contact(testing::paper_model(60).problem, o);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("solver.r"), std::string::npos) << e.what();
  }
  o = {};
  o.armijo_sigma = 0.7;
  EXPECT_THROW((void)solve_contact(testing::paper_model(60).problem, o), InputError);
  o = {};
  o.linear.cg_tolerance = 0.0;
  EXPECT_THROW((void)solve_contact(testing::paper_model(60).problem, o), InputError);
}

}  // namespace
}  // namespace signorini

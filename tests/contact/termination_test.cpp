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
}

TEST(Termination, SemismoothNewtonIterationLimitIsReported) {
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  o.max_newton_iterations = 2;
  const ContactResult r = solve_contact(testing::paper_model(60).problem, o);
  EXPECT_EQ(r.summary.termination, Termination::IterationLimit);
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

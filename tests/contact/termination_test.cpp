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

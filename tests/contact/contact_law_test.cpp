// The contact law as an open part: the unilateral law's projection, derivative and penalty
// change, and a law given in the options is the one the Uzawa-GNM and classical Uzawa loops use.

#include "signorini/contact/contact_law.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "signorini/core/error.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

TEST(UnilateralContactLaw, ProjectionDerivativeAndPenaltyChange) {
  const ContactLaw& law = unilateral_contact_law();
  EXPECT_EQ(law.name(), "unilateral");
  Vector z(4);
  z << -2.0, 0.0, 3.0, -std::numeric_limits<double>::infinity();
  const Vector p = law.project(z);
  EXPECT_EQ(p(0), 0.0);
  EXPECT_EQ(p(1), 0.0);
  EXPECT_EQ(p(2), 3.0);
  EXPECT_EQ(p(3), 0.0);  // a node that cannot move
  EXPECT_EQ(law.active_set(z), (ActiveSet{false, false, true, false}));
  EXPECT_DOUBLE_EQ(law.penalty_change(2.0, 1.0), 9.0 - 4.0);
  EXPECT_DOUBLE_EQ(law.penalty_change(2.0, -5.0), -4.0);
  EXPECT_DOUBLE_EQ(law.penalty_change(-1.0, 3.0), 4.0);
  // No cancellation: (z0 + dz)^2 - z0^2 for z0 = 1e8 and dz = 1e-8 is 2 + 1e-16, which the
  // difference of the squares would lose entirely.
  EXPECT_NEAR(law.penalty_change(1e8, 1e-8), 2.0, 1e-15);
}

// The unilateral law, counting its calls.
class CountingLaw final : public ContactLaw {
 public:
  [[nodiscard]] std::string_view name() const override { return "counting"; }
  [[nodiscard]] Vector project(const Vector& z) const override {
    ++projections;
    return unilateral_contact_law().project(z);
  }
  [[nodiscard]] ActiveSet active_set(const Vector& z) const override {
    ++derivatives;
    return unilateral_contact_law().active_set(z);
  }
  [[nodiscard]] double penalty_change(double z0, double dz) const override {
    ++penalties;
    return unilateral_contact_law().penalty_change(z0, dz);
  }
  mutable int projections = 0, derivatives = 0, penalties = 0;
};

TEST(ContactLaw, TheLawOfTheProblemIsTheOneTheLoopsUse) {
  const ContactProblem& p = testing::paper_model(60).problem;
  for (const auto method : {ContactMethod::UzawaGnm, ContactMethod::ClassicalUzawa}) {
    ContactSolverOptions o;
    o.method = method;
    const ContactResult reference = solve_contact(p, o);
    CountingLaw law;
    const ContactResult counted = solve_contact(testing::with_law(p, law), o);
    ASSERT_TRUE(counted.summary.converged()) << counted.summary.message;
    EXPECT_GT(law.projections, 0);
    EXPECT_GT(law.penalties, 0);  // M(u, l) of the summary, at least
    if (method == ContactMethod::UzawaGnm) {
      EXPECT_GT(law.derivatives, 0);
    }
    // The same law by another object: the same iterates, to the last bit.
    EXPECT_EQ(counted.u, reference.u);
    EXPECT_EQ(counted.l, reference.l);
    EXPECT_EQ(counted.summary.lagrangian, reference.summary.lagrangian);
  }
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  CountingLaw law;
  try {
    (void)solve_contact(testing::with_law(p, law), o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("unilateral contact law only, not \"counting\""),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signorini

// What a frictional law says of itself and of a solution's nodes: its name as the problem states
// it (Tresca with a zero bound is still Tresca), and each node's state, `separated` wherever the
// pressure is zero (a Tresca node that has lifted off may carry a traction at the bound: the
// classical model's, not a contact's).

#include "signorini/contact/friction_law.hpp"

#include <gtest/gtest.h>

namespace signorini {
namespace {

TEST(FrictionLaw, NameIsTheLawStated) {
  const Vector zero = Vector::Zero(3), one = Vector::Ones(3);
  EXPECT_EQ(FrictionLaw(FrictionKind::Tresca, 2, zero).name(), "tresca");
  EXPECT_EQ(FrictionLaw(FrictionKind::Coulomb, 2, zero).name(), "coulomb");
  EXPECT_EQ(FrictionLaw(2, zero, zero, {FrictionKind::Tresca}).name(), "tresca");
  EXPECT_EQ(FrictionLaw(2, zero, zero, {FrictionKind::Tresca, FrictionKind::Coulomb}).name(),
            "tresca and coulomb");
  // Without the stated kinds: from the positive bounds.
  EXPECT_EQ(FrictionLaw(2, one, zero).name(), "tresca");
  EXPECT_EQ(FrictionLaw(2, zero, one).name(), "coulomb");
}

TEST(FrictionLaw, StatesSeparateNodesWithoutPressure) {
  // Tresca, s = 2 on three nodes: one lifted off with its traction at the bound, one in contact
  // at the bound, one in contact below it.
  const FrictionLaw law(FrictionKind::Tresca, 2, Vector::Constant(3, 2.0));
  Vector pressure(3);
  pressure << 0.0, 5.0, 5.0;
  Matrix tangential(1, 3);
  tangential << 2.0, -2.0, 0.5;
  const std::vector<FrictionState> states = friction_states(law, pressure, tangential);
  EXPECT_EQ(states[0], FrictionState::Separated);
  EXPECT_EQ(states[1], FrictionState::Sliding);
  EXPECT_EQ(states[2], FrictionState::Sticking);
}

}  // namespace
}  // namespace signorini

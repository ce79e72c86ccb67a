// The seam to a distributed engine (src/signorini/contact/distributed_engine.hpp) in a program
// without one: the serial paths, and clear errors where the options ask for the distributed one.

#include "signorini/contact/distributed_engine.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "../test_problems.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

TEST(DistributedEngine, WithoutAnEngineTheSerialPathsRun) {
  ContactSolverOptions o;
  EXPECT_FALSE(distributed_path(nullptr, o));  // auto
  o.distributed = DistributedMode::Off;
  EXPECT_FALSE(distributed_path(nullptr, o));
  o.distributed = DistributedMode::Petsc;
  try {
    (void)distributed_path(nullptr, o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("signorini-mpi"), std::string::npos) << e.what();
  }
  // The products and sums of a whole problem are the serial ones.
  const ContactProblem& p = testing::paper_model(30).problem;
  const Vector u = Vector::LinSpaced(p.A.rows(), -1.0, 1.0);
  EXPECT_FALSE(p.partitioned());
  EXPECT_EQ(p.engine, nullptr);  // (build_model without an engine)
  EXPECT_FALSE(distributed_path(p, ContactSolverOptions{}));
  EXPECT_EQ(p.first_row(), 0);
  EXPECT_EQ(p.end_row(), p.A.rows());
  EXPECT_EQ(held_stiffness_rows(p, u), p.A * u);
  const double energy = 0.5 * u.dot(p.A * u) - p.b.dot(u);
  EXPECT_NEAR(quadratic_energy(p, u), energy, 1e-14 * std::abs(energy));
  EXPECT_EQ(load_norm(p), p.b.norm());
}

TEST(DistributedEngine, APartitionedProblemNeedsItsEngine) {
  ContactProblem p = testing::paper_model(30).problem;
  p.row_starts = {0, p.A.rows()};
  const Vector u = Vector::Ones(p.A.rows());
  EXPECT_THROW((void)quadratic_energy(p, u), InputError);
  EXPECT_THROW((void)load_norm(p), InputError);
  EXPECT_THROW((void)solve_contact(p, ContactSolverOptions{}), InputError);
}

}  // namespace
}  // namespace signorini

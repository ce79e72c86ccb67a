// Semismooth Newton on the PETSc engine (src/signorini/petsc/petsc_active_set_solver.hpp), run
// on 1, 2 and 4 ranks on the partitioned model: the same active sets step by step as the serial
// solver, and u and l to 1e-8, with MUMPS and with CG and GAMG; and the two methods agree on the
// distributed path.

#include <gtest/gtest.h>

#include "../problem/ball_on_block.hpp"
#include "../test_problems.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

void expect_same_steps(const ContactResult& distributed, const ContactResult& serial) {
  testing::expect_distributed_agrees(distributed, serial);
  if (::testing::Test::HasFatalFailure()) return;
  ASSERT_EQ(distributed.summary.steps.size(), serial.summary.steps.size());
  for (std::size_t k = 0; k < serial.summary.steps.size(); ++k)
    EXPECT_EQ(distributed.summary.steps[k].active_set_size, serial.summary.steps[k].active_set_size)
        << "Newton step " << k + 1;
}

TEST(DistributedSemismoothNewton, PaperProblemWithMumpsTakesTheSerialSteps) {
  const ProblemSpec spec = paper_benchmark(60, 20);
  ContactSolverOptions o;
  o.method = ContactMethod::SemismoothNewton;
  o.schur_complement = false;  // the serial sparse path: the same elimination
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, o);
  expect_same_steps(distributed, testing::serial_solve(testing::serial_model(spec), o));
  EXPECT_NE(distributed.summary.device.find("MUMPS"), std::string::npos);

  // Uzawa-GNM on the same path reaches the same solution.
  ContactSolverOptions gnm = o;
  gnm.method = ContactMethod::UzawaGnm;
  gnm.uzawa_tolerance = 1e-12;
  const ContactResult uzawa = testing::distributed_solve(model, gnm);
  ASSERT_TRUE(uzawa.summary.converged()) << uzawa.summary.message;
  EXPECT_LT(testing::relative_difference_where_known(uzawa.u, distributed.u), 1e-8);
}

TEST(DistributedSemismoothNewton, BallOnBlockWithGamgTakesTheSerialSteps) {
  ProblemSpec spec = testing::ball_on_block(8, 6e-3);
  spec.solver.automatic_path = false;
  spec.solver.method = ContactMethod::SemismoothNewton;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  ContactSolverOptions direct = serial_model.solver;  // the serial steps by sparse elimination
  direct.linear.type = LinearSolverType::Cholmod;
  direct.schur_complement = false;
  expect_same_steps(distributed, testing::serial_solve(serial_model, direct));
  EXPECT_NE(distributed.summary.device.find("gamg"), std::string::npos);
}

}  // namespace
}  // namespace signorini

// Friction on the distributed path (docs/distributed.md, "Friction"): Uzawa-GNM with Tresca's
// and Coulomb's laws on the PETSc engine, run on 1, 2 and 4 ranks, against the serial solve of
// the same problem on the same rank (u, l and the tangential forces to 1e-8, the same Uzawa
// counts), in 2D with MUMPS and in 3D with CG and GAMG's kept levels (the nodes' coupled blocks
// on the fine level, W's diagonal on the coarse ones), and classical Uzawa; semismooth Newton
// with friction is refused there with a message.

#include <gtest/gtest.h>

#include "../problem/ball_on_block.hpp"
#include "../test_problems.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/core/error.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {
namespace {

using testing::relative_difference;
using testing::with_friction;

void expect_same_frictional_solve(const ContactResult& distributed, const ContactResult& serial) {
  testing::expect_distributed_agrees(distributed, serial);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(distributed.summary.outer_iterations, serial.summary.outer_iterations);
  ASSERT_EQ(distributed.tangential.rows(), serial.tangential.rows());
  ASSERT_GT(serial.tangential.size(), 0);
  EXPECT_LT(relative_difference(distributed.tangential.reshaped(), serial.tangential.reshaped()),
            1e-8);
  // Friction did something: some node carries a tangential force.
  EXPECT_GT(serial.tangential.cwiseAbs().maxCoeff(), 0.0);
}

// The distributed solve of the partitioned model and the serial solve on this rank, checked
// against each other (expect_same_frictional_solve).
std::pair<ContactResult, ContactResult> solve_both_ways(const ProblemSpec& spec) {
  const Model part = testing::distributed_model(spec);
  ContactResult distributed = testing::distributed_solve(part, part.solver);
  const Model whole = testing::serial_model(spec);
  ContactResult serial = testing::serial_solve(whole, whole.solver);
  expect_same_frictional_solve(distributed, serial);
  return {std::move(distributed), std::move(serial)};
}

// The paper's strip with Coulomb's and Tresca's laws: MUMPS's distributed factorisation of
// H = A + N^T W N on the partitioned model, against the serial condensed path.
TEST(DistributedFriction, PaperStripWithMumpsMatchesTheSerialSolve) {
  for (const auto& [model, value] :
       {std::pair{FrictionModel::Coulomb, 0.5}, std::pair{FrictionModel::Tresca, 0.05}}) {
    SCOPED_TRACE(model == FrictionModel::Coulomb ? "Coulomb" : "Tresca");
    ProblemSpec spec = with_friction(paper_benchmark(40, 12), model, value);
    spec.solver.uzawa_tolerance = 1e-11;
    const auto [distributed, serial] = solve_both_ways(spec);
    EXPECT_NE(distributed.summary.device.find("MUMPS"), std::string::npos)
        << distributed.summary.device;
    // Both solve their Newton systems exactly, with the same matrix: the same GNM steps.
    ASSERT_EQ(distributed.summary.steps.size(), serial.summary.steps.size());
    for (std::size_t k = 0; k < serial.summary.steps.size(); ++k)
      EXPECT_EQ(distributed.summary.steps[k].inner_iterations,
                serial.summary.steps[k].inner_iterations)
          << "Uzawa step " << k + 1;
  }
}

// A 3D block pressed onto a rigid ball with Coulomb friction: CG with GAMG's levels kept, the
// sliding nodes' 3 x 3 blocks changing with every Newton step, against the serial multigrid CG.
TEST(DistributedFriction, BallOnBlockWithGamgMatchesTheSerialSolve) {
  ProblemSpec spec = with_friction(testing::ball_on_block(8, 3e-2), FrictionModel::Coulomb, 0.2);
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.linear.cg_tolerance = 1e-13;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  spec.solver.uzawa_tolerance = 1e-10;
  spec.solver.petsc_multigrid = PetscMultigrid::Gamg;  // (the default's choice on several ranks)
  const auto [distributed, serial] = solve_both_ways(spec);
  EXPECT_NE(distributed.summary.device.find("PC mg (GAMG's levels, kept"), std::string::npos)
      << distributed.summary.device;
  // Some nodes slide (their blocks are not the identity's): |t| reaches mu p somewhere.
  int sliding = 0;
  for (Index j = 0; j < serial.l.size(); ++j)
    if (serial.l(j) > 0.0 && serial.tangential.col(j).norm() > (1.0 - 1e-6) * 0.2 * serial.l(j))
      ++sliding;
  EXPECT_GT(sliding, 0);
}

// Classical Uzawa with Tresca's law: the same projected steps on every row of N (normals and
// tangents), A factorised once by MUMPS, against the serial tool's.
TEST(DistributedFriction, ClassicalUzawaMatchesTheSerialSolve) {
  ProblemSpec spec = with_friction(paper_benchmark(12, 4), FrictionModel::Tresca, 0.05);
  spec.solver.method = ContactMethod::ClassicalUzawa;
  spec.solver.uzawa_tolerance = 1e-9;
  const auto [distributed, serial] = solve_both_ways(spec);
  EXPECT_GT(serial.summary.outer_iterations, 10);
  EXPECT_NEAR(distributed.summary.classical_step, serial.summary.classical_step,
              1e-9 * serial.summary.classical_step);
}

// Semismooth Newton with friction factorises the whole KKT system in one process: refused on
// the distributed path, on every rank alike, with a message that names the way out, when the
// model is built (the tool's check) and by the solver itself for a model built otherwise.
TEST(DistributedFriction, SemismoothNewtonWithFrictionIsRefusedWithAMessage) {
  ProblemSpec spec = with_friction(paper_benchmark(12, 4), FrictionModel::Coulomb, 0.3);
  spec.solver.method = ContactMethod::SemismoothNewton;
  try {
    (void)testing::distributed_model(spec);
    ADD_FAILURE() << "no error from the model";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("uzawa_gnm"), std::string::npos) << e.what();
  }
  spec.solver.method = ContactMethod::UzawaGnm;
  const Model part = testing::distributed_model(spec);
  ContactSolverOptions o = part.solver;
  o.method = ContactMethod::SemismoothNewton;
  try {
    (void)testing::distributed_solve(part, o);
    ADD_FAILURE() << "no error from the solver";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("uzawa_gnm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace signorini

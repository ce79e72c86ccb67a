// Uzawa-GNM on the PETSc engine (src/signorini/petsc/, docs/distributed.md), run on 1, 2 and 4
// ranks: the same Uzawa steps as the serial solver on every rank, and u and l to 1e-8 (the
// distributed issue's check), with each of the KSP configurations that the options choose.

#include <gtest/gtest.h>
#include <petscsys.h>

#include "../problem/ball_on_block.hpp"
#include "../test_problems.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/parallel/distributed_engine.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

// The serial solve on this rank alone: without the engine the solver takes a serial path.
ContactResult serial_solve(const ContactProblem& problem, ContactSolverOptions o,
                           const MultigridHierarchy* multigrid = nullptr) {
  DistributedEngine* engine = distributed_engine();
  set_distributed_engine(nullptr);
  o.distributed = DistributedMode::Auto;
  ContactResult r = solve_contact(problem, o, multigrid);
  set_distributed_engine(engine);
  return r;
}

void expect_same_solve(const ContactResult& distributed, const ContactResult& serial) {
  ASSERT_TRUE(distributed.summary.converged()) << distributed.summary.message;
  ASSERT_TRUE(serial.summary.converged()) << serial.summary.message;
  EXPECT_EQ(distributed.summary.path, SolvePath::Distributed);
  EXPECT_EQ(distributed.summary.ranks, distributed_engine()->size());
  EXPECT_EQ(distributed.summary.outer_iterations, serial.summary.outer_iterations);
  EXPECT_LT(relative_difference(distributed.u, serial.u), 1e-8);
  EXPECT_LT(relative_difference(distributed.l, serial.l), 1e-8);
  EXPECT_LT(distributed.summary.kkt.max(), 1e-8);
}

// The paper's problem with the direct solver: MUMPS's distributed Cholesky factorisation,
// against the serial condensed path.
TEST(DistributedUzawaGnm, PaperProblemWithMumpsMatchesTheSerialSolve) {
  const ContactProblem& problem = testing::paper_model(60).problem;
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-10;
  o.distributed = DistributedMode::Petsc;
  const ContactResult distributed = solve_contact(problem, o);
  const ContactResult serial = serial_solve(problem, o);
  expect_same_solve(distributed, serial);
  // The same GNM counts too: both factorise, so the Newton steps are exact.
  ASSERT_EQ(distributed.summary.steps.size(), serial.summary.steps.size());
  for (std::size_t k = 0; k < serial.summary.steps.size(); ++k)
    EXPECT_EQ(distributed.summary.steps[k].inner_iterations,
              serial.summary.steps[k].inner_iterations)
        << "Uzawa step " << k + 1;
  EXPECT_NE(distributed.summary.device.find("MUMPS"), std::string::npos)
      << distributed.summary.device;
}

// A 3D block on a rigid ball with CG and GAMG on the rigid-body modes (build_model gives them
// for the distributed path), against the serial CG with smoothed aggregation.
TEST(DistributedUzawaGnm, BallOnBlockWithGamgMatchesTheSerialSolve) {
  ProblemSpec spec = testing::ball_on_block(8, 6e-3);
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  spec.solver.uzawa_tolerance = 1e-10;
  spec.solver.distributed = DistributedMode::Petsc;
  const Model model = build_model(spec);
  ASSERT_EQ(model.problem.near_null_space.cols(), 6);
  ASSERT_EQ(model.problem.node_of_unknown.size(), static_cast<std::size_t>(model.problem.A.rows()));
  const ContactResult distributed = solve_contact(model.problem, model.solver);

  ProblemSpec serial_spec = spec;
  serial_spec.solver.distributed = DistributedMode::Auto;
  DistributedEngine* engine = distributed_engine();
  set_distributed_engine(nullptr);
  const Model serial_model = build_model(serial_spec);
  set_distributed_engine(engine);
  const ContactResult serial =
      serial_solve(serial_model.problem, serial_model.solver, &serial_model.multigrid);
  expect_same_solve(distributed, serial);
  EXPECT_NE(distributed.summary.device.find("gamg"), std::string::npos)
      << distributed.summary.device;
  EXPECT_NE(distributed.summary.device.find("6 rigid-body modes"), std::string::npos);
  int cg = 0;
  for (const OuterStepRecord& s : distributed.summary.steps) cg += s.linear_iterations;
  EXPECT_GT(cg, 0);
}

// CG with hypre's BoomerAMG (solver.petsc_multigrid = "hypre") on the same 3D problem.
TEST(DistributedUzawaGnm, BallOnBlockWithHypreMatchesTheSerialSolve) {
  ProblemSpec spec = testing::ball_on_block(6, 6e-3);
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  spec.solver.uzawa_tolerance = 1e-10;
  spec.solver.distributed = DistributedMode::Petsc;
  spec.solver.petsc_multigrid = PetscMultigrid::Hypre;
  const Model model = build_model(spec);
  const ContactResult distributed = solve_contact(model.problem, model.solver);
  ContactSolverOptions direct = model.solver;
  direct.linear.type = LinearSolverType::Cholmod;
  expect_same_solve(distributed, serial_solve(model.problem, direct));
  EXPECT_NE(distributed.summary.device.find("PC hypre"), std::string::npos)
      << distributed.summary.device;
}

// CG with Jacobi, the paper's own configuration, on the paper's problem.
TEST(DistributedUzawaGnm, PaperProblemWithJacobiMatchesTheSerialSolve) {
  const ContactProblem& problem = testing::paper_model(30).problem;
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-10;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.cg_tolerance = 1e-13;
  o.distributed = DistributedMode::Petsc;
  const ContactResult distributed = solve_contact(problem, o);
  const ContactResult serial = serial_solve(problem, o);
  expect_same_solve(distributed, serial);
}

TEST(DistributedUzawaGnm, ClassicalUzawaIsRefusedWithAMessage) {
  ContactSolverOptions o;
  o.distributed = DistributedMode::Petsc;
  o.method = ContactMethod::ClassicalUzawa;
  try {
    (void)solve_contact(testing::paper_model(30).problem, o);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("uzawa_gnm"), std::string::npos) << e.what();
  }
}

TEST(DistributedUzawaGnm, PetscOptionsReachTheSolver) {
  const ContactProblem& problem = testing::paper_model(30).problem;
  ContactSolverOptions o;
  o.distributed = DistributedMode::Petsc;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.petsc_options = "-pc_type none";
  const ContactResult r = solve_contact(problem, o);
  // PETSc's options database is the process's: the next tests must not see this one.
  ASSERT_EQ(PetscOptionsClearValue(nullptr, "-pc_type"), 0);
  EXPECT_NE(r.summary.device.find("PC none"), std::string::npos) << r.summary.device;
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
}

}  // namespace
}  // namespace signorini

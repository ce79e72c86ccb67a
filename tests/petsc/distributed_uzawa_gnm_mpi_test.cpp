// Uzawa-GNM on the PETSc engine (src/signorini/petsc/, docs/distributed.md), run on 1, 2 and 4
// ranks: on the partitioned model (each rank its part of A), the same Uzawa steps as the serial
// solver on every rank, and u and l to 1e-8 (the distributed issue's check), with each of the
// KSP configurations that the options choose.

#include <gtest/gtest.h>
#include <petscsys.h>

#include <algorithm>

#include "../problem/ball_on_block.hpp"
#include "../problem/hertz_ball.hpp"
#include "../test_problems.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {
namespace {

using testing::relative_difference;

void expect_same_solve(const ContactResult& distributed, const ContactResult& serial) {
  testing::expect_distributed_agrees(distributed, serial);
  if (::testing::Test::HasFatalFailure()) return;
  EXPECT_EQ(distributed.summary.outer_iterations, serial.summary.outer_iterations);
  // The energy and the KKT residuals of the partitioned problem are sums over the ranks.
  EXPECT_LT(std::abs(distributed.summary.energy - serial.summary.energy),
            1e-10 * std::abs(serial.summary.energy));
}

// The partitioned model: each rank holds the columns of its own unknowns only, and they add up
// to the serial A.
void expect_own_columns(const ProblemSpec& spec);

TEST(DistributedModel, EachRankAssemblesItsOwnColumns) {
  expect_own_columns(paper_benchmark(30, 10));
}

// A Gmsh mesh, numbered in Z-order and then rank by rank, with rollers: a rank's part of the
// mesh keeps its nodes in the whole mesh's order, not the numbering's, and the columns' rows
// must still come in order.
TEST(DistributedModel, EachRankAssemblesItsOwnColumnsOfAGmshMeshOnRollers) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::Cholmod;
  expect_own_columns(spec);
}

void expect_own_columns(const ProblemSpec& spec) {
  const Model part = testing::distributed_model(spec);
  const Model whole = testing::serial_model(spec);
  ASSERT_TRUE(part.problem.partitioned());
  const DistributedEngine& engine = testing::mpi_engine();
  ASSERT_EQ(part.problem.row_starts.size(), static_cast<std::size_t>(engine.size()) + 1);
  const Index lo = part.problem.row_starts[static_cast<std::size_t>(engine.rank())];
  const Index hi = part.problem.row_starts[static_cast<std::size_t>(engine.rank()) + 1];
  // The two models number the unknowns differently (the distributed one rank by rank, after
  // the partition): whole_of[i] is the serial number of the distributed model's unknown i. On
  // more than one rank each rank holds its part of the mesh only (Model::is_part) and the mesh
  // node of its own unknowns (ContactProblem::node_of_unknown): those nodes and their free
  // components in order give its own unknowns' numbers, and the part's numbering the rest.
  const SparseMatrix& A = part.problem.A;
  EXPECT_EQ(part.is_part(), engine.size() > 1);
  const std::vector<Index>& node_of = part.problem.node_of_unknown;
  ASSERT_EQ(static_cast<Index>(node_of.size()), part.is_part() ? hi - lo : A.rows());
  const Index offset_of_first = part.is_part() ? lo : 0;
  std::vector<Index> whole_of(static_cast<std::size_t>(A.rows()), -1);
  for (Index i = lo, offset = 0; i < hi; ++i) {
    const auto at = static_cast<std::size_t>(i - offset_of_first);
    const Index node = node_of[at];
    offset = i > lo && node_of[at - 1] == node ? offset + 1 : 0;
    for (int k = 0, seen = 0; k < whole.dofs.dim(); ++k)
      if (whole.dofs.free_index(node, k) >= 0 && seen++ == offset)
        whole_of[static_cast<std::size_t>(i)] = whole.dofs.free_index(node, k);
    ASSERT_GE(whole_of[static_cast<std::size_t>(i)], 0) << "unknown " << i;
  }
  {  // every rank's, put together (each unknown is one rank's own)
    std::vector<double> sum(static_cast<std::size_t>(A.rows()), 0.0);
    for (Index i = lo; i < hi; ++i)
      sum[static_cast<std::size_t>(i)] =
          static_cast<double>(whole_of[static_cast<std::size_t>(i)] + 1);
    engine.sum(sum.data(), A.rows());
    for (Index i = 0; i < A.rows(); ++i)
      whole_of[static_cast<std::size_t>(i)] =
          static_cast<Index>(sum[static_cast<std::size_t>(i)]) - 1;
  }
  // (And the part's own numbering agrees with it at every node of the part.)
  for (Index v = 0; v < part.dofs.num_nodes(); ++v) {
    const Index node = part.is_part() ? part.global_nodes[static_cast<std::size_t>(v)] : v;
    for (int k = 0; k < part.dofs.dim(); ++k)
      if (const Index f = part.dofs.free_index(v, k); f >= 0) {
        EXPECT_EQ(whole_of[static_cast<std::size_t>(f)], whole.dofs.free_index(node, k));
      }
  }
  // Each column's rows in increasing order (what products and coeff() take for granted).
  for (Index col = 0; col < A.outerSize(); ++col)
    for (Index k = A.outerIndexPtr()[col] + 1; k < A.outerIndexPtr()[col + 1]; ++k)
      ASSERT_LT(A.innerIndexPtr()[k - 1], A.innerIndexPtr()[k]) << "column " << col;
  const auto w = [&](Index i) { return whole_of[static_cast<std::size_t>(i)]; };
  const double scale = whole.problem.A.norm();  // (sums in another order: rounding differs)
  // The rank's columns only (no array of all n columns): column k is unknown lo + k's.
  ASSERT_EQ(A.cols(), hi - lo);
  for (Index col = lo; col < hi; ++col) {
    const Index k = part.problem.column_of(col);
    ASSERT_EQ(k, col - lo);
    const Index entries = A.outerIndexPtr()[k + 1] - A.outerIndexPtr()[k];
    const Index serial_entries =
        whole.problem.A.outerIndexPtr()[w(col) + 1] - whole.problem.A.outerIndexPtr()[w(col)];
    EXPECT_EQ(entries, serial_entries) << "column " << col;
    for (SparseMatrix::InnerIterator it(A, k); it; ++it)
      EXPECT_LE(std::abs(it.value() - whole.problem.A.coeff(w(it.row()), w(col))), 1e-12 * scale)
          << "entry (" << it.row() << ", " << col << ")";
  }
  const Vector u = Vector::LinSpaced(A.rows(), -1.0, 1.0);
  Vector u_whole(A.rows());
  for (Index i = 0; i < A.rows(); ++i) u_whole(w(i)) = u(i);
  const Vector Au_whole = whole.problem.A * u_whole;
  Vector Au(A.rows());
  for (Index i = 0; i < A.rows(); ++i) Au(i) = Au_whole(w(i));
  // On a rank's part of the mesh a solution holds the part's unknowns only (its own, and those
  // of the part's other nodes, increasing), as the distributed solve returns it.
  Vector u_held = u;
  if (part.problem.part_solution()) {
    const std::vector<Index>& unknowns = part.problem.solution_unknowns;
    ASSERT_TRUE(std::is_sorted(unknowns.begin(), unknowns.end()));
    u_held.resize(static_cast<Index>(unknowns.size()));
    for (std::size_t k = 0; k < unknowns.size(); ++k)
      u_held(static_cast<Index>(k)) = u(unknowns[k]);
    for (Index i = lo; i < hi; ++i) ASSERT_GE(part.problem.solution_index(i), 0) << i;
  }
  // Each rank holds its rows of A u, of b and of the near-null space (none here: the direct
  // solver), and the sums over the unknowns add up over the ranks.
  EXPECT_EQ(part.problem.first_row(), lo);
  EXPECT_EQ(part.problem.end_row(), hi);
  EXPECT_LT(relative_difference(held_stiffness_rows(part.problem, u_held), Au.segment(lo, hi - lo)),
            1e-14);
  EXPECT_EQ(part.problem.held_rows(u_held), u.segment(lo, hi - lo));
  // N u and ||u||_inf, each row from the rank that owns it, summed.
  EXPECT_LT(relative_difference(contact_rows(part.problem, u_held), part.problem.contact.N * u),
            1e-14);
  EXPECT_EQ(largest_displacement(part.problem, u_held), 1.0);
  ASSERT_EQ(part.problem.b.size(), hi - lo);
  for (Index i = lo; i < hi; ++i)
    EXPECT_EQ(part.problem.b(i - lo), whole.problem.b(w(i))) << "row " << i;
  EXPECT_NEAR(load_norm(part.problem), whole.problem.b.norm(), 1e-14 * whole.problem.b.norm());
  const double energy = 0.5 * u_whole.dot(Au_whole) - whole.problem.b.dot(u_whole);
  EXPECT_NEAR(quadratic_energy(part.problem, u_held), energy, 1e-12 * std::abs(energy));
  EXPECT_NEAR(automatic_r(part.problem, 10.0), automatic_r(whole.problem, 10.0),
              1e-12 * automatic_r(whole.problem, 10.0));
  // A partitioned problem is the distributed path's only.
  ContactSolverOptions serial;
  serial.distributed = DistributedMode::Off;
  if (engine.size() == 1) {
    EXPECT_THROW((void)solve_contact(part.problem, serial), InputError);
  }
}

// The paper's problem with the direct solver: MUMPS's distributed Cholesky factorisation,
// against the serial condensed path.
TEST(DistributedUzawaGnm, PaperProblemWithMumpsMatchesTheSerialSolve) {
  const ProblemSpec spec = paper_benchmark(60, 20);
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-10;
  const ContactResult distributed = testing::distributed_solve(testing::distributed_model(spec), o);
  const ContactResult serial = testing::serial_solve(testing::serial_model(spec), o);
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

int cg_iterations(const ContactResult& r) {
  int cg = 0;
  for (const OuterStepRecord& s : r.summary.steps) cg += s.linear_iterations;
  return cg;
}

ProblemSpec ball_with_multigrid(Index n) {
  ProblemSpec spec = testing::ball_on_block(n, 6e-3);
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  spec.solver.uzawa_tolerance = 1e-10;
  return spec;
}

// A 3D block on a rigid ball with CG and GAMG on the rigid-body modes (build_model gives them
// for the distributed path), against the serial CG with smoothed aggregation.
TEST(DistributedUzawaGnm, BallOnBlockWithGamgMatchesTheSerialSolve) {
  ProblemSpec spec = ball_with_multigrid(8);
  spec.solver.petsc_multigrid = PetscMultigrid::Gamg;
  const Model model = testing::distributed_model(spec);
  ASSERT_EQ(model.problem.near_null_space.cols(), 6);
  ASSERT_EQ(model.problem.near_null_space.rows(),
            model.problem.end_row() - model.problem.first_row());  // this rank's rows
  // The node of each of this rank's unknowns, for PETSc's node blocks (on more than one rank
  // the rank's own unknowns' only).
  ASSERT_EQ(static_cast<Index>(model.problem.node_of_unknown.size()),
            model.is_part() ? model.problem.end_row() - model.problem.first_row()
                            : model.problem.A.rows());
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  const ContactResult serial = testing::serial_solve(serial_model, serial_model.solver);
  expect_same_solve(distributed, serial);
  EXPECT_NE(distributed.summary.device.find("PC mg (GAMG's levels, kept"), std::string::npos)
      << distributed.summary.device;
  EXPECT_NE(distributed.summary.device.find("6 rigid-body modes"), std::string::npos);
  EXPECT_GT(cg_iterations(distributed), 0);
}

// Inexact Uzawa-GNM ends with the active-set finish (docs/solvers.md) on PETSc's vectors as the
// serial backend path ends with it on its own: the same steps and the same answer, with the
// tighter KKT residuals of the finish's projected CG.
TEST(DistributedUzawaGnm, ActiveSetFinishMatchesTheSerialOne) {
  ProblemSpec spec = ball_with_multigrid(8);
  spec.solver.inner_tolerance = InnerTolerance::Adaptive;
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  const ContactResult serial = testing::serial_solve(serial_model, serial_model.solver);
  expect_same_solve(distributed, serial);
  EXPECT_TRUE(distributed.summary.active_set_finish) << distributed.summary.message;
  EXPECT_TRUE(serial.summary.active_set_finish) << serial.summary.message;
  EXPECT_LT(distributed.summary.kkt.max(), 1e-11);
}

// A problem that every rank holds whole (a library caller's, not partitioned by build_model):
// each rank takes its rows of A, b and the rigid-body modes from it, and the answers are the
// serial ones, with GAMG and with MUMPS's semismooth Newton.
TEST(DistributedUzawaGnm, AWholeProblemGivesTheSerialAnswersToo) {
  Model whole = testing::serial_model(ball_with_multigrid(6));
  ASSERT_FALSE(whole.problem.partitioned());
  whole.problem.near_null_space = rigid_body_modes(whole.mesh, whole.dofs);
  whole.problem.node_of_unknown = free_dof_nodes(whole.dofs);
  whole.problem.engine = &testing::mpi_engine();  // (solved on the ranks too)
  expect_same_solve(testing::distributed_solve(whole, whole.solver),
                    testing::serial_solve(whole, whole.solver));
  ContactSolverOptions ssn = whole.solver;
  ssn.method = ContactMethod::SemismoothNewton;
  ssn.linear.type = LinearSolverType::Cholmod;
  testing::expect_distributed_agrees(testing::distributed_solve(whole, ssn),
                                     testing::serial_solve(whole, ssn));
}

// GAMG's levels kept, with the contact term N_l^T diag(c) N_l on each, precondition as well as
// GAMG set up again for each active set (-pc_type gamg among the PETSc options): no more CG
// iterations than 1.2 times as many. (One GAMG set-up for all active sets, without the contact
// terms on the coarse levels, -ksp_reuse_preconditioner, took 78 CG iterations against 48 on
// a box of 40 x 40 x 20 hex8 cells.)
TEST(DistributedUzawaGnm, KeptGamgLevelsPreconditionAsWellAsGamgSetUpAgain) {
  const ProblemSpec spec = ball_with_multigrid(10);
  const Model model = testing::distributed_model(spec);
  const ContactResult kept = testing::distributed_solve(model, model.solver);
  ContactSolverOptions again = model.solver;
  again.petsc_options = "-pc_type gamg";
  const ContactResult full = testing::distributed_solve(model, again);
  ASSERT_EQ(PetscOptionsClearValue(nullptr, "-pc_type"), 0);  // the process's options database
  EXPECT_NE(full.summary.device.find("PC gamg"), std::string::npos) << full.summary.device;
  EXPECT_NEAR(kept.summary.energy, full.summary.energy, 1e-10 * std::abs(full.summary.energy));
  EXPECT_EQ(kept.summary.outer_iterations, full.summary.outer_iterations);
  EXPECT_LE(cg_iterations(kept), 1.2 * cg_iterations(full))
      << cg_iterations(kept) << " against " << cg_iterations(full);
}

// GAMG of one level (-pc_mg_levels 1): the kept "levels" are the
// smoother alone, and CG still converges to the serial answer.
// (Both multigrids: -pc_mg_levels caps our own levels as it caps GAMG's.)
TEST(DistributedUzawaGnm, GamgOfOneLevelStillSolves) {
  for (const PetscMultigrid levels : {PetscMultigrid::Gamg, PetscMultigrid::Aggregation}) {
    SCOPED_TRACE(enum_to_string(kPetscMultigridNames, levels));
    const ProblemSpec spec = ball_with_multigrid(4);
    const Model model = testing::distributed_model(spec);
    ContactSolverOptions o = model.solver;
    o.petsc_multigrid = levels;
    o.petsc_options = "-pc_mg_levels 1";
    const ContactResult distributed = testing::distributed_solve(model, o);
    ASSERT_EQ(PetscOptionsClearValue(nullptr, "-pc_mg_levels"), 0);
    const std::string& device = distributed.summary.device;
    const std::size_t at = device.find("levels of ");
    ASSERT_NE(at, std::string::npos) << device;
    EXPECT_EQ(device.find(',', at), std::string::npos) << "one level expected: " << device;
    const Model serial_model = testing::serial_model(spec);
    ContactSolverOptions direct = serial_model.solver;
    direct.linear.type = LinearSolverType::Cholmod;
    expect_same_solve(distributed, testing::serial_solve(serial_model, direct));
  }
}

// Hertz's ball on rollers: its nodes on the symmetry planes have one or two free unknowns, so
// the PETSc path pads them to whole blocks (node_padding.hpp) before GAMG; the answer is the
// serial one.
TEST(DistributedUzawaGnm, BallOnRollersWithPaddedBlocksMatchesTheSerialSolve) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Fixed;
  spec.solver.uzawa_tolerance = 1e-10;
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  expect_same_solve(distributed, testing::serial_solve(serial_model, serial_model.solver));
  // The levels count slots: more than the free unknowns, by the padding.
  const std::size_t at = distributed.summary.device.find("levels of ");
  ASSERT_NE(at, std::string::npos) << distributed.summary.device;
  const long slots = std::stol(distributed.summary.device.substr(at + 10));
  EXPECT_GT(slots, model.problem.A.rows());
  EXPECT_EQ(slots % 3, 0);
}

// solver.petsc_multigrid = "auto" (the default): the serial tool's own levels on one rank, where
// they are the serial path's hierarchy, and GAMG's on several, where its aggregates cross the
// ranks' borders.
TEST(DistributedUzawaGnm, DefaultMultigridIsTheSerialLevelsOnOneRankAndGamgOnSeveral) {
  EXPECT_EQ(resolved_petsc_multigrid(PetscMultigrid::Auto, 1), PetscMultigrid::Aggregation);
  EXPECT_EQ(resolved_petsc_multigrid(PetscMultigrid::Auto, 2), PetscMultigrid::Gamg);
  EXPECT_EQ(resolved_petsc_multigrid(PetscMultigrid::Hypre, 1), PetscMultigrid::Hypre);
  EXPECT_EQ(resolved_petsc_multigrid(PetscMultigrid::Gamg, 1), PetscMultigrid::Gamg);
  const ProblemSpec spec = ball_with_multigrid(8);
  ASSERT_EQ(spec.solver.petsc_multigrid, PetscMultigrid::Auto);
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  expect_same_solve(distributed, testing::serial_solve(serial_model, serial_model.solver));
  const char* expected = testing::mpi_engine().size() == 1
                             ? "smoothed aggregation on each rank's nodes"
                             : "PC mg (GAMG's levels, kept";
  EXPECT_NE(distributed.summary.device.find(expected), std::string::npos)
      << distributed.summary.device;
  // On one rank A and H are products on the serial tool's upper node blocks.
  EXPECT_EQ(distributed.summary.device.find("A and H in upper node blocks") != std::string::npos,
            testing::mpi_engine().size() == 1)
      << distributed.summary.device;
}

// signorini's own smoothed aggregation on each rank's nodes (solver.petsc_multigrid =
// "aggregation", petsc/aggregation_levels.hpp): the serial answers, on the block and on
// Hertz's ball on rollers (padded node blocks), in no more CG iterations than GAMG's kept
// levels take. (The serial tool's count is no measure here: on meshes this small its coarsest
// level is the whole problem, solved densely.)
TEST(DistributedUzawaGnm, OwnAggregationLevelsMatchTheSerialSolve) {
  for (const bool rollers : {false, true}) {
    ProblemSpec spec =
        rollers ? testing::hertz_ball("hertz_sphere_coarse.msh") : ball_with_multigrid(8);
    spec.solver.automatic_path = false;
    spec.solver.linear.type = LinearSolverType::ConjugateGradient;
    spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
    spec.solver.inner_tolerance = InnerTolerance::Fixed;
    spec.solver.uzawa_tolerance = 1e-10;
    spec.solver.petsc_multigrid = PetscMultigrid::Aggregation;
    const Model model = testing::distributed_model(spec);
    const ContactResult distributed = testing::distributed_solve(model, model.solver);
    const Model serial_model = testing::serial_model(spec);
    const ContactResult serial = testing::serial_solve(serial_model, serial_model.solver);
    expect_same_solve(distributed, serial);
    EXPECT_NE(distributed.summary.device.find("smoothed aggregation on each rank's nodes"),
              std::string::npos)
        << distributed.summary.device;
    ContactSolverOptions gamg = model.solver;
    gamg.petsc_multigrid = PetscMultigrid::Gamg;
    const ContactResult with_gamg = testing::distributed_solve(model, gamg);
    EXPECT_LE(cg_iterations(distributed), cg_iterations(with_gamg))
        << cg_iterations(distributed) << " against GAMG's " << cg_iterations(with_gamg);
  }
}

// The same on the paper's problem in 2D (three rigid-body modes, node blocks of 2).
TEST(DistributedUzawaGnm, PaperProblemWithOwnAggregationMatchesTheSerialSolve) {
  const ProblemSpec spec = paper_benchmark(60, 20);
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-10;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  o.linear.cg_tolerance = 1e-13;
  o.petsc_multigrid = PetscMultigrid::Aggregation;
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, o);
  expect_same_solve(distributed, testing::serial_solve(testing::serial_model(spec), o));
  EXPECT_NE(distributed.summary.device.find("smoothed aggregation"), std::string::npos)
      << distributed.summary.device;
}

// CG with hypre's BoomerAMG (solver.petsc_multigrid = "hypre") on the same 3D problem.
TEST(DistributedUzawaGnm, BallOnBlockWithHypreMatchesTheSerialSolve) {
  ProblemSpec spec = ball_with_multigrid(6);
  spec.solver.petsc_multigrid = PetscMultigrid::Hypre;
  const Model model = testing::distributed_model(spec);
  const ContactResult distributed = testing::distributed_solve(model, model.solver);
  const Model serial_model = testing::serial_model(spec);
  ContactSolverOptions direct = serial_model.solver;
  direct.linear.type = LinearSolverType::Cholmod;
  expect_same_solve(distributed, testing::serial_solve(serial_model, direct));
  EXPECT_NE(distributed.summary.device.find("PC hypre"), std::string::npos)
      << distributed.summary.device;
}

// CG with Jacobi, the paper's own configuration, on the paper's problem.
TEST(DistributedUzawaGnm, PaperProblemWithJacobiMatchesTheSerialSolve) {
  const ProblemSpec spec = paper_benchmark(30, 10);
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-10;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.cg_tolerance = 1e-13;
  expect_same_solve(testing::distributed_solve(testing::distributed_model(spec), o),
                    testing::serial_solve(testing::serial_model(spec), o));
}

// Classical Uzawa, the paper's baseline: step (i) by the engine's solves with no node active
// (MUMPS's one factorisation of A, as the serial path's one CHOLMOD factor), step (ii) on every
// rank alike. The step rho from 30 Lanczos steps on N A^-1 N^T, each a distributed solve, equals
// the serial one; so do the answers and the number of steps.
// (A coarse mesh: the method takes over a thousand steps, each a collective solve.)
TEST(DistributedUzawaGnm, ClassicalUzawaMatchesTheSerialSolve) {
  const ProblemSpec spec = paper_benchmark(12, 4);
  ContactSolverOptions o;
  o.method = ContactMethod::ClassicalUzawa;
  o.uzawa_tolerance = 1e-9;
  const ContactResult distributed = testing::distributed_solve(testing::distributed_model(spec), o);
  const ContactResult serial = testing::serial_solve(testing::serial_model(spec), o);
  expect_same_solve(distributed, serial);
  EXPECT_GT(serial.summary.outer_iterations, 10);
  EXPECT_GT(serial.summary.classical_step, 0.0);
  EXPECT_NEAR(distributed.summary.classical_step, serial.summary.classical_step,
              1e-9 * serial.summary.classical_step);
  EXPECT_NE(distributed.summary.device.find("MUMPS"), std::string::npos)
      << distributed.summary.device;
  // With a given step and CG with multigrid instead: the same steps again.
  o.classical_step = serial.summary.classical_step;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  o.linear.cg_tolerance = 1e-13;
  const ContactResult with_cg = testing::distributed_solve(testing::distributed_model(spec), o);
  testing::expect_distributed_agrees(with_cg, serial);
  EXPECT_EQ(with_cg.summary.outer_iterations, serial.summary.outer_iterations);
}

TEST(DistributedUzawaGnm, PetscOptionsReachTheSolver) {
  ContactSolverOptions o;
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.petsc_options = "-pc_type none";
  const ContactResult r =
      testing::distributed_solve(testing::distributed_model(paper_benchmark(30, 10)), o);
  // PETSc's options database is the process's: the next tests must not see this one.
  ASSERT_EQ(PetscOptionsClearValue(nullptr, "-pc_type"), 0);
  EXPECT_NE(r.summary.device.find("PC none"), std::string::npos) << r.summary.device;
  EXPECT_TRUE(r.summary.converged()) << r.summary.message;
}

}  // namespace
}  // namespace signorini

// The results of a distributed run from the ranks' parts of the mesh (docs/distributed.md, "The
// mesh in parts"), on 1, 2 and 4 ranks: each rank accounts for its nodes and cells once, and the
// resultants and the contact nodes' values that the ranks give together are the serial run's.

#include <gtest/gtest.h>

#include "../problem/hertz_ball.hpp"
#include "../test_problems.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/problem/contact_node_values.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini {
namespace {

// The raw solves (the problem's own numbering), distributed and serial.
ContactResult solve_distributed(const Model& model) {
  ContactSolverOptions o = model.solver;
  o.distributed = DistributedMode::Petsc;
  return solve_contact(model.problem, o);
}

ContactResult solve_serial(const Model& model) {
  ContactSolverOptions o = model.solver;
  o.distributed = DistributedMode::Auto;
  return solve_contact(testing::without_engine(model.problem), o, &model.multigrid);
}

void expect_close(const Eigen::Vector3d& a, const Eigen::Vector3d& b, double scale,
                  const std::string& what) {
  EXPECT_LE((a - b).norm(), 1e-8 * scale)
      << what << ": " << a.transpose() << " against " << b.transpose();
}

void expect_serial_results(const ProblemSpec& spec) {
  const Model part = testing::distributed_model(spec);
  const Model whole = testing::serial_model(spec);
  const DistributedEngine& engine = testing::mpi_engine();
  EXPECT_EQ(part.is_part(), engine.size() > 1);
  EXPECT_EQ(part.num_dofs(), whole.dofs.num_dofs());

  // Every node and every cell of the whole mesh is accounted for by one rank, which has it.
  testing::expect_every_node_and_cell_once(part, whole);

  const ContactResult distributed = solve_distributed(part);
  const ContactResult serial = solve_serial(whole);
  ASSERT_TRUE(distributed.summary.converged()) << distributed.summary.message;
  ASSERT_TRUE(serial.summary.converged()) << serial.summary.message;

  const Resultants a = compute_resultants(part, distributed);
  const Resultants b = compute_resultants(whole, serial);
  const double scale = b.applied.norm() + b.contact.norm();
  ASSERT_GT(scale, 0.0);
  expect_close(a.reference, b.reference, 1.0, "reference point");
  expect_close(a.applied, b.applied, scale, "applied load");
  expect_close(a.contact, b.contact, scale, "contact force");
  ASSERT_EQ(a.reactions.size(), b.reactions.size());
  for (std::size_t i = 0; i < a.reactions.size(); ++i) {
    EXPECT_EQ(a.reactions[i].boundary, b.reactions[i].boundary);
    expect_close(a.reactions[i].force, b.reactions[i].force, scale,
                 "reaction of " + b.reactions[i].boundary);
    expect_close(a.reactions[i].moment, b.reactions[i].moment, scale,
                 "moment of " + b.reactions[i].boundary);
  }
  EXPECT_LT(a.relative_balance, 1e-8);
  EXPECT_NEAR(a.relative_moment_balance, b.relative_moment_balance, 1e-8);

  // The contact set is in the same order in both models.
  const ContactNodeValues p = contact_node_values(part, distributed);
  const ContactNodeValues q = contact_node_values(whole, serial);
  ASSERT_EQ(p.points.cols(), q.points.cols());
  EXPECT_EQ(p.points, q.points);
  EXPECT_EQ(p.prescribed, q.prescribed);
  EXPECT_LE((p.displacement - q.displacement).norm(), 1e-8 * q.displacement.norm());
}

// Hertz's ball on rollers, pressed by a prescribed displacement: nodes with one or two free
// unknowns, a reaction on every symmetry plane, and nodes in contact on several ranks.
TEST(DistributedResults, BallOnRollersGivesTheSerialResultantsAndContactValues) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.solver.automatic_path = false;
  spec.solver.uzawa_tolerance = 1e-10;
  expect_serial_results(spec);
}

// The paper's strip: a clamped edge (nodes without a free unknown, which rank 0 accounts for)
// and a traction.
TEST(DistributedResults, PaperStripGivesTheSerialResultantsAndContactValues) {
  ProblemSpec spec = paper_benchmark(60, 20);
  spec.solver.uzawa_tolerance = 1e-10;
  expect_serial_results(spec);
}

}  // namespace
}  // namespace signorini

#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <vector>
// The models of the MPI tests (tests/petsc/): each problem built twice on every rank, as the
// distributed path builds it (partitioned: each rank its part of A, docs/distributed.md) and as
// a serial run does (the engine out of sight while it is built and solved), so that the
// distributed solve can be checked against the serial one on the same rank.

#include <gtest/gtest.h>

#include "../test_problems.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/distributed_engine.hpp"
#include "signorini/core/error.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::testing {

/// The engine of the test program's ranks (mpi_test_main.cpp).
DistributedEngine& mpi_engine();

/// The model as the distributed path builds it: partitioned over the ranks.
inline Model distributed_model(ProblemSpec spec) {
  spec.solver.distributed = DistributedMode::Petsc;
  return build_model(spec, &mpi_engine());
}

/// The model as a serial run builds it (no engine: this rank alone).
inline Model serial_model(ProblemSpec spec) {
  spec.solver.distributed = DistributedMode::Auto;
  return build_model(spec);
}

/// `model`'s problem without its engine: a serial solve on this rank alone.
inline ContactProblem without_engine(const ContactProblem& problem) {
  ContactProblem serial = problem;
  serial.engine = nullptr;
  return serial;
}

/// A serial solve on this rank alone. Its u is the mesh's whole displacement
/// (DofMap::expand): the distributed path numbers the unknowns rank by rank (the partition), the
/// serial one in another order, and the two compare node by node.
inline ContactResult serial_solve(const Model& model, ContactSolverOptions o) {
  o.distributed = DistributedMode::Auto;
  ContactResult r = solve_contact(without_engine(model.problem), o, &model.multigrid);
  r.u = model.dofs.expand(r.u);
  return r;
}

/// ||a - b|| / ||b|| over the entries that a knows (not NaN: a rank's part of the mesh,
/// distributed_solve), and at least one.
inline double relative_difference_where_known(const Vector& a, const Vector& b) {
  double difference = 0.0, size = 0.0;
  Index known = 0;
  for (Index i = 0; i < a.size(); ++i) {
    if (std::isnan(a(i))) continue;
    ++known;
    difference += (a(i) - b(i)) * (a(i) - b(i));
    size += b(i) * b(i);
  }
  if (known == 0 || a.size() != b.size()) return std::numeric_limits<double>::infinity();
  return size > 0.0 ? std::sqrt(difference / size) : std::sqrt(difference);
}

/// What every distributed solve must share with the serial one (the distributed issue's
/// check): both converged, the distributed path on all the ranks, u and l to 1e-8, small KKT
/// residuals. The callers compare the steps as their method defines them.
inline void expect_distributed_agrees(const ContactResult& distributed,
                                      const ContactResult& serial) {
  ASSERT_TRUE(distributed.summary.converged()) << distributed.summary.message;
  ASSERT_TRUE(serial.summary.converged()) << serial.summary.message;
  EXPECT_EQ(distributed.summary.path, SolvePath::Distributed);
  EXPECT_EQ(distributed.summary.ranks, mpi_engine().size());
  EXPECT_LT(relative_difference_where_known(distributed.u, serial.u), 1e-8);
  EXPECT_LT(relative_difference(distributed.l, serial.l), 1e-8);
  EXPECT_LT(distributed.summary.kkt.max(), 1e-8);
}

/// The distributed solve; u the mesh's whole displacement, as serial_solve's. A rank that holds
/// a part of the mesh (Model::is_part) knows it at its part's nodes only: NaN elsewhere (its
/// solution holds the part's unknowns only, ContactProblem::solution_unknowns, which
/// Model::full_displacement expands).
inline ContactResult distributed_solve(const Model& model, ContactSolverOptions o) {
  o.distributed = DistributedMode::Petsc;
  ContactResult r = solve_contact(model.problem, o);
  if (model.is_part()) {
    EXPECT_TRUE(model.problem.part_solution());
    EXPECT_EQ(r.u.size(), static_cast<Index>(model.problem.solution_unknowns.size()));
  }
  const Vector held = model.full_displacement(r);
  if (!model.is_part()) {
    r.u = held;
    return r;
  }
  const int dim = model.dofs.dim();
  r.u = Vector::Constant(model.whole.nodes * dim, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t i = 0; i < model.global_nodes.size(); ++i)
    r.u.segment(model.global_nodes[i] * dim, dim) = held.segment(static_cast<Index>(i) * dim, dim);
  return r;
}

/// Every node and every cell of the whole mesh accounted for by exactly one rank (Model::
/// node_rank, cell_rank), which has it in its part (a collective call).
inline void expect_every_node_and_cell_once(const Model& part, const Model& whole) {
  const DistributedEngine& engine = mpi_engine();
  double counts[2] = {0.0, 0.0};
  for (Index v = 0; v < part.mesh.num_nodes(); ++v)
    if (part.node_rank(v) == engine.rank()) counts[0] += 1.0;
  for (Index c = 0; c < part.mesh.num_cells(); ++c)
    if (part.cell_rank(c) == engine.rank()) counts[1] += 1.0;
  engine.sum(counts, 2);
  EXPECT_EQ(counts[0], static_cast<double>(whole.mesh.num_nodes()));
  EXPECT_EQ(counts[1], static_cast<double>(whole.mesh.num_cells()));
}

/// Building the model of `spec` throws InputError on every rank, with the same message on all,
/// which holds `expected`.
inline void expect_one_message_on_every_rank(const ProblemSpec& spec, const std::string& expected) {
  std::string message;
  try {
    (void)distributed_model(spec);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find(expected), std::string::npos) << message;
  const std::vector<std::vector<char>> all =
      mpi_engine().allgather(std::vector<char>(message.begin(), message.end()));
  for (const std::vector<char>& m : all) EXPECT_EQ(std::string(m.begin(), m.end()), message);
}

}  // namespace signorini::testing

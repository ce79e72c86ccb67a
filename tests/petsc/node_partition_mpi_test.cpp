// The partition of the mesh's nodes among the ranks (src/signorini/parallel/node_partition.hpp,
// docs/distributed.md, "The partition"), by PETSc's graph partitioner.

#include <gtest/gtest.h>
#include <mpi.h>
#include <petscsys.h>

#include <algorithm>
#include <string>

#include "../problem/hertz_ball.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/parallel/node_partition.hpp"

namespace signorini {
namespace {

// The coarse mesh of Hertz's ball: an unstructured gmsh mesh, its unknowns numbered along the
// Z-order curve, with rollers.
ProblemSpec hertz_ball() {
  return testing::hertz_ball("hertz_sphere_coarse.msh");
}

Index sum_over_ranks(Index value) {
  long long v = value;
  MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_LONG_LONG, MPI_SUM, MPI_COMM_WORLD);
  return static_cast<Index>(v);
}

TEST(NodePartition, BalancesTheUnknownsAndCutsLessThanTheNumbering) {
  const ProblemSpec spec = hertz_ball();
  const Model serial = testing::serial_model(spec);
  DistributedEngine& engine = testing::mpi_engine();
  const int ranks = engine.size();
  const NodeGraph graph = node_graph(serial.mesh, serial.dofs, engine.rank(), ranks);
  ASSERT_GT(graph.vertices, 100);
  const std::vector<int> owner = engine.partition(graph, spec.solver.petsc_options);
  ASSERT_EQ(owner.size(), static_cast<std::size_t>(graph.vertices));
  std::vector<Index> unknowns(static_cast<std::size_t>(ranks), 0);
  for (Index v = 0; v < graph.vertices; ++v) {
    const int r = owner[static_cast<std::size_t>(v)];
    ASSERT_GE(r, 0);
    ASSERT_LT(r, ranks);
    const Index node = graph.node[static_cast<std::size_t>(v)];
    for (int k = 0; k < serial.dofs.dim(); ++k)
      unknowns[static_cast<std::size_t>(r)] += serial.dofs.free_index(node, k) >= 0 ? 1 : 0;
  }
  const auto [fewest, most] = std::minmax_element(unknowns.begin(), unknowns.end());
  EXPECT_GT(*fewest, 0);
  EXPECT_LE(static_cast<double>(*most), 1.1 * static_cast<double>(serial.dofs.num_free()) / ranks)
      << "the most unknowns on one rank";
  // Against the even split of the Z-order numbering (what the ranks owned before the partition).
  std::vector<int> split(owner.size());
  for (int r = 0; r < ranks; ++r)
    for (Index v = vertex_share_start(graph.vertices, r, ranks);
         v < vertex_share_start(graph.vertices, r + 1, ranks); ++v)
      split[static_cast<std::size_t>(v)] = r;
  const Index cut = sum_over_ranks(cut_edges(graph, owner));
  const Index split_cut = sum_over_ranks(cut_edges(graph, split));
  if (ranks == 1) {
    EXPECT_EQ(cut, 0);
  }
  EXPECT_LE(cut, split_cut) << "edges cut: " << cut << " by the partitioner, " << split_cut
                            << " by the numbering's even split";
  if (engine.rank() == 0 && ranks > 1)
    std::printf("[ partition ] %d ranks: %lld edges cut, %lld by the even split of the numbering\n",
                ranks, static_cast<long long>(cut), static_cast<long long>(split_cut));

  // The distributed model numbers the unknowns rank by rank, from such a partition (PT-Scotch's
  // random choices go on from one call to the next in a process, so not this one; a run is the
  // same from one start to the next).
  const Model part = testing::distributed_model(spec);
  ASSERT_EQ(part.problem.row_starts.size(), static_cast<std::size_t>(ranks) + 1);
  EXPECT_EQ(part.problem.row_starts.back(), serial.dofs.num_free());
  for (int r = 0; r < ranks; ++r) {
    const Index own = part.problem.row_starts[static_cast<std::size_t>(r) + 1] -
                      part.problem.row_starts[static_cast<std::size_t>(r)];
    EXPECT_GT(own, 0) << "rank " << r;
    EXPECT_LE(static_cast<double>(own), 1.1 * static_cast<double>(serial.dofs.num_free()) / ranks)
        << "rank " << r;
  }
  if (ranks > 1) {
    EXPECT_NE(engine.description().find("nodes partitioned by ptscotch"), std::string::npos)
        << engine.description();
  }
}

// -mat_partitioning_type current: each rank keeps its share of the numbering, the even split.
TEST(NodePartition, CurrentKeepsTheNumberingsSplit) {
  const ProblemSpec spec = hertz_ball();
  const Model serial = testing::serial_model(spec);
  DistributedEngine& engine = testing::mpi_engine();
  const NodeGraph graph = node_graph(serial.mesh, serial.dofs, engine.rank(), engine.size());
  ContactSolverOptions o = spec.solver;
  o.petsc_options = "-mat_partitioning_type current";
  const std::vector<int> owner = engine.partition(graph, o.petsc_options);
  ASSERT_EQ(PetscOptionsClearValue(nullptr, "-mat_partitioning_type"), 0);
  for (int r = 0; r < engine.size(); ++r)
    for (Index v = vertex_share_start(graph.vertices, r, engine.size());
         v < vertex_share_start(graph.vertices, r + 1, engine.size()); ++v)
      EXPECT_EQ(owner[static_cast<std::size_t>(v)], r) << "vertex " << v;
}

}  // namespace
}  // namespace signorini

// A model made in parts (problem/model_in_parts.hpp, docs/distributed.md), on 1, 2 and 4 ranks:
// a generated box that each rank makes its block of (problem/box_model_in_parts.hpp), and a mesh
// from a file that rank 0 sends in parts of the mesh. No rank holds the whole model (nor, for
// the box, the whole mesh); each rank's part of the model is the whole model's, to the bit where
// the sums run in the same order (b, the contact set, the prescribed values), and the solve and
// its resultants are the serial run's; bad input found by one rank stops every rank with one
// message.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

#include "../problem/ball_on_block.hpp"
#include "../problem/hertz_ball.hpp"
#include "mpi_test_problems.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/contact_node_values.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini {
namespace {

// The box of examples/box_on_plane.toml, read from its text with the cell type given: rollers
// on two sides, a prescribed displacement on the top, an inclined plane below, and a traction
// on one side and a body force besides.
ProblemSpec rolled_box(const std::string& cell) {
  return parse_problem_string(R"(
[mesh]
type = "box"
length = 1.0
width = 1.0
height = 0.5
nx = 4
ny = 5
nz = 3
cell = ")" + cell + R"("
[material]
E = 1000.0
nu = 0.3
[[clamp]]
boundary = "xmin"
components = ["x"]
[[clamp]]
boundary = "ymin"
components = ["y"]
[[displacement]]
boundary = "zmax"
z = "-0.001 - 0.0005 * x"
[[traction]]
boundary = "xmax"
p = ["-0.1 * z", "0", "0"]
[body_force]
f = ["0", "0", "-0.2"]
[contact]
boundary = "zmin"
obstacle = "plane"
point = [0.0, 0.0, 0.0]
normal = [0.002, 0.0, 1.0]
[solver]
uzawa_tolerance = 1e-10
)",
                              "rolled_box.toml")
      .spec;
}

void expect_whole_model_in_parts(const ProblemSpec& spec, bool smaller = false) {
  const DistributedEngine& engine = testing::mpi_engine();
  const Model part = testing::distributed_model(spec);
  const Model whole = testing::serial_model(spec);
  if (engine.size() == 1) {
    EXPECT_FALSE(part.is_part());
    return;
  }
  // Made in parts: each rank its own, none of them whole.
  ASSERT_TRUE(part.is_part());
  ASSERT_EQ(static_cast<Index>(part.node_ranks.size()), part.mesh.num_nodes());
  // (A part is two layers of cells around the rank's nodes: on a small mesh that may be all.)
  if (smaller) {
    EXPECT_LT(part.mesh.num_cells(), whole.mesh.num_cells());
  }
  EXPECT_LE(part.mesh.num_cells(), whole.mesh.num_cells());
  EXPECT_EQ(part.whole.nodes, whole.mesh.num_nodes());
  EXPECT_EQ(part.dofs.num_free(), whole.dofs.num_free());

  const int dim = whole.mesh.dim();
  // Node for node, the numbering and the prescribed values of the whole; b on the rank's rows.
  const Index first = part.problem.first_row();
  Index own = 0;
  for (Index v = 0; v < part.mesh.num_nodes(); ++v) {
    const Index g = part.global_nodes[static_cast<std::size_t>(v)];
    EXPECT_EQ(part.mesh.node(v), whole.mesh.node(g));
    for (int k = 0; k < dim; ++k) {
      EXPECT_EQ(part.dofs.is_clamped(v, k), whole.dofs.is_clamped(g, k)) << g << " " << k;
      EXPECT_EQ(part.dofs.value(v, k), whole.dofs.value(g, k));
      const Index i = part.dofs.free_index(v, k);
      if (i < first || i >= part.problem.end_row()) continue;
      ++own;
      EXPECT_EQ(part.node_ranks[static_cast<std::size_t>(v)], engine.rank());
      EXPECT_EQ(part.problem.b(i - first), whole.problem.b(whole.dofs.free_index(g, k)))
          << "node " << g << " component " << k;
    }
  }
  EXPECT_EQ(own, part.problem.end_row() - first);

  // At the rank's nodes: the applied loads, and each load group's loads, prescribed dofs and
  // rows of b, to the bit; the point loads where the whole mesh places them.
  ASSERT_EQ(part.load_groups.size(), whole.load_groups.size());
  const auto held = [](const LoadGroup& g, Index size) {
    std::vector<bool> out(static_cast<std::size_t>(size), false);
    for (const Index d : g.prescribed_dofs) out[static_cast<std::size_t>(d)] = true;
    return out;
  };
  for (std::size_t gi = 0; gi < whole.load_groups.size(); ++gi) {
    const LoadGroup& pg = part.load_groups[gi];
    const LoadGroup& wg = whole.load_groups[gi];
    EXPECT_EQ(pg.entry, wg.entry);
    EXPECT_EQ(pg.factors, wg.factors);
    ASSERT_EQ(pg.loads.size() != 0, wg.loads.size() != 0) << wg.entry;
    const std::vector<bool> ph = held(pg, part.dofs.num_dofs());
    const std::vector<bool> wh = held(wg, whole.dofs.num_dofs());
    for (Index v = 0; v < part.mesh.num_nodes(); ++v) {
      if (part.node_ranks[static_cast<std::size_t>(v)] != engine.rank()) continue;
      const Index g = part.global_nodes[static_cast<std::size_t>(v)];
      for (int k = 0; k < dim; ++k) {
        EXPECT_EQ(ph[static_cast<std::size_t>(v * dim + k)],
                  wh[static_cast<std::size_t>(g * dim + k)]);
        if (wg.loads.size() != 0) {
          EXPECT_EQ(pg.loads(v * dim + k), wg.loads(g * dim + k));
        }
        if (const Index i = part.dofs.free_index(v, k); i >= 0) {
          EXPECT_EQ(pg.b(i - first), wg.b(whole.dofs.free_index(g, k))) << wg.entry;
        }
      }
    }
  }
  for (Index v = 0; v < part.mesh.num_nodes(); ++v) {
    if (part.node_ranks[static_cast<std::size_t>(v)] != engine.rank()) continue;
    const Index g = part.global_nodes[static_cast<std::size_t>(v)];
    for (int k = 0; k < dim; ++k) EXPECT_EQ(part.loads(v * dim + k), whole.loads(g * dim + k));
  }
  ASSERT_EQ(part.point_loads.size(), whole.point_loads.size());
  for (std::size_t i = 0; i < whole.point_loads.size(); ++i) {
    EXPECT_EQ(part.point_loads[i].node, whole.point_loads[i].node);
    EXPECT_EQ(part.point_loads[i].at, whole.point_loads[i].at);
    EXPECT_EQ(part.point_loads[i].distance, whole.point_loads[i].distance);
  }

  // The contact set whole on every rank, in the serial order, to the bit.
  const ContactSet& a = part.problem.contact;
  const ContactSet& b = whole.problem.contact;
  ASSERT_EQ(a.nodes, b.nodes);
  EXPECT_EQ(a.normals, b.normals);
  EXPECT_EQ(a.weights, b.weights);
  EXPECT_EQ(a.gaps, b.gaps);
  EXPECT_EQ(a.movable, b.movable);
  EXPECT_EQ(a.facets, b.facets);
  EXPECT_EQ(part.contact_starts, whole.contact_starts);
  EXPECT_EQ(part.contact_gap_shift, whole.contact_gap_shift);
  EXPECT_EQ(part.contact_gap_shift_group, whole.contact_gap_shift_group);
  // N's rows: the same entries at the same nodes' unknowns (numbered otherwise).
  for (Index j = 0; j < a.size(); ++j) {
    const Index g = b.nodes[static_cast<std::size_t>(j)];
    const Index v = part.local_node(g);
    for (int k = 0; k < dim; ++k) {
      const Index i = whole.dofs.free_index(g, k);
      const double expected = i < 0 ? 0.0 : b.N.coeff(j, i);
      if (v >= 0 && part.dofs.free_index(v, k) >= 0) {
        EXPECT_EQ(a.N.coeff(j, part.dofs.free_index(v, k)), expected);
      }
    }
  }
  EXPECT_EQ(a.N.nonZeros(), b.N.nonZeros());
  EXPECT_NEAR(
      part.whole.radius,
      [&] {
        double r = 0.0;
        const Eigen::VectorXd c = whole.mesh.coordinates().rowwise().mean();
        for (Index v = 0; v < whole.mesh.num_nodes(); ++v)
          r = std::max(r, (whole.mesh.node(v) - c).norm());
        return r;
      }(),
      1e-14)
      << "the largest distance from the centroid";

  // The solve and its resultants, summed over the parts, as the serial run's.
  ContactSolverOptions o = part.solver;
  o.distributed = DistributedMode::Petsc;
  const ContactResult distributed = solve_contact(part.problem, o);
  const ContactResult serial = testing::serial_solve(whole, whole.solver);
  ASSERT_TRUE(distributed.summary.converged()) << distributed.summary.message;
  ASSERT_TRUE(serial.summary.converged()) << serial.summary.message;
  EXPECT_EQ(distributed.summary.outer_iterations, serial.summary.outer_iterations);
  EXPECT_NEAR(distributed.summary.energy, serial.summary.energy,
              1e-10 * std::abs(serial.summary.energy));
  EXPECT_LE((distributed.l - serial.l).norm(), 1e-8 * serial.l.norm());
  ContactResult serial_raw = serial;
  serial_raw.u = whole.dofs.restrict_to_free(serial.u);
  const Resultants ra = compute_resultants(part, distributed);
  const Resultants rb = compute_resultants(whole, serial_raw);
  const double scale = rb.applied.norm() + rb.contact.norm();
  ASSERT_GT(scale, 0.0);
  EXPECT_LE((ra.applied - rb.applied).norm(), 1e-8 * scale);
  EXPECT_LE((ra.contact - rb.contact).norm(), 1e-8 * scale);
  ASSERT_EQ(ra.reactions.size(), rb.reactions.size());
  for (std::size_t i = 0; i < ra.reactions.size(); ++i) {
    EXPECT_EQ(ra.reactions[i].boundary, rb.reactions[i].boundary);
    EXPECT_LE((ra.reactions[i].force - rb.reactions[i].force).norm(), 1e-8 * scale)
        << rb.reactions[i].boundary << ": " << ra.reactions[i].force.transpose() << " against "
        << rb.reactions[i].force.transpose();
  }
  EXPECT_LT(ra.relative_balance, 1e-8);
  const ContactNodeValues p = contact_node_values(part, distributed);
  const ContactNodeValues q = contact_node_values(whole, serial_raw);
  EXPECT_EQ(p.points, q.points);
  EXPECT_EQ(p.prescribed, q.prescribed);
  EXPECT_LE((p.displacement - q.displacement).norm(), 1e-8 * q.displacement.norm());

  // Every node and every cell accounted for by one rank.
  testing::expect_every_node_and_cell_once(part, whole);
}

TEST(BoxInParts, RolledHex27BoxIsTheWholeModelInParts) {
  expect_whole_model_in_parts(rolled_box("hex27"));
}

TEST(BoxInParts, RolledTet10BoxIsTheWholeModelInParts) {
  expect_whole_model_in_parts(rolled_box("tet10"));
}

TEST(BoxInParts, ClampedBlockOnABallIsTheWholeModelInParts) {
  ProblemSpec spec = testing::ball_on_block(8, 6e-3, CellType::Tet4);
  spec.solver.uzawa_tolerance = 1e-10;
  expect_whole_model_in_parts(spec, /*smaller=*/true);
}

// Point loads (one on a side, one anywhere) and entries with load factors of their own (a
// traction, the prescribed displacement, a point load): each placed at the whole box's nearest
// node, each group's loads and b the whole model's.
TEST(BoxInParts, PointLoadsAndLoadGroupsAreTheWholeModelsInParts) {
  ProblemSpec spec = rolled_box("hex8");
  spec.load_factors = {0.5, 1.0};
  spec.tractions[0].factors = {0.0, 1.0};
  spec.displacements[0].factors = {1.0, 1.0};
  PointLoadSpec side;
  side.at = Point(1.0, 0.52, 0.26);
  side.force = Eigen::Vector3d(-0.01, 0.002, 0.0);
  side.boundary = "xmax";
  side.factors = {1.0, 0.5};
  PointLoadSpec anywhere;
  anywhere.at = Point(0.3, 0.7, 0.2);
  anywhere.force = Eigen::Vector3d(0.0, 0.0, -0.02);
  spec.point_loads = {side, anywhere};
  expect_whole_model_in_parts(spec);
}

// solver.partition = "graph": rank 0 builds the model and PETSc's partitioner shares it.
TEST(BoxInParts, GraphPartitionIsKeptOnRequest) {
  ProblemSpec spec = rolled_box("hex8");
  spec.solver.partition = PartitionMode::Graph;
  const Model part = testing::distributed_model(spec);
  EXPECT_TRUE(part.node_ranks.empty());
  EXPECT_EQ(part.is_part(), testing::mpi_engine().size() > 1);
}

// A traction that is not finite on part of one side: the ranks whose parts have it find it,
// and every rank throws the same message.
TEST(BoxInParts, BadInputOnOneRankStopsEveryRankWithOneMessage) {
  ProblemSpec spec = rolled_box("hex8");
  spec.tractions[0].p = [](const Point& x) {
    Eigen::Vector3d t(0.0, 0.0, 0.0);
    if (x(1) > 0.7) t(0) = std::numeric_limits<double>::quiet_NaN();
    return t;
  };
  testing::expect_one_message_on_every_rank(spec, "traction on 'xmax'");
}

// A mesh from a file: rank 0 reads it and partitions its nodes, and sends each rank its part
// of the mesh; each rank builds its model from it. Hertz's ball: tetrahedra, rollers on the
// symmetry planes (the nodes of the axis have no free dof but z), a prescribed displacement
// (the gaps' shifts), and a curved contact side with the exact normal.
TEST(MeshInParts, HertzBallFromAFileIsTheWholeModelInParts) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.solver.uzawa_tolerance = 1e-10;
  expect_whole_model_in_parts(spec, /*smaller=*/true);
}

// In 2D, on quadratic triangles from a file, clamped on a side (nodes without a free dof).
TEST(MeshInParts, QuadraticCylinderFromAFileIsTheWholeModelInParts) {
  ProblemSpec spec = read_problem_file(SIGNORINI_EXAMPLES_DIR "/hertz_p2.toml").spec;
  spec.solver.uzawa_tolerance = 1e-10;
  expect_whole_model_in_parts(spec);
}

// A body force that is not finite in part of the ball: the ranks whose parts hold it find it,
// and every rank throws the same message.
TEST(MeshInParts, BadInputOnOneRankStopsEveryRankWithOneMessage) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.body_force = [](const Point& x) {
    Eigen::Vector3d f(0.0, 0.0, 0.0);
    if (x(0) > 0.6) f(2) = std::numeric_limits<double>::quiet_NaN();
    return f;
  };
  testing::expect_one_message_on_every_rank(spec, "is not finite");
}

// A pinned clamp (its node the whole mesh's nearest, which rank 0 numbers), a point load with
// load factors of its own, and the prescribed displacement with its own.
TEST(MeshInParts, PinnedClampAndLoadGroupsAreTheWholeModelsInParts) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.solver.uzawa_tolerance = 1e-10;
  ClampSpec pin;
  pin.boundary = "top";
  pin.components = {true, false, false};
  pin.at = Point(0.4, 0.3, 1.0);
  spec.clamps.push_back(pin);
  spec.load_factors = {0.5, 1.0};
  spec.displacements[0].factors = {0.5, 1.0};
  PointLoadSpec load;
  load.at = Point(0.3, 0.3, 0.5);
  load.force = Eigen::Vector3d(0.0, 0.0, -1e-6);
  load.factors = {1.0, 1.0};
  spec.point_loads = {load};
  expect_whole_model_in_parts(spec);
}

// Coulomb friction: the law per node and the tangential rows of N from the gathered rows, as
// the whole model has them (the solve with friction on the parts: distributed_friction_mpi_test).
TEST(MeshInParts, FrictionIsTheWholeModelsInParts) {
  ProblemSpec spec = testing::hertz_ball("hertz_sphere_coarse.msh");
  spec.contacts[0].friction = FrictionModel::Coulomb;
  spec.contacts[0].mu = 0.2;
  const Model part = testing::distributed_model(spec);
  const Model whole = testing::serial_model(spec);
  // (The parameters of the laws themselves: a test may ask which law it has.)
  const auto part_law = std::dynamic_pointer_cast<const FrictionLaw>(part.problem.law);
  const auto whole_law = std::dynamic_pointer_cast<const FrictionLaw>(whole.problem.law);
  ASSERT_TRUE(part_law && whole_law);
  EXPECT_EQ(part_law->mu(), whole_law->mu());
  EXPECT_EQ(part_law->slip_bound(), whole_law->slip_bound());
  const ContactSet& a = part.problem.contact;
  const ContactSet& b = whole.problem.contact;
  EXPECT_EQ(a.components, b.components);
  ASSERT_EQ(a.N.rows(), b.N.rows());
  EXPECT_EQ(a.N.nonZeros(), b.N.nonZeros());
  if (!part.is_part()) return;
  // Row by row, the same entries at the same nodes' unknowns (numbered otherwise).
  const int dim = 3;
  for (Index j = 0; j < a.size(); ++j) {
    const Index g = b.nodes[static_cast<std::size_t>(j)];
    const Index v = part.local_node(g);
    if (v < 0) continue;
    for (Index row = dim * j; row < dim * (j + 1); ++row)
      for (int k = 0; k < dim; ++k) {
        const Index i = whole.dofs.free_index(g, k);
        if (i < 0) continue;
        EXPECT_EQ(a.N.coeff(row, part.dofs.free_index(v, k)), b.N.coeff(row, i))
            << "row " << row << " component " << k;
      }
  }
}

// A block of quadratic triangles turned by 30 degrees (a mesh the program gives), held by
// normal displacements on its inclined sides: the nodes there have local axes (DofMap frames),
// which rank 0's numbering sends with each part; the top is in contact with a plane, its end
// nodes in local axes too (their N rows, the gaps' shifts), with friction (the tangents in them).
TEST(MeshInParts, NormalDisplacementsOnInclinedSidesAreTheWholeModelsInParts) {
  RectangleMeshOptions r;
  r.length = 2.0;
  r.height = 1.0;
  r.nx = 12;
  r.ny = 6;
  r.cell = CellType::Tri6;
  const Mesh flat = make_rectangle_mesh(r);
  const double angle = std::numbers::pi / 6.0, c = std::cos(angle), s = std::sin(angle);
  Eigen::MatrixXd x = flat.coordinates();
  for (Index v = 0; v < x.cols(); ++v) {
    const Eigen::Vector2d p = x.col(v);
    x.col(v) = Eigen::Vector2d(c * p(0) - s * p(1), s * p(0) + c * p(1));
  }
  std::vector<CellType> types;
  std::vector<Index> connectivity;
  for (Index cell = 0; cell < flat.num_cells(); ++cell) {
    types.push_back(flat.cell_type(cell));
    for (const Index v : flat.cell(cell)) connectivity.push_back(v);
  }
  auto turned = std::make_shared<Mesh>(std::move(types), std::move(x), std::move(connectivity));
  for (const std::string& name : flat.boundary_part_names())
    turned->set_boundary_part(name, flat.boundary_part(name).facets);
  ProblemSpec spec;
  spec.mesh_type = MeshType::Given;
  spec.given_mesh = turned;
  spec.elasticity.material = {1000.0, 0.3};
  for (const auto& [side, value] :
       {std::pair{"left", 0.0}, std::pair{"bottom", -0.001}, std::pair{"right", 0.001}}) {
    DisplacementSpec d;
    d.boundary = side;
    d.normal = [value = value](const Point&) { return value; };
    d.normal_text = std::to_string(value);
    spec.displacements.push_back(d);
  }
  ContactSpec top;
  top.boundary = "top";
  top.obstacle.shape = ObstacleShape::Plane;
  top.obstacle.point = Point(0.0, 1.0 / c + 0.0005, 0.0);  // (above the top's left end)
  top.obstacle.normal = Point(s, -c, 0.0);                 // (towards the block)
  top.friction = FrictionModel::Coulomb;
  top.mu = 0.3;
  spec.contacts = {top};
  spec.solver.uzawa_tolerance = 1e-10;
  const Model whole = testing::serial_model(spec);
  bool framed_contact_node = false;  // (the top's ends)
  for (const Index node : whole.problem.contact.nodes)
    framed_contact_node = framed_contact_node || whole.dofs.has_frame(node);
  EXPECT_TRUE(framed_contact_node);
  const ContactResult serial = testing::serial_solve(whole, whole.solver);
  ASSERT_TRUE(serial.summary.converged()) << serial.summary.message;
  EXPECT_GT(serial.l.maxCoeff(), 0.0) << "no contact";
  expect_whole_model_in_parts(spec);
}

}  // namespace
}  // namespace signorini

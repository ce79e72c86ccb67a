// A rank's part of a mesh (problem/model_part.hpp): its two layers of cells, its nodes with
// the whole numbering, the stiffness columns it assembles, and the bytes that carry them.

#include "signorini/problem/model_part.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

struct Whole {
  Mesh mesh;
  DofMap dofs;
  std::vector<bool> own;  // the nodes of the first half of the unknowns
  std::vector<Index> own_nodes;
};

// Tetrahedra held at the bottom and on a roller at x = 0, numbered in the reverse of the nodes'
// order, so that a part's node order (the mesh's) is not its numbering's.
Whole whole() {
  BoxMeshOptions box;
  box.nx = 3;
  box.ny = 2;
  box.nz = 8;
  box.cell = CellType::Tet4;
  Mesh mesh = make_box_mesh(box);
  std::vector<Index> order(static_cast<std::size_t>(mesh.num_nodes()));
  std::iota(order.rbegin(), order.rend(), Index{0});
  DofMap dofs = make_dof_map(
      mesh, {ClampSpec{"zmin", {true, true, true}}, ClampSpec{"xmin", {true, false, false}}}, {},
      order);
  std::vector<bool> own(static_cast<std::size_t>(mesh.num_nodes()), false);
  std::vector<Index> own_nodes;
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    for (int k = 0; k < 3; ++k)
      if (const Index f = dofs.free_index(v, k); f >= 0 && f < dofs.num_free() / 2) {
        if (!own[static_cast<std::size_t>(v)]) own_nodes.push_back(v);
        own[static_cast<std::size_t>(v)] = true;
      }
  return {std::move(mesh), std::move(dofs), std::move(own), std::move(own_nodes)};
}

TEST(ModelPart, TwoLayersOfCellsAroundTheRanksNodes) {
  const Whole w = whole();
  PartCells part_cells(w.mesh);
  const std::vector<Index> cells = part_cells.cells(w.own_nodes);
  // By brute force: the cells around the nodes of the cells around the own nodes.
  const auto around = [&](const std::vector<bool>& nodes) {
    std::vector<bool> near(nodes.size(), false);
    for (Index c = 0; c < w.mesh.num_cells(); ++c) {
      bool touches = false;
      for (const Index v : w.mesh.cell(c)) touches = touches || nodes[static_cast<std::size_t>(v)];
      if (touches)
        for (const Index v : w.mesh.cell(c)) near[static_cast<std::size_t>(v)] = true;
    }
    return near;
  };
  const std::vector<bool> first = around(w.own);
  std::vector<Index> expected;
  for (Index c = 0; c < w.mesh.num_cells(); ++c) {
    bool touches = false;
    for (const Index v : w.mesh.cell(c)) touches = touches || first[static_cast<std::size_t>(v)];
    if (touches) expected.push_back(c);
  }
  EXPECT_EQ(cells, expected);
  EXPECT_LT(cells.size(), static_cast<std::size_t>(w.mesh.num_cells()));  // a part, not all
  // Asked again (another rank's call), the same answer.
  EXPECT_EQ(part_cells.cells(w.own_nodes), expected);
}

TEST(ModelPart, APartAssemblesTheSameColumnsAsTheWholeMesh) {
  const Whole w = whole();
  PartCells part_cells(w.mesh);
  const MeshPart part = mesh_part(w.mesh, part_cells.cells(w.own_nodes));
  ASSERT_TRUE(std::is_sorted(part.global_nodes.begin(), part.global_nodes.end()));
  ASSERT_EQ(part.mesh.num_nodes(), static_cast<Index>(part.global_nodes.size()));
  for (Index v = 0; v < part.mesh.num_nodes(); ++v)
    EXPECT_EQ(part.mesh.node(v), w.mesh.node(part.global_nodes[static_cast<std::size_t>(v)]));
  const DofMap dofs = w.dofs.part(part.global_nodes);
  EXPECT_EQ(dofs.num_free(), w.dofs.num_free());
  std::vector<bool> own(static_cast<std::size_t>(part.mesh.num_nodes()), false);
  for (Index v = 0; v < part.mesh.num_nodes(); ++v) {
    const Index g = part.global_nodes[static_cast<std::size_t>(v)];
    own[static_cast<std::size_t>(v)] = w.own[static_cast<std::size_t>(g)];
    for (int k = 0; k < 3; ++k) EXPECT_EQ(dofs.free_index(v, k), w.dofs.free_index(g, k));
  }
  // The places follow the numbering: a node's free dofs after those of lower places.
  for (Index a = 0; a < dofs.num_nodes(); ++a)
    for (Index b = 0; b < dofs.num_nodes(); ++b)
      if (dofs.free_index(a, 2) >= 0 && dofs.free_index(b, 2) >= 0 &&
          dofs.node_place(a) < dofs.node_place(b)) {
        EXPECT_LT(dofs.free_index(a, 2), dofs.free_index(b, 2));
      }
  const ElasticityOptions elasticity;
  const SparseMatrix A = assemble_stiffness(part.mesh, dofs, elasticity, &own);
  const SparseMatrix whole_A = assemble_stiffness(w.mesh, w.dofs, elasticity, &w.own);
  ASSERT_EQ(A.nonZeros(), whole_A.nonZeros());
  for (Index col = 0; col < A.outerSize(); ++col) {
    ASSERT_EQ(A.outerIndexPtr()[col], whole_A.outerIndexPtr()[col]);
    for (Index k = A.outerIndexPtr()[col]; k < A.outerIndexPtr()[col + 1]; ++k) {
      EXPECT_EQ(A.innerIndexPtr()[k], whole_A.innerIndexPtr()[k]);
      EXPECT_EQ(A.valuePtr()[k], whole_A.valuePtr()[k]);
    }
  }
  // The rigid-body modes of the part's rows, about the whole mesh's centroid.
  const Eigen::VectorXd centre = w.mesh.coordinates().rowwise().mean();
  const Index half = w.dofs.num_free() / 2;
  EXPECT_EQ(rigid_body_modes(part.mesh, dofs, 0, half, &centre),
            rigid_body_modes(w.mesh, w.dofs, 0, half));
}

TEST(ModelPart, TheBytesCarryEachPieceWhole) {
  const Whole w = whole();
  ByteWriter out;
  pack(out, w.mesh);
  pack(out, w.dofs);
  RigidObstacle plane;
  plane.shape = ObstacleShape::Plane;
  plane.point = Eigen::Vector3d(0.0, 0.0, 1.1);
  plane.normal = Eigen::Vector3d(0.0, 0.0, -1.0);
  const ContactSet contact = make_contact_set(w.mesh, w.mesh.boundary_part("zmax"), w.dofs, plane);
  pack(out, contact);
  const NodeGraph graph = node_graph(w.mesh, w.dofs, 0, 1);
  pack(out, graph);
  out.put(std::vector<std::string>{"a", "", "bc"});
  ByteReader in(out.bytes());
  const Mesh mesh = unpack_mesh(in);
  const DofMap dofs = unpack_dof_map(in);
  const ContactSet c = unpack_contact_set(in);
  const NodeGraph g = unpack_node_graph(in);
  EXPECT_EQ(in.get_strings(), (std::vector<std::string>{"a", "", "bc"}));
  EXPECT_TRUE(in.done());
  ASSERT_EQ(mesh.num_cells(), w.mesh.num_cells());
  EXPECT_EQ(mesh.coordinates(), w.mesh.coordinates());
  for (Index cell = 0; cell < mesh.num_cells(); ++cell) {
    EXPECT_EQ(mesh.cell_type(cell), w.mesh.cell_type(cell));
    EXPECT_TRUE(std::ranges::equal(mesh.cell(cell), w.mesh.cell(cell)));
  }
  EXPECT_EQ(dofs.num_free(), w.dofs.num_free());
  for (Index v = 0; v < dofs.num_nodes(); ++v)
    for (int k = 0; k < 3; ++k) EXPECT_EQ(dofs.free_index(v, k), w.dofs.free_index(v, k));
  EXPECT_EQ(c.nodes, contact.nodes);
  EXPECT_EQ(c.normals, contact.normals);
  EXPECT_EQ(c.weights, contact.weights);
  EXPECT_EQ(c.gaps, contact.gaps);
  EXPECT_EQ(Matrix(c.N), Matrix(contact.N));
  EXPECT_EQ(c.movable, contact.movable);
  EXPECT_EQ(c.facets, contact.facets);
  EXPECT_EQ(g.offsets, graph.offsets);
  EXPECT_EQ(g.neighbours, graph.neighbours);
  EXPECT_EQ(g.weights, graph.weights);
  // A message cut short fails with a message rather than reading past its end.
  const std::vector<char> cut(out.bytes().begin(), out.bytes().begin() + 100);
  ByteReader short_one(cut);
  EXPECT_THROW((void)unpack_mesh(short_one), NumericalError);
}

// The node graph's rows made rank by rank (NodeGraphRows, what rank 0 sends): each rank's rows
// are those of the whole graph, and each vertex's neighbours are the free nodes that share a
// cell with it, counted from the cells directly.
TEST(NodeGraphRows, EachRanksRowsAreTheWholeGraphs) {
  const Whole w = whole();
  const NodeGraphRows rows(w.mesh, w.dofs);
  const NodeGraph all = rows.rows(0, 1);
  ASSERT_GT(all.vertices, 0);
  for (Index v = 0; v < all.vertices; ++v) {
    std::vector<Index> expected;
    const Index node = all.node[static_cast<std::size_t>(v)];
    for (Index c = 0; c < w.mesh.num_cells(); ++c) {
      const auto cell = w.mesh.cell(c);
      if (std::find(cell.begin(), cell.end(), node) == cell.end()) continue;
      for (const Index b : cell) {
        const auto at = std::find(all.node.begin(), all.node.end(), b);
        if (b != node && at != all.node.end()) expected.push_back(at - all.node.begin());
      }
    }
    std::sort(expected.begin(), expected.end());
    expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
    const auto i = static_cast<std::size_t>(v);
    EXPECT_TRUE(std::equal(expected.begin(), expected.end(),
                           all.neighbours.begin() + all.offsets[i],
                           all.neighbours.begin() + all.offsets[i + 1]))
        << "vertex " << v;
  }
  Index at = 0;
  for (int r = 0; r < 3; ++r) {
    const NodeGraph g = rows.rows(r, 3, /*with_nodes=*/r == 0);
    EXPECT_EQ(g.first, at);
    EXPECT_EQ(g.node.empty(), r != 0);
    for (Index v = g.first; v < g.last; ++v) {
      const auto i = static_cast<std::size_t>(v - g.first), j = static_cast<std::size_t>(v);
      EXPECT_EQ(g.weights[i], all.weights[j]);
      EXPECT_TRUE(std::equal(
          g.neighbours.begin() + g.offsets[i], g.neighbours.begin() + g.offsets[i + 1],
          all.neighbours.begin() + all.offsets[j], all.neighbours.begin() + all.offsets[j + 1]))
          << "rank " << r << ", vertex " << v;
    }
    at = g.last;
  }
  EXPECT_EQ(at, all.vertices);
}

}  // namespace
}  // namespace signorini

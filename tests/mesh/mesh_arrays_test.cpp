// Meshes given as arrays (mesh/mesh_arrays.hpp): a Gmsh mesh taken apart into arrays and put back
// together is the same mesh, and a problem on it solves to the same bits as the problem file on
// the Gmsh file; clockwise 2D cells are turned; every kind of bad array gets its one-line message;
// a problem given a mesh refuses a [mesh] section and checks its keys against the mesh's
// dimension.

#include "signorini/mesh/mesh_arrays.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "expect_contains.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

std::string example(const std::string& file) {
  return std::string(SIGNORINI_EXAMPLES_DIR) + "/" + file;
}

// The arrays of a mesh: its points, a block per (type, region), its boundary parts' facets.
MeshArrays arrays_of(const Mesh& mesh) {
  MeshArrays a;
  a.points = mesh.coordinates();
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const std::string& region = mesh.region_names()[static_cast<std::size_t>(mesh.cell_region(c))];
    if (a.blocks.empty() || a.blocks.back().type != mesh.cell_type(c) ||
        a.blocks.back().region != region)
      a.blocks.push_back({mesh.cell_type(c), {}, region});
    for (const Index v : mesh.cell(c)) a.blocks.back().nodes.push_back(v);
  }
  for (const std::string& name : mesh.boundary_part_names()) {
    BoundaryFacets f{name, 0, {}};
    for (const Facet& facet : mesh.boundary_part(name).facets) {
      const std::vector<Index> nodes = mesh.facet_nodes(facet);
      f.nodes_per_facet = static_cast<int>(nodes.size());
      f.nodes.insert(f.nodes.end(), nodes.begin(), nodes.end());
    }
    a.boundaries.push_back(std::move(f));
  }
  return a;
}

void expect_same_mesh(const Mesh& a, const Mesh& b) {
  ASSERT_EQ(a.num_nodes(), b.num_nodes());
  ASSERT_EQ(a.num_cells(), b.num_cells());
  EXPECT_EQ(a.coordinates(), b.coordinates());
  for (Index c = 0; c < a.num_cells(); ++c) {
    ASSERT_EQ(a.cell_type(c), b.cell_type(c));
    const auto x = a.cell(c), y = b.cell(c);
    ASSERT_TRUE(std::equal(x.begin(), x.end(), y.begin(), y.end())) << "cell " << c;
    EXPECT_EQ(a.region_names()[static_cast<std::size_t>(a.cell_region(c))],
              b.region_names()[static_cast<std::size_t>(b.cell_region(c))]);
  }
  ASSERT_EQ(a.boundary_part_names(), b.boundary_part_names());
  for (const std::string& name : a.boundary_part_names()) {
    const auto& f = a.boundary_part(name).facets;
    const auto& g = b.boundary_part(name).facets;
    ASSERT_EQ(f.size(), g.size()) << name;
    for (std::size_t i = 0; i < f.size(); ++i) {
      EXPECT_EQ(f[i].cell, g[i].cell) << name << " facet " << i;
      EXPECT_EQ(f[i].local, g[i].local) << name << " facet " << i;
    }
  }
}

TEST(MeshArrays, GmshMeshesComeBackTheSameIn2DAnd3D) {
  for (const char* file : {"gmsh/hertz.msh", "gmsh/hertz_p2.msh", "gmsh/hertz_sphere_coarse.msh",
                           "gmsh/disc_quarter.msh"}) {
    SCOPED_TRACE(file);
    const Mesh read = read_gmsh_mesh(example(file));
    expect_same_mesh(read, mesh_from_arrays(arrays_of(read)));
  }
}

std::string without_mesh_section(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream out;
  std::string line;
  bool skipping = false;
  while (std::getline(in, line)) {
    if (line.rfind('[', 0) == 0) skipping = line == "[mesh]";
    if (!skipping) out << line << '\n';
  }
  return out.str();
}

TEST(MeshArrays, AProblemOnTheArraysSolvesToTheBitsOfTheProblemFile) {
  for (const char* problem : {"hertz.toml", "hertz_sphere.toml"}) {
    SCOPED_TRACE(problem);
    const LoadedProblem file = read_problem_file(example(problem));
    auto mesh = std::make_shared<const Mesh>(
        mesh_from_arrays(arrays_of(read_mesh_file(file.spec.mesh_file))));
    const LoadedProblem given =
        parse_problem_string(without_mesh_section(example(problem)), problem, {}, mesh);
    EXPECT_EQ(given.spec.mesh_type, MeshType::Given);
    EXPECT_NE(given.effective_toml.find("# [mesh]: given by the program"), std::string::npos);
    const Model a = build_model(file.spec);
    const Model b = build_model(given.spec);
    const ContactResult ra = solve_contact(a.problem, a.solver, &a.multigrid);
    const ContactResult rb = solve_contact(b.problem, b.solver, &b.multigrid);
    ASSERT_TRUE(ra.summary.converged());
    EXPECT_EQ(ra.u, rb.u);
    EXPECT_EQ(ra.l, rb.l);
    EXPECT_EQ(ra.summary.outer_iterations, rb.summary.outer_iterations);
  }
}

MeshArrays two_squares() {
  MeshArrays a;
  a.points.resize(2, 6);
  a.points << 0, 1, 2, 0, 1, 2,  //
      0, 0, 0, 1, 1, 1;
  a.blocks.push_back({CellType::Quad4, {0, 1, 4, 3, 1, 2, 5, 4}, "left"});
  a.boundaries.push_back({"bottom", 2, {0, 1, 2, 1}});
  return a;
}

TEST(MeshArrays, ClockwiseCellsAreTurnedAndRegionsAndFacetsKept) {
  MeshArrays a = two_squares();
  a.blocks[0].nodes = {0, 3, 4, 1, 1, 2, 5, 4};  // the first clockwise
  const Mesh m = mesh_from_arrays(a);
  EXPECT_EQ(std::vector<Index>(m.cell(0).begin(), m.cell(0).end()),
            (std::vector<Index>{0, 1, 4, 3}));
  EXPECT_EQ(m.region_names(), (std::vector<std::string>{"", "left"}));
  EXPECT_EQ(m.cell_region(1), 1);
  const auto& f = m.boundary_part("bottom").facets;
  ASSERT_EQ(f.size(), 2u);
  EXPECT_EQ(m.facet_nodes(f[0]), (std::vector<Index>{0, 1}));  // oriented with the cell
  EXPECT_EQ(m.facet_nodes(f[1]), (std::vector<Index>{1, 2}));
}

void expect_refused(const MeshArrays& a, const std::string& words) {
  try {
    (void)mesh_from_arrays(a);
    ADD_FAILURE() << "accepted; expected: " << words;
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), words);
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
}

TEST(MeshArrays, BadArraysAreRefusedInOneLine) {
  MeshArrays a = two_squares();
  a.blocks[0].nodes[5] = 9;
  expect_refused(a, "mesh: cell block 0 (quad4), cell 1: node 9 out of range, expected 0..5");
  a = two_squares();
  a.blocks[0].nodes.pop_back();
  expect_refused(a, "not a multiple of 4");
  a = two_squares();
  a.blocks[0].type = CellType::Tet4;
  expect_refused(a, "a 3D cell type, but the points have 2 coordinates");
  a = two_squares();
  a.points.conservativeResize(2, 7);
  a.points.col(6) << 5, 5;
  expect_refused(a, "point 6 belongs to no cell");
  a = two_squares();
  a.points(1, 3) = std::nan("");
  expect_refused(a, "point 3 has a coordinate that is not finite");
  a = two_squares();
  a.boundaries[0].nodes = {0, 4};
  expect_refused(a, "boundary part 'bottom', facet 0 (nodes 0, 4): not an edge of any cell");
  a = two_squares();
  a.boundaries.push_back(a.boundaries[0]);
  expect_refused(a, "boundary part 'bottom' is given twice");
  a = two_squares();
  a.boundaries[0].nodes_per_facet = 4;
  expect_refused(a, "facets of 4 nodes, expected 2 or 3 (lines)");
  a = two_squares();
  a.points.row(1).setZero();
  expect_refused(a, "cell 0: degenerate (zero area)");
  MeshArrays t;
  t.points.resize(3, 4);
  t.points << 0, 1, 0, 0,  //
      0, 0, 1, 0,          //
      0, 0, 0, 1;
  t.blocks.push_back({CellType::Tet4, {0, 2, 1, 3}, ""});
  expect_refused(t, "cell 0: inverted: det J < 0 at a corner");
  t.points.resize(1, 4);
  expect_refused(t, "the points have 1 coordinates each, expected 2");
}

// Cells that count the same ground twice, or a collapsed one, assemble without complaint: each
// is refused with the cell it concerns (mesh/cell_overlap.hpp).
TEST(MeshArrays, CollapsedDoubledAndOverlappingCellsAreRefused) {
  MeshArrays a = two_squares();
  a.blocks[0].nodes = {0, 1, 1, 3, 1, 2, 5, 4};  // the report's collapsed quad
  expect_refused(a, "mesh: cell block 0 (quad4), cell 0 names node 1 twice (a collapsed cell)");
  a = two_squares();
  a.blocks[0].nodes.insert(a.blocks[0].nodes.end(), {1, 4, 3, 0});  // cell 0 again, turned
  expect_refused(a,
                 "mesh: cell block 0 (quad4), cell 0 and cell block 0 (quad4), cell 2 have the "
                 "same nodes (a doubled cell");
  a = two_squares();  // the same cell again in a block of its own (another region)
  a.blocks.push_back({CellType::Quad4, {1, 2, 5, 4}, "right"});
  expect_refused(a, "cell block 0 (quad4), cell 1 and cell block 1 (quad4), cell 0 have the same");
  a = two_squares();  // a triangle laid over half of the first square
  a.blocks.push_back({CellType::Tri3, {0, 1, 4}, ""});
  expect_refused(a, "lie on the same side of their common facet (corners 0, 1): the cells overlap");
  a = two_squares();  // a third square folded back over the second, on its right edge
  a.points.conservativeResize(2, 8);
  a.points.col(6) << 1.5, 0;
  a.points.col(7) << 1.5, 1;
  a.blocks[0].nodes.insert(a.blocks[0].nodes.end(), {6, 2, 5, 7});
  expect_refused(a,
                 "cell 1 and cell block 0 (quad4), cell 2 lie on the same side of their common "
                 "facet (corners 2, 5)");
  // In 3D: a tetrahedron of the cube given twice.
  MeshArrays t;
  t.points.resize(3, 5);
  t.points << 0, 1, 0, 0, 1,  //
      0, 0, 1, 0, 1,          //
      0, 0, 0, 1, 1;
  t.blocks.push_back({CellType::Tet4, {0, 1, 2, 3, 1, 2, 3, 4}, ""});
  EXPECT_NO_THROW((void)mesh_from_arrays(t));
  t.blocks[0].nodes.insert(t.blocks[0].nodes.end(), {1, 0, 3, 2});
  expect_refused(t, "cell 0 and cell block 0 (tet4), cell 2 have the same nodes");
}

TEST(MeshArrays, AProblemGivenAMeshRefusesMeshAndChecksTheDimension) {
  auto mesh = std::make_shared<const Mesh>(mesh_from_arrays(two_squares()));
  const std::string body =
      "[material]\nE = 1.0\nnu = 0.3\n[[clamp]]\nboundary = \"bottom\"\n"
      "[contact]\nboundary = \"bottom\"\n";
  try {
    (void)parse_problem_string("[mesh]\ntype = \"rectangle\"\n" + body, "p.toml", {}, mesh);
    ADD_FAILURE() << "accepted a [mesh] section";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "p.toml:1: section [mesh]: the mesh is given by the program");
  }
  try {
    (void)parse_problem_string(body + "[body_force]\nf = [\"0\", \"0\", \"1\"]\n", "p.toml", {},
                               mesh);
    ADD_FAILURE() << "accepted a 3D body force on a 2D mesh";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "key 'body_force.f' must have 2 entries (x and y components), got 3");
  }
}

}  // namespace
}  // namespace signorini

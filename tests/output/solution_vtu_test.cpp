// solution.vtu and contact.vtu: the files parse (by an independent reader here, and by meshio
// where /usr/bin/python3 has it), and every value equals the one in memory.

#include "signorini/output/solution_vtu.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "expect_contains.hpp"
#include "output/vtu_reader.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/output/vtu_file.hpp"
#include "temporary_folder.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;

// The paper's problem on 12 x 4 cells with a curved foundation, so that the gap is not zero
// everywhere and the body touches only part of it.
struct Solved {
  ProblemSpec spec = [] {
    ProblemSpec s = paper_benchmark(12, 4);
    s.contacts[0].gap = [](const Point& x) { return 1e-6 * (x(0) - 0.5) * (x(0) - 0.5); };
    return s;
  }();
  Model model = build_model(spec);
  ContactResult result = solve_contact(model.problem, spec.solver);
  Vector u = model.dofs.expand(result.u);
};

const Solved& solved() {
  static const Solved s;
  return s;
}

void expect_all_finite(const testing::VtuContents& v) {
  for (const auto& [name, a] : v.point_data)
    for (const double x : a.values) ASSERT_TRUE(std::isfinite(x)) << name;
}

TEST(SolutionVtu, MeshAndFieldsEqualTheSolution) {
  const Solved& s = solved();
  ASSERT_TRUE(s.result.summary.converged()) << s.result.summary.message;
  const testing::VtuContents v = testing::read_vtu_text(solution_vtu(s.result, s.model));
  const Mesh& mesh = s.model.mesh;
  ASSERT_EQ(v.points, mesh.num_nodes());
  ASSERT_EQ(v.cells, mesh.num_cells());
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto k = static_cast<std::size_t>(n);
    EXPECT_EQ(v.coordinates.values[3 * k], mesh.node(n)(0));
    EXPECT_EQ(v.coordinates.values[3 * k + 1], mesh.node(n)(1));
    EXPECT_EQ(v.coordinates.values[3 * k + 2], 0.0);
  }
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto k = static_cast<std::size_t>(c);
    EXPECT_EQ(v.types.values[k], 9.0);  // VTK_QUAD
    EXPECT_EQ(v.offsets.values[k], 4.0 * static_cast<double>(c + 1));
    for (std::size_t a = 0; a < 4; ++a)
      EXPECT_EQ(v.connectivity.values[4 * k + a], static_cast<double>(mesh.cell(c)[a]));
  }

  const NodalStress stress = nodal_stress(mesh, s.spec.elasticity, s.u);
  const auto& displacement = v.point_data.at("displacement");
  const auto& tensor = v.point_data.at("stress");
  const auto& von_mises = v.point_data.at("von_mises");
  ASSERT_EQ(displacement.components, 3);
  ASSERT_EQ(tensor.components, 6);
  EXPECT_EQ(tensor.attributes.at("ComponentName3"), "XY");
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto k = static_cast<std::size_t>(n);
    EXPECT_EQ(displacement.values[3 * k], s.u(2 * n));
    EXPECT_EQ(displacement.values[3 * k + 1], s.u(2 * n + 1));
    EXPECT_EQ(displacement.values[3 * k + 2], 0.0);
    for (int i = 0; i < 4; ++i) EXPECT_EQ(tensor.values[6 * k + i], stress.sigma(i, n)) << i;
    EXPECT_EQ(tensor.values[6 * k + 4], 0.0);
    EXPECT_EQ(tensor.values[6 * k + 5], 0.0);
    EXPECT_EQ(von_mises.values[k], stress.von_mises(n));
  }

  // Contact quantities on the contact nodes, 0 elsewhere.
  const ContactSet& c = s.model.problem.contact;
  std::vector<double> pressure(static_cast<std::size_t>(mesh.num_nodes()), 0.0);
  std::vector<double> gap = pressure, active = pressure, boundary = pressure;
  for (Index j = 0; j < c.size(); ++j) {
    const auto node = static_cast<std::size_t>(c.nodes[static_cast<std::size_t>(j)]);
    pressure[node] = s.result.l(j);
    gap[node] = c.gaps(j);
    active[node] = s.result.l(j) > 0.0 ? 1.0 : 0.0;
    boundary[node] = 1.0;
  }
  EXPECT_EQ(v.point_data.at("contact_pressure").values, pressure);
  EXPECT_EQ(v.point_data.at("gap").values, gap);
  EXPECT_EQ(v.point_data.at("contact_active").values, active);
  EXPECT_EQ(v.point_data.at("contact_boundary").values, boundary);
  EXPECT_EQ(v.point_data.at("contact_active").type, "UInt8");
  // The example is one where the body touches part of the foundation only.
  const auto touching = static_cast<double>(std::count(active.begin(), active.end(), 1.0));
  EXPECT_EQ(touching, static_cast<double>(s.result.summary.num_active));
  EXPECT_GT(touching, 0.0);
  EXPECT_LT(touching, static_cast<double>(c.size()));
  expect_all_finite(v);
}

TEST(ContactVtu, LinesAlongTheContactBoundaryWithTheCsvValues) {
  const Solved& s = solved();
  const testing::VtuContents v = testing::read_vtu_text(contact_vtu(s.result, s.model));
  const ContactSet& c = s.model.problem.contact;
  ASSERT_EQ(v.points, c.size());
  ASSERT_EQ(v.cells, c.size() - 1);  // the bottom edge: one line per facet
  for (Index e = 0; e < v.cells; ++e) {
    const auto k = static_cast<std::size_t>(e);
    EXPECT_EQ(v.types.values[k], 3.0);  // VTK_LINE
    EXPECT_EQ(v.offsets.values[k], 2.0 * static_cast<double>(e + 1));
    // Facets along the edge join consecutive contact nodes.
    EXPECT_EQ(std::abs(v.connectivity.values[2 * k + 1] - v.connectivity.values[2 * k]), 1.0);
  }
  for (Index j = 0; j < c.size(); ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Index node = c.nodes[k];
    const double ux = s.u(2 * node), uy = s.u(2 * node + 1);
    const double nx = c.normals(0, j), ny = c.normals(1, j);
    EXPECT_EQ(v.coordinates.values[3 * k], s.model.mesh.node(node)(0));
    EXPECT_EQ(v.coordinates.values[3 * k + 1], s.model.mesh.node(node)(1));
    EXPECT_EQ(v.point_data.at("displacement").values[3 * k], ux);
    EXPECT_EQ(v.point_data.at("displacement").values[3 * k + 1], uy);
    EXPECT_EQ(v.point_data.at("normal").values[3 * k], nx);
    EXPECT_EQ(v.point_data.at("normal").values[3 * k + 1], ny);
    EXPECT_EQ(v.point_data.at("normal_displacement").values[k], ux * nx + uy * ny);
    EXPECT_EQ(v.point_data.at("tangential_displacement").values[k], -ux * ny + uy * nx);
    EXPECT_EQ(v.point_data.at("contact_pressure").values[k], s.result.l(j));
    EXPECT_EQ(v.point_data.at("gap").values[k], c.gaps(j));
    EXPECT_EQ(v.point_data.at("deformed_gap").values[k], c.gaps(j) - (ux * nx + uy * ny));
    EXPECT_EQ(v.point_data.at("contact_active").values[k], s.result.l(j) > 0.0 ? 1.0 : 0.0);
  }
  expect_all_finite(v);
}

TEST(VtuFile, CellsPointDataAndChecks) {
  Eigen::MatrixXd points(2, 3);
  points << 0, 1, 0, 0, 0, 1;
  VtuFile f(points);
  const std::vector<Index> triangle = {0, 1, 2};
  f.add_cell(VtkCellType::Triangle, triangle);
  f.add_point_data("a<b", 1, {1.0, 2.0, 3.0});
  f.add_point_data("flag", std::vector<std::uint8_t>{0, 1, 0});
  EXPECT_THROW(f.add_point_data("short", 2, {1.0, 2.0}), std::invalid_argument);
  EXPECT_THROW(f.add_point_data("flags", std::vector<std::uint8_t>{1}), std::invalid_argument);
  const std::vector<Index> bad = {0, 3};
  EXPECT_THROW(f.add_cell(VtkCellType::Line, bad), std::invalid_argument);
  const std::string text = f.take_text();
  EXPECT_EQ(f.num_points(), 0);  // its arrays were freed as they went into the text
  EXPECT_EQ(f.num_cells(), 0);
  EXPECT_CONTAINS(text, "Name=\"a&lt;b\"");                     // attribute values stay well-formed
  const testing::VtuContents v = testing::read_vtu_text(text);  // names as written, escaped
  EXPECT_EQ(v.points, 3);
  EXPECT_EQ(v.cells, 1);
  EXPECT_EQ(v.types.values, std::vector<double>({5.0}));
  EXPECT_EQ(v.coordinates.values, std::vector<double>({0, 0, 0, 1, 0, 0, 0, 1, 0}));
  EXPECT_EQ(v.point_data.at("a&lt;b").values, std::vector<double>({1.0, 2.0, 3.0}));
  EXPECT_EQ(v.point_data.at("flag").values, std::vector<double>({0.0, 1.0, 0.0}));
  EXPECT_EQ(vtk_cell_type(CellType::Quad4), VtkCellType::Quad);
  EXPECT_EQ(vtk_cell_type(CellType::Hex8), VtkCellType::Hexahedron);
}

// meshio is how most Python users would read the files; it is also what ParaView's format
// checks come closest to without a display. It runs where /usr/bin/python3 has meshio
// (scripts/setup.sh installs python3-meshio).
bool python_has_meshio() {
  return std::system("/usr/bin/python3 -c 'import meshio' > /dev/null 2>&1") == 0;
}

TEST(SolutionVtu, MeshioReadsTheSameValues) {
  if (!python_has_meshio()) GTEST_SKIP() << "/usr/bin/python3 has no meshio (python3-meshio)";
  const Solved& s = solved();
  const testing::TemporaryFolder dir;
  write_results(dir.path(), s.result, s.model, s.spec);
  // meshio's arrays as JSON lists; Python's repr of a float reads back to the same double.
  std::ofstream(dir / "read.py") << R"py(
import json, sys, meshio
out = {}
for name in ("solution", "contact"):
    m = meshio.read(sys.argv[1] + "/" + name + ".vtu")
    out[name] = {"points": m.points.tolist(),
                 "cells": {b.type: b.data.tolist() for b in m.cells},
                 "point_data": {k: v.tolist() for k, v in m.point_data.items()}}
json.dump(out, open(sys.argv[1] + "/meshio.json", "w"))
)py";
  const std::string command =
      "/usr/bin/python3 '" + (dir / "read.py").string() + "' '" + dir.path().string() + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << command;
  std::ifstream in(dir / "meshio.json");
  const nlohmann::json j = nlohmann::json::parse(in);

  const Mesh& mesh = s.model.mesh;
  const nlohmann::json& sol = j["solution"];
  ASSERT_EQ(sol["points"].size(), static_cast<std::size_t>(mesh.num_nodes()));
  ASSERT_EQ(sol["cells"]["quad"].size(), static_cast<std::size_t>(mesh.num_cells()));
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (std::size_t a = 0; a < 4; ++a)
      EXPECT_EQ(sol["cells"]["quad"][static_cast<std::size_t>(c)][a].get<Index>(), mesh.cell(c)[a]);
  const NodalStress stress = nodal_stress(mesh, s.spec.elasticity, s.u);
  const nlohmann::json& pd = sol["point_data"];
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    const auto k = static_cast<std::size_t>(n);
    EXPECT_EQ(sol["points"][k][0].get<double>(), mesh.node(n)(0));
    EXPECT_EQ(sol["points"][k][1].get<double>(), mesh.node(n)(1));
    EXPECT_EQ(pd["displacement"][k][0].get<double>(), s.u(2 * n));
    EXPECT_EQ(pd["displacement"][k][1].get<double>(), s.u(2 * n + 1));
    for (std::size_t i = 0; i < 4; ++i)
      EXPECT_EQ(pd["stress"][k][i].get<double>(), stress.sigma(static_cast<Index>(i), n));
    // meshio keeps a one-component array as n x 1.
    EXPECT_EQ(pd["von_mises"][k][0].get<double>(), stress.von_mises(n));
  }
  const ContactSet& c = s.model.problem.contact;
  const nlohmann::json& con = j["contact"];
  ASSERT_EQ(con["cells"]["line"].size(), static_cast<std::size_t>(c.size() - 1));
  for (Index jj = 0; jj < c.size(); ++jj) {
    const auto k = static_cast<std::size_t>(jj);
    const auto node = static_cast<std::size_t>(c.nodes[k]);
    EXPECT_EQ(pd["contact_pressure"][node][0].get<double>(), s.result.l(jj));
    EXPECT_EQ(pd["gap"][node][0].get<double>(), c.gaps(jj));
    EXPECT_EQ(pd["contact_boundary"][node][0].get<int>(), 1);
    EXPECT_EQ(con["point_data"]["contact_pressure"][k][0].get<double>(), s.result.l(jj));
    EXPECT_EQ(con["point_data"]["gap"][k][0].get<double>(), c.gaps(jj));
  }
}

// Every cell type, and a mixed Gmsh mesh with regions: meshio reads solution.vtu and contact.vtu
// with VTK's cell types (triangle6, quad8, quad9 ...), the connectivity of our cells, and the
// region of each cell.
TEST(SolutionVtu, MeshioReadsEveryCellTypeAndTheRegions) {
  if (!python_has_meshio()) GTEST_SKIP() << "/usr/bin/python3 has no meshio (python3-meshio)";
  struct Case {
    std::string label, meshio_type;
    CellType cell;
    bool gmsh;
  };
  for (const Case& k : {Case{"tri3", "triangle", CellType::Tri3, false},
                        Case{"tri6", "triangle6", CellType::Tri6, false},
                        Case{"quad8", "quad8", CellType::Quad8, false},
                        Case{"quad9", "quad9", CellType::Quad9, false},
                        Case{"gmsh", "quad9", CellType::Quad9, true}}) {
    ProblemSpec spec = paper_benchmark(12, 4);
    spec.mesh.cell = k.cell;
    if (k.gmsh) {
      spec.mesh_type = MeshType::Gmsh;
      spec.mesh_file = std::string(SIGNORINI_TEST_DATA_DIR) + "/mesh/data/mixed_msh41.msh";
      spec.tractions[1].boundary = "top";
      spec.tractions[0].boundary = "right";
    }
    const Model model = build_model(spec);
    const ContactResult result = solve_contact(model.problem, spec.solver);
    ASSERT_TRUE(result.summary.converged()) << k.label << ": " << result.summary.message;
    const testing::TemporaryFolder dir;
    write_results(dir.path(), result, model, spec);
    std::ofstream(dir / "read.py") << R"py(
import json, sys, meshio
out = {}
for name in ("solution", "contact"):
    m = meshio.read(sys.argv[1] + "/" + name + ".vtu")
    cells = {}  # meshio starts a block wherever the type changes: join the blocks per type
    for b in m.cells:
        cells.setdefault(b.type, []).extend(b.data.tolist())
    out[name] = {"cells": cells,
                 "cell_data": {k: [a.tolist() for a in v] for k, v in m.cell_data.items()}}
json.dump(out, open(sys.argv[1] + "/meshio.json", "w"))
)py";
    const std::string command =
        "/usr/bin/python3 '" + (dir / "read.py").string() + "' '" + dir.path().string() + "'";
    ASSERT_EQ(std::system(command.c_str()), 0) << command;
    std::ifstream in(dir / "meshio.json");
    const nlohmann::json j = nlohmann::json::parse(in);
    const Mesh& mesh = model.mesh;
    // meshio groups cells by type, in the order of the file: count and compare per type.
    std::map<std::string, std::size_t> next;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const std::string type = mesh.cell_type(c) == CellType::Tri6 ? "triangle6" : k.meshio_type;
      const nlohmann::json& cells = j["solution"]["cells"][type];
      const std::size_t row = next[type]++;
      ASSERT_LT(row, cells.size()) << k.label;
      for (std::size_t a = 0; a < mesh.cell(c).size(); ++a)
        EXPECT_EQ(cells[row][a].get<Index>(), mesh.cell(c)[a]) << k.label << " cell " << c;
    }
    EXPECT_TRUE(j["solution"]["cell_data"].contains("region")) << k.label;
    const std::string edge = cell_order(k.cell) == 2 ? "line3" : "line";
    EXPECT_EQ(j["contact"]["cells"][edge].size(), model.problem.contact.facets.size()) << k.label;
  }
}

}  // namespace
}  // namespace signorini

namespace signorini {
namespace {

// With friction contact.vtu has the tangential traction (Cartesian, along tau = (1, 0) on the
// paper's bottom edge) and each node's state, as the solver and friction_states give them.
TEST(ContactVtu, FrictionArrays) {
  ProblemSpec spec = paper_benchmark(30, 10);
  spec.contacts[0].friction = FrictionModel::Coulomb;
  spec.contacts[0].mu = 1.0;
  const Model model = build_model(spec);
  const ContactResult r = solve_contact(model.problem, model.solver);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  const testing::VtuContents v = testing::read_vtu_text(contact_vtu(r, model));
  const std::vector<FrictionState> states =
      friction_states(contact_law(model.problem), r.l, r.tangential);
  int sticking = 0;
  for (Index j = 0; j < model.problem.contact.size(); ++j) {
    const auto k = static_cast<std::size_t>(j);
    EXPECT_EQ(v.point_data.at("tangential_traction").values[3 * k], r.tangential(0, j));
    EXPECT_EQ(v.point_data.at("tangential_traction").values[3 * k + 1], 0.0);
    EXPECT_EQ(v.point_data.at("friction_state").values[k], static_cast<double>(states[k]));
    sticking += states[k] == FrictionState::Sticking ? 1 : 0;
  }
  EXPECT_GT(sticking, 0);
  EXPECT_EQ(v.point_data.at("friction_state").type, "UInt8");
}

}  // namespace
}  // namespace signorini

// The 3D examples from the command line: each problem file, solved by `signorini solve`, gives
// the contact pressures and normal displacements of the same problem built through the library
// (a ProblemSpec written out here) and solved by solve_contact(), to round-off; and the settings
// it echoes (summary.json) are the file's, with three components.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/tool_run.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

namespace fs = std::filesystem;
using testing::quoted;
using testing::run_tool;
using testing::ToolRun;

// The columns of a 3D contact.csv (docs/output.md) that the comparison needs.
struct ContactRow3d {
  Eigen::Vector3d x;
  double u_n = 0.0, pressure = 0.0;
  std::string boundary;
};

std::vector<ContactRow3d> contact_rows_3d(const fs::path& path) {
  std::istringstream csv(testing::read_text(path));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "x,y,z,u_n,u_tx,u_ty,u_tz,pressure,gap,n_x,n_y,n_z,boundary") << path;
  std::vector<ContactRow3d> rows;
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream in(line);
    for (std::string field; std::getline(in, field, ',');) f.push_back(field);
    EXPECT_EQ(f.size(), 13U) << line;
    if (f.size() != 13U) continue;
    rows.push_back({Eigen::Vector3d(std::stod(f[0]), std::stod(f[1]), std::stod(f[2])),
                    std::stod(f[3]), std::stod(f[7]), f[12]});
  }
  return rows;
}

ScalarField constant(double value) {
  return [value](const Point&) { return value; };
}

// The top (zmax) moved by `z`, and held in x and y when `hold_xy`.
DisplacementSpec pushed_top(const std::string& boundary, double z, bool hold_xy) {
  DisplacementSpec d;
  d.boundary = boundary;
  if (hold_xy) {
    d.values[0] = constant(0.0);
    d.values[1] = constant(0.0);
  }
  d.values[2] = constant(z);
  return d;
}

ProblemSpec box_spec(double length, double width, double height, Index nx, Index ny, Index nz,
                     CellType cell) {
  ProblemSpec spec;
  spec.mesh_type = MeshType::Box;
  spec.box.length = length;
  spec.box.width = width;
  spec.box.height = height;
  spec.box.nx = nx;
  spec.box.ny = ny;
  spec.box.nz = nz;
  spec.box.cell = cell;
  spec.elasticity.material = {1000.0, 0.3};
  return spec;
}

// What each example file says, written through the library.
ProblemSpec library_spec(const std::string& example) {
  if (example == "box_on_plane") {
    ProblemSpec spec = box_spec(1.0, 1.0, 0.5, 4, 4, 2, CellType::Hex27);
    spec.clamps = {{"xmin", {true, false, false}}, {"ymin", {false, true, false}}};
    spec.displacements = {pushed_top("zmax", -0.001, false)};
    ContactSpec c;
    c.boundary = "zmin";
    c.obstacle.shape = ObstacleShape::Plane;
    c.obstacle.point = Eigen::Vector3d::Zero();
    c.obstacle.normal = Eigen::Vector3d(0.002, 0.0, 1.0);
    spec.contacts = {c};
    return spec;
  }
  if (example == "box_on_sphere") {
    ProblemSpec spec = box_spec(1.0, 1.0, 0.5, 12, 12, 4, CellType::Tet4);
    spec.displacements = {pushed_top("zmax", -0.005, true)};
    ContactSpec c;
    c.boundary = "zmin";
    c.obstacle.shape = ObstacleShape::Disc;
    c.obstacle.centre = Eigen::Vector3d(0.5, 0.5, -4.0);
    c.obstacle.radius = 4.0;
    spec.contacts = {c};
    return spec;
  }
  if (example == "box_on_cylinder") {
    ProblemSpec spec = box_spec(1.0, 0.5, 0.5, 8, 4, 4, CellType::Hex8);
    spec.displacements = {pushed_top("zmax", -0.001, true)};
    ContactSpec c;
    c.boundary = "zmin";
    c.obstacle.shape = ObstacleShape::Cylinder;
    c.obstacle.centre = Eigen::Vector3d(0.5, 0.0, -2.0);
    c.obstacle.axis = Eigen::Vector3d(0.0, 1.0, 0.0);
    c.obstacle.radius = 2.0;
    spec.contacts = {c};
    return spec;
  }
  // hertz_sphere: as tests/problem/hertz_sphere_test.cpp builds it, on the coarse mesh.
  ProblemSpec spec;
  spec.mesh_type = MeshType::Gmsh;
  spec.mesh_file = SIGNORINI_EXAMPLES_DIR "/gmsh/hertz_sphere_coarse.msh";
  spec.elasticity.material = {1.0, 0.3};
  spec.clamps = {{"xsym", {true, false, false}}, {"ysym", {false, true, false}}};
  spec.displacements = {pushed_top("top", -0.001, false)};
  ContactSpec c;
  c.boundary = "contact";
  c.obstacle.shape = ObstacleShape::Plane;
  c.obstacle.point = Eigen::Vector3d::Zero();
  c.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  c.surface_normal = [](const Point& x) { return Eigen::Vector3d(x(0), x(1), x(2) - 1.0); };
  spec.contacts = {c};
  return spec;
}

class ThreeDimensionalExample : public ::testing::TestWithParam<const char*> {};

TEST_P(ThreeDimensionalExample, ToolSolvesWhatTheLibrarySolves) {
  const std::string example = GetParam();
  const testing::TemporaryFolder dir;
  const fs::path out = dir / example;
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/" + example + ".toml") + " -q -o " +
                        quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream js(out / "summary.json");
  const nlohmann::json summary = nlohmann::json::parse(js);
  const std::vector<ContactRow3d> rows = contact_rows_3d(out / "contact.csv");

  const ProblemSpec spec = library_spec(example);
  const Model model = build_model(spec);
  ASSERT_EQ(model.mesh.dim(), 3);
  const ContactResult lib = solve_contact(model.problem, spec.solver);
  ASSERT_TRUE(lib.summary.converged()) << lib.summary.message;
  EXPECT_TRUE(summary["converged"].get<bool>());
  EXPECT_EQ(summary["n_dofs"].get<Index>(), model.dofs.num_dofs());
  EXPECT_LT(model.dofs.num_dofs(), 10000);  // small enough for a quick test
  EXPECT_NEAR(summary["M"].get<double>(), lib.summary.lagrangian,
              1e-12 * std::abs(lib.summary.lagrangian));

  const ContactSet& c = model.problem.contact;
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(c.size()));
  const Vector u = model.dofs.expand(lib.u);
  const double peak = lib.l.cwiseAbs().maxCoeff();
  ASSERT_GT(peak, 0.0);
  double largest_u_n = 0.0;
  std::vector<double> u_n(rows.size());
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    u_n[static_cast<std::size_t>(j)] = u.segment<3>(3 * node).dot(c.normals.col(j));
    largest_u_n = std::max(largest_u_n, std::abs(u_n[static_cast<std::size_t>(j)]));
  }
  int touching = 0;
  for (std::size_t j = 0; j < rows.size(); ++j) {
    const auto jj = static_cast<Index>(j);
    const auto x = model.mesh.node(c.nodes[j]);
    EXPECT_EQ(rows[j].x, Eigen::Vector3d(x(0), x(1), x(2))) << j;
    EXPECT_EQ(rows[j].boundary, spec.contacts[0].boundary);
    EXPECT_NEAR(rows[j].pressure, lib.l(jj), 1e-12 * peak) << j;
    EXPECT_NEAR(rows[j].u_n, u_n[j], 1e-12 * largest_u_n) << j;
    touching += rows[j].pressure > 0.0 ? 1 : 0;
  }
  // Each obstacle touches part of the face only: the problem is a contact problem, not a
  // prescribed displacement in disguise.
  EXPECT_GT(touching, 0);
  EXPECT_LT(touching, static_cast<int>(rows.size()));
}

INSTANTIATE_TEST_SUITE_P(Examples, ThreeDimensionalExample,
                         ::testing::Values("box_on_plane", "box_on_sphere", "box_on_cylinder",
                                           "hertz_sphere"));

// The settings the run echoes are the file's, points and vectors with three components.
TEST(ThreeDimensionalExamples, SummaryEchoesThreeComponents) {
  const testing::TemporaryFolder dir;
  const fs::path out = dir / "cylinder";
  const ToolRun r =
      run_tool(dir, "solve " + quoted(SIGNORINI_EXAMPLES_DIR "/box_on_cylinder.toml") +
                        " -q --set mesh.nz=2 -o " + quoted(out.string()));
  ASSERT_EQ(r.status, 0) << r.err;
  std::ifstream js(out / "summary.json");
  const nlohmann::json j = nlohmann::json::parse(js);
  const nlohmann::json& problem = j["problem"];
  EXPECT_EQ(problem["mesh"]["type"], "box");
  EXPECT_EQ(problem["mesh"]["nz"], 2);  // the --set value
  EXPECT_EQ(problem["mesh"]["origin"], nlohmann::json({0.0, 0.0, 0.0}));
  EXPECT_EQ(problem["mesh"]["cell"], "hex8");
  EXPECT_FALSE(problem["material"].contains("plane_model"));  // 3D: no plane model
  EXPECT_EQ(problem["contact"]["obstacle"], "cylinder");
  EXPECT_EQ(problem["contact"]["centre"], nlohmann::json({0.5, 0.0, -2.0}));
  EXPECT_EQ(problem["contact"]["axis"], nlohmann::json({0.0, 1.0, 0.0}));
  EXPECT_EQ(problem["displacement"][0]["z"], "-0.001");
  // 9 x 5 x 3 nodes of the hex8 box with nz = 2, three unknowns each.
  EXPECT_EQ(j["n_dofs"], 9 * 5 * 3 * 3);
  EXPECT_EQ(j["resultants"]["contact"].size(), 3U);
}

// A 3D mesh file with 2D vectors, and a 2D mesh file with 3D ones, are refused when the model is
// built (the file cannot know the mesh's dimension before), in one line naming the file and key.
TEST(ThreeDimensionalExamples, GmshMeshOfTheOtherDimensionIsOneLine) {
  const testing::TemporaryFolder dir;
  const auto write = [&](const std::string& name, const std::string& text) {
    std::ofstream(dir / name) << text;
    return (dir / name).string();
  };
  const std::string ball = SIGNORINI_EXAMPLES_DIR "/gmsh/hertz_sphere_coarse.msh";
  ToolRun r = run_tool(
      dir, "check " + quoted(write("ball.toml", "[mesh]\ntype = \"gmsh\"\nfile = \"" + ball +
                                                    "\"\n[material]\nE = 1\nnu = 0.3\n[[clamp]]\n"
                                                    "boundary = \"top\"\n[contact]\nboundary = "
                                                    "\"contact\"\nobstacle = \"plane\"\npoint = "
                                                    "[0, 0]\nnormal = [0, 1]\n")));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: " + (dir / "ball.toml").string() +
                       ": contact.point gives 2 components (2D problems only), but the mesh '" +
                       ball + "' is 3D: expected 3 components (x, y, z)\n");
  // A plane model on a 3D mesh file: refused, not ignored.
  r = run_tool(dir, "check " + quoted(write("plane.toml",
                                            "[mesh]\ntype = \"gmsh\"\nfile = \"" + ball +
                                                "\"\n[material]\nE = 1\nnu = 0.3\nplane_model = "
                                                "\"plane_stress\"\n[[clamp]]\nboundary = "
                                                "\"top\"\n[contact]\nboundary = \"contact\"\n")));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: " + (dir / "plane.toml").string() +
                       ": material.plane_model gives a plane model (2D problems only), but the "
                       "mesh '" +
                       ball + "' is 3D: expected no plane_model (a 3D body has none)\n");
  const std::string strip = SIGNORINI_EXAMPLES_DIR "/gmsh/paper.msh";
  r = run_tool(dir, "check " + quoted(write("strip.toml",
                                            "[mesh]\ntype = \"gmsh\"\nfile = \"" + strip +
                                                "\"\n[material]\nE = 1\nnu = 0.3\n[[clamp]]\n"
                                                "boundary = \"left\"\n[[traction]]\nboundary = "
                                                "\"top\"\np = [0, -1, 0]\n[contact]\nboundary = "
                                                "\"bottom\"\n")));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.err, "signorini: error: " + (dir / "strip.toml").string() +
                       ": traction[0].p gives 3 components (3D problems only), but the mesh '" +
                       strip + "' is 2D: expected 2 components (x, y)\n");
}

}  // namespace
}  // namespace signorini

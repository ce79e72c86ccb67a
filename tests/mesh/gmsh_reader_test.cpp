// The Gmsh reader: one mixed, second-order mesh written by Gmsh in the formats 2.2 and 4.1, ASCII
// and binary (tests/mesh/data/mixed.geo), reads to the same mesh in all four; cells, regions and
// boundary parts come out as documented in gmsh_reader.hpp; a solve on it passes the patch test;
// and every kind of bad file gets one line naming the file and the place.

#include "signorini/mesh/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <fstream>
#include <sstream>

#include "fem/uniaxial_tension.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

std::string data(const std::string& file) {
  return std::string(SIGNORINI_TEST_DATA_DIR) + "/mesh/data/" + file;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// The error message of parsing `content`, or "" if it parses.
std::string error_of(const std::string& content) {
  try {
    (void)parse_gmsh_mesh(content, "bad.msh");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshReader, FourFormatsGiveTheSameMesh) {
  const Mesh m = read_gmsh_mesh(data("mixed_msh41.msh"));
  EXPECT_EQ(m.dim(), 2);
  // 4 x 4 transfinite quadrilaterals on the left, triangles on the right, both second order.
  EXPECT_EQ(m.cell_types(), (std::vector<CellType>{CellType::Tri6, CellType::Quad9}));
  Index quads = 0;
  for (Index c = 0; c < m.num_cells(); ++c) quads += m.cell_type(c) == CellType::Quad9 ? 1 : 0;
  EXPECT_EQ(quads, 16);
  EXPECT_EQ(m.region_names(), (std::vector<std::string>{"", "quads", "triangles"}));
  for (Index c = 0; c < m.num_cells(); ++c) {
    EXPECT_EQ(m.cell_region(c), m.cell_type(c) == CellType::Quad9 ? 1 : 2);
    EXPECT_GT(m.cell_source_tag(c), 0);
  }
  EXPECT_EQ(m.boundary_part_names(), (std::vector<std::string>{"bottom", "left", "right", "top"}));
  for (const Index n : m.boundary_part_nodes("bottom")) EXPECT_NEAR(m.node(n)(1), 0.0, 1e-14);
  for (const Index n : m.boundary_part_nodes("right")) EXPECT_NEAR(m.node(n)(0), 2.0, 1e-14);
  // Quadratic edges: 2 k + 1 nodes on a side of k edges (the left side has 4).
  EXPECT_EQ(m.boundary_part_nodes("left").size(), 9u);
  // The binary files hold the doubles themselves and agree to the last bit; Gmsh writes 16
  // significant digits in ASCII, which do not always give the same double back.
  const Mesh b41 = read_gmsh_mesh(data("mixed_msh41_bin.msh"));
  EXPECT_EQ(read_gmsh_mesh(data("mixed_msh22_bin.msh")).coordinates(), b41.coordinates());
  EXPECT_LT((m.coordinates() - b41.coordinates()).cwiseAbs().maxCoeff(), 1e-15);
  for (const char* other : {"mixed_msh41_bin.msh", "mixed_msh22.msh", "mixed_msh22_bin.msh"}) {
    const Mesh o = read_gmsh_mesh(data(other));
    ASSERT_EQ(o.num_nodes(), m.num_nodes()) << other;
    ASSERT_EQ(o.num_cells(), m.num_cells()) << other;
    EXPECT_LT((o.coordinates() - m.coordinates()).cwiseAbs().maxCoeff(), 1e-15) << other;
    for (Index c = 0; c < m.num_cells(); ++c) {
      ASSERT_EQ(o.cell_type(c), m.cell_type(c)) << other;
      EXPECT_TRUE(std::equal(o.cell(c).begin(), o.cell(c).end(), m.cell(c).begin())) << other;
      EXPECT_EQ(o.cell_region(c), m.cell_region(c)) << other;
    }
    for (const auto& name : m.boundary_part_names())
      EXPECT_EQ(o.boundary_part_nodes(name), m.boundary_part_nodes(name)) << other << " " << name;
  }
}

TEST(GmshReader, CellsAreCounterclockwiseAndPassThePatchTest) {
  const Mesh m = read_gmsh_mesh(data("mixed_msh22_bin.msh"));
  // Rollers on the left and the bottom, a uniform traction on the right: the exact solution is
  // linear, and quadratic cells on a Gmsh mesh reproduce it.
  ElasticityOptions opt;
  opt.material = {1000.0, 0.3};
  const double sigma = 2.5;
  const Vector full = testing::solve_uniaxial_tension(m, opt, sigma);  // throws on a clockwise cell
  const double E = opt.material.E, nu = opt.material.nu;
  for (Index n = 0; n < m.num_nodes(); ++n) {
    EXPECT_NEAR(full(2 * n), (1.0 - nu * nu) / E * sigma * m.node(n)(0), 1e-12);
    EXPECT_NEAR(full(2 * n + 1), -nu * (1.0 + nu) / E * sigma * m.node(n)(1), 1e-12);
  }
}

TEST(GmshReader, ClockwiseCellsAreTurned) {
  // One quadrilateral, clockwise, and its bottom edge as a physical line.
  const std::string msh =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n1\n1 7 \"base\"\n$EndPhysicalNames\n"
      "$Nodes\n4\n1 0 0 0\n2 0 1 0\n3 1 1 0\n4 1 0 0\n$EndNodes\n"
      "$Elements\n2\n1 3 2 0 1 1 2 3 4\n2 1 2 7 1 4 1\n$EndElements\n";
  const Mesh m = parse_gmsh_mesh(msh, "cw.msh");
  const auto v = m.cell(0);
  double area2 = 0.0;
  for (std::size_t a = 0; a < 4; ++a) {
    const auto p = m.node(v[a]), q = m.node(v[(a + 1) % 4]);
    area2 += p(0) * q(1) - q(0) * p(1);
  }
  EXPECT_NEAR(area2, 2.0, 1e-15);
  EXPECT_EQ(m.boundary_part("base").facets.size(), 1u);
  // Outward: the facet runs from (0,0) to (1,0), the body on its left.
  const auto fn = m.facet_nodes(m.boundary_part("base").facets[0]);
  EXPECT_EQ(m.node(fn[0])(0), 0.0);
  EXPECT_EQ(m.node(fn[1])(0), 1.0);
  EXPECT_EQ(m.region_names(), (std::vector<std::string>{""}));  // no physical surface
}

TEST(GmshReader, BadFilesAreNamedWithTheLine) {
  const std::string head = "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n";
  const std::string nodes = "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 0\n$EndNodes\n";
  EXPECT_EQ(error_of(""), "bad.msh:1: empty file: not a Gmsh mesh file");
  EXPECT_EQ(error_of("$Nodes\n"),
            "bad.msh:1: the file does not start with $MeshFormat: not a "
            "Gmsh mesh file");
  EXPECT_EQ(error_of("$MeshFormat\n4.0 0 8\n$EndMeshFormat\n"),
            "bad.msh:2: format 4.0 is not supported: save the mesh as 4.1 or 2.2 (Gmsh: "
            "-format msh41 or msh22)");
  // A truncated file, an unsupported and a 3D element, an undefined node, an odd line.
  EXPECT_EQ(error_of(head + "$Nodes\n3\n1 0 0 0\n2 1"),
            "bad.msh:7: file ends where a node coordinate was expected (truncated?)");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 20 2 0 1 1 2 3 1 2 3 1 2 3\n$EndElements\n"),
            "bad.msh:11: element 5 has Gmsh type 20, which is not supported (supported: lines of "
            "2 and 3 nodes, triangles of 3 and 6, quadrilaterals of 4, 8 and 9)");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 4 2 0 1 1 2 3 1\n$EndElements\n"),
            "bad.msh:11: element 5 is a 3D element (Gmsh type 4): 3D meshes are not supported yet");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 2 2 0 1 1 2 9\n$EndElements\n"),
            "bad.msh: element 5 uses node 9, which $Nodes does not define");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n2\n5 2 2 0 1 1 2 3\n6 1 2 4 1 2 9\n$EndElements\n"),
            "bad.msh: element 6 uses node 9, which $Nodes does not define");
  EXPECT_EQ(error_of(head + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n$EndNodes\n" +
                     "$Elements\n2\n5 2 2 0 1 1 2 3\n6 1 2 4 1 2 4\n$EndElements\n"),
            "bad.msh: line element 6 (physical group '4') is not an edge of any 2D element");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 1 2 4 1 1 2\n$EndElements\n"),
            "bad.msh: no 2D elements (triangles or quadrilaterals): is it meshed in 2D (gmsh -2)?");
  EXPECT_EQ(error_of(head + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 1\n$EndNodes\n" +
                     "$Elements\n1\n5 2 2 0 1 1 2 3\n$EndElements\n"),
            "bad.msh: the 2D elements do not lie in one plane z = constant (z from 0.000000 to "
            "1.000000)");
  EXPECT_EQ(error_of(head + nodes), "bad.msh:10: the file has no $Elements section");
  // A binary file cut short names the byte.
  const std::string bin = text_of(data("mixed_msh41_bin.msh"));
  const std::string cut = error_of(bin.substr(0, bin.size() / 2));
  EXPECT_EQ(cut.rfind("bad.msh: byte ", 0), 0u) << cut;
  EXPECT_NE(cut.find("truncated"), std::string::npos) << cut;
  EXPECT_THROW((void)read_gmsh_mesh(data("no_such_file.msh")), InputError);
}

// Every prefix of a file (a truncated download, a disk that filled up) and files with bytes
// overwritten either read or give an InputError: never a crash, a hang or another exception (run
// under the asan-ubsan preset too).
TEST(GmshReader, TruncatedAndCorruptedFilesAreInputErrors) {
  for (const char* name : {"mixed_msh41_bin.msh", "mixed_msh22_bin.msh", "mixed_msh41.msh"}) {
    const std::string full = text_of(data(name));
    int errors = 0;
    for (std::size_t cut = 0; cut < full.size(); cut += 13) {
      try {
        (void)parse_gmsh_mesh(full.substr(0, cut), "cut.msh");
      } catch (const InputError&) {
        ++errors;
      }
    }
    EXPECT_GT(errors, 0) << name;
    // Bytes overwritten with values that make counts, tags and types absurd.
    std::uint32_t state = 12345;
    for (int trial = 0; trial < 400; ++trial) {
      std::string bad = full;
      for (int k = 0; k < 4; ++k) {
        state = state * 1664525u + 1013904223u;
        bad[state % bad.size()] = static_cast<char>((state >> 8) & 0xff);
      }
      try {
        (void)parse_gmsh_mesh(bad, "bad.msh");
      } catch (const InputError&) {
      }
    }
  }
}

// Materials per region: the left half of the mixed mesh (region "quads") twice as stiff as the
// right ("triangles"), nu = 0 in both (so that the lateral strains, 0, agree across the
// interface). Under a uniform traction sigma each half strains uniformly by its own modulus, so
// u_x is piecewise linear with a kink at x = 1, which both meshes represent exactly.
TEST(GmshReader, MaterialsPerRegionGiveEachItsStrain) {
  const Mesh m = read_gmsh_mesh(data("mixed_msh41.msh"));
  ElasticityOptions opt;
  opt.material = {1000.0, 0.0};  // the triangles (region 2) keep it
  opt.region_materials.resize(2);
  opt.region_materials[1] = IsotropicMaterial{2000.0, 0.0};  // "quads"
  EXPECT_EQ(material_of_region(opt, 1).E, 2000.0);
  EXPECT_EQ(material_of_region(opt, 2).E, 1000.0);
  const double sigma = 2.5;
  const Vector full = testing::solve_uniaxial_tension(m, opt, sigma);
  const double factor = sigma;  // e_xx = sigma / E with nu = 0
  for (Index n = 0; n < m.num_nodes(); ++n) {
    const double x = m.node(n)(0);
    const double expected =
        x <= 1.0 ? factor / 2000.0 * x : factor / 2000.0 + factor / 1000.0 * (x - 1.0);
    EXPECT_NEAR(full(2 * n), expected, 1e-12) << "node " << n << " at x = " << x;
  }
  // The stresses are uniform across the interface: sigma_xx = sigma in both materials.
  const NodalStress s = nodal_stress(m, opt, full);
  for (Index n = 0; n < m.num_nodes(); ++n) EXPECT_NEAR(s.sigma(0, n), sigma, 1e-9);
}

}  // namespace
}  // namespace signorini

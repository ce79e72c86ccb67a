// The Gmsh reader: one mixed, second-order mesh written by Gmsh in the formats 2.2 and 4.1, ASCII
// and binary (tests/mesh/data/mixed.geo), reads to the same mesh in all four; cells, regions and
// boundary parts come out as documented in gmsh_reader.hpp; a solve on it passes the patch test;
// and every kind of bad file gets one line naming the file and the place. 3D: hand-written
// tetrahedra and a hexahedron, and boxes meshed by the gmsh program (where installed) with
// tetrahedra and hexahedra of both orders, read with their regions and boundary faces.

#include "signorini/mesh/gmsh_reader.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>

#include "fem/uniaxial_tension.hpp"
#include "mesh/cell_geometry.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/problem/model.hpp"
#include "temporary_folder.hpp"

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
  // A truncated file, an unsupported 2D and 3D element, an undefined node, an odd line.
  EXPECT_EQ(error_of(head + "$Nodes\n3\n1 0 0 0\n2 1"),
            "bad.msh:7: file ends where a node coordinate was expected (truncated?)");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 20 2 0 1 1 2 3 1 2 3 1 2 3\n$EndElements\n"),
            "bad.msh:11: element 5 has Gmsh type 20, which is not supported (supported: lines of "
            "2 and 3 nodes, triangles of 3 and 6, quadrilaterals of 4, 8 and 9)");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 6 2 0 1 1 2 3 1 2 3\n$EndElements\n"),
            "bad.msh:11: element 5 has Gmsh type 6, a 3D element that is not supported "
            "(supported: tetrahedra of 4 and 10 nodes, hexahedra of 8 and 27)");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 2 2 0 1 1 2 9\n$EndElements\n"),
            "bad.msh: element 5 uses node 9, which $Nodes does not define");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n2\n5 2 2 0 1 1 2 3\n6 1 2 4 1 2 9\n$EndElements\n"),
            "bad.msh: element 6 uses node 9, which $Nodes does not define");
  EXPECT_EQ(error_of(head + "$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 1 1 0\n$EndNodes\n" +
                     "$Elements\n2\n5 2 2 0 1 1 2 3\n6 1 2 4 1 2 4\n$EndElements\n"),
            "bad.msh: line element 6 (physical group '4') is not an edge of any 2D element");
  EXPECT_EQ(error_of(head + nodes + "$Elements\n1\n5 1 2 4 1 1 2\n$EndElements\n"),
            "bad.msh: no 2D elements (triangles or quadrilaterals), only lines: where a geometry "
            "has physical groups, Gmsh saves only their elements, so the body's surfaces need one "
            "too (e.g. Physical Surface(\"body\") = {1};)");
  EXPECT_EQ(error_of(head + "$Nodes\n3\n1 0 0 0\n2 1 0 0\n3 0 1 1\n$EndNodes\n" +
                     "$Elements\n1\n5 2 2 0 1 1 2 3\n$EndElements\n"),
            "bad.msh: the 2D elements do not lie in one plane z = constant (z from 0.000000 to "
            "1.000000); if it is a 3D body, its volumes need a physical group too (e.g. Physical "
            "Volume(\"body\") = {1};): where a geometry has physical groups, Gmsh saves only "
            "their elements");
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

// The fuzzer's find (tests/fuzz/run.sh gmsh_reader): a binary 2.2 element block whose header
// announces 2^31 - 1 tags per element overflowed the int in which the reader sized the block
// (UBSan, under the asan-ubsan preset); it is a block the rest of the file cannot hold.
TEST(GmshReader, ABlockOfAbsurdlyManyTagsIsAnInputError) {
  std::string bin = text_of(data("mixed_msh22_bin.msh"));
  const std::size_t section = bin.find("$Elements\n");
  ASSERT_NE(section, std::string::npos);
  const std::size_t block = bin.find('\n', section + 10) + 1;  // after the element count
  const std::int32_t many = 2147483647;  // the header: type, count, tags per element
  std::memcpy(&bin[block + 8], &many, sizeof many);
  const std::string message = error_of(bin);
  EXPECT_NE(message.find("more than the rest of the file can hold"), std::string::npos) << message;
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

// 3D -----------------------------------------------------------------------------------------

// The checks every 3D mesh of a box [0, a] x [0, b] x [0, c] passes: positive cells filling it,
// straight second-order cells with their middle nodes in the middle, and each named side with
// its facets on the side's plane, outward, covering its area.
struct BoxSide {
  const char* name;
  int axis;
  double value, sign, area;
};
void expect_box(const Mesh& m, double volume, const std::vector<BoxSide>& sides,
                const std::string& what) {
  ASSERT_EQ(m.dim(), 3) << what;
  double sum = 0.0;
  for (Index c = 0; c < m.num_cells(); ++c) {
    for (const double d : testing::corner_dets(m, c)) EXPECT_GT(d, 0.0) << what << " cell " << c;
    sum += testing::cell_volume(m, c);
    EXPECT_LT(testing::middle_node_error(m, c), 1e-12) << what << " cell " << c;
  }
  EXPECT_NEAR(sum, volume, 1e-12 * volume) << what;
  for (const BoxSide& s : sides) {
    double area = 0.0;
    for (const Facet& f : m.boundary_part(s.name).facets) {
      for (const Index n : m.facet_nodes(f))
        EXPECT_NEAR(m.point(n)(s.axis), s.value, 1e-14) << what << " " << s.name;
      EXPECT_GT(testing::facet_normal(m, f)(s.axis) * s.sign, 0.0) << what << " " << s.name;
      area += testing::facet_area(m, f);
    }
    EXPECT_NEAR(area, s.area, 1e-12 * s.area) << what << " " << s.name;
  }
}

// The unit cube in six tetrahedra around its diagonal from node 1 to node 7 (nodes 1..8 at the
// corners in the Hex8 order), its bottom and top as physical surfaces (the triangles written
// with either orientation), the cube as a physical volume, a triangle of the side x = 0 in no
// group and a line in a group (both ignored in 3D). `tets[k]` replaces the k-th tetrahedron,
// `more` adds elements.
std::string tet_cube(const std::map<int, std::string>& tets = {}, const std::string& more = "") {
  std::vector<std::string> elements{"1 2 2 1 1 1 3 2",    "2 2 2 1 1 1 4 3",   "3 2 2 2 2 5 6 7",
                                    "4 2 2 2 2 5 7 8",    "5 4 2 3 1 1 2 3 7", "6 4 2 3 1 1 4 8 7",
                                    "7 4 2 3 1 1 5 6 7",  "8 4 2 3 1 1 6 2 7", "9 4 2 3 1 1 3 4 7",
                                    "10 4 2 3 1 1 8 5 7", "11 2 2 0 1 1 4 8",  "12 1 2 4 1 1 2"};
  for (const auto& [k, tet] : tets) elements[static_cast<std::size_t>(4 + k)] = tet;
  if (!more.empty()) elements.push_back(more);
  std::string text =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$PhysicalNames\n3\n2 1 \"bottom\"\n2 2 \"top\"\n"
      "3 3 \"cube\"\n$EndPhysicalNames\n$Nodes\n8\n1 0 0 0\n2 1 0 0\n3 1 1 0\n4 0 1 0\n"
      "5 0 0 1\n6 1 0 1\n7 1 1 1\n8 0 1 1\n$EndNodes\n$Elements\n" +
      std::to_string(elements.size()) + "\n";
  for (const std::string& e : elements) text += e + "\n";
  return text + "$EndElements\n";
}

TEST(GmshReader, TetrahedraWithPhysicalSurfacesAndVolume) {
  const Mesh m = parse_gmsh_mesh(tet_cube(), "cube.msh");
  EXPECT_EQ(m.num_nodes(), 8);
  EXPECT_EQ(m.num_cells(), 6);
  EXPECT_EQ(m.cell_types(), std::vector<CellType>{CellType::Tet4});
  EXPECT_EQ(m.region_names(), (std::vector<std::string>{"", "cube"}));
  for (Index c = 0; c < m.num_cells(); ++c) {
    EXPECT_EQ(m.cell_region(c), 1);
    EXPECT_GE(m.cell_source_tag(c), 5);
    EXPECT_LE(m.cell_source_tag(c), 10);
  }
  EXPECT_EQ(m.boundary_part_names(), (std::vector<std::string>{"bottom", "top"}));
  EXPECT_EQ(m.boundary_part("bottom").facets.size(), 2u);
  EXPECT_EQ(m.boundary_part_nodes("top").size(), 4u);
  expect_box(m, 1.0, {{"bottom", 2, 0.0, -1.0, 1.0}, {"top", 2, 1.0, 1.0, 1.0}}, "cube");
}

// One hexahedron, 2 x 1 x 3, in the format 4.1 (physical groups through $Entities), its base as
// a physical surface written upwards (into the cell).
std::string hex_41(const std::string& hex_nodes) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$PhysicalNames\n2\n2 1 \"base\"\n3 2 \"brick\"\n"
         "$EndPhysicalNames\n$Entities\n0 0 1 1\n1 0 0 0 2 1 0 1 1 0\n1 0 0 0 2 1 3 1 2 0\n"
         "$EndEntities\n$Nodes\n2 8 1 8\n2 1 0 4\n1\n2\n3\n4\n0 0 0\n2 0 0\n2 1 0\n0 1 0\n"
         "3 1 0 4\n5\n6\n7\n8\n0 0 3\n2 0 3\n2 1 3\n0 1 3\n$EndNodes\n"
         "$Elements\n2 2 1 2\n2 1 3 1\n1 1 2 3 4\n3 1 5 1\n2 " +
         hex_nodes + "\n$EndElements\n";
}

TEST(GmshReader, HexahedronInFormat41) {
  const Mesh m = parse_gmsh_mesh(hex_41("1 2 3 4 5 6 7 8"), "hex.msh");
  EXPECT_EQ(m.num_nodes(), 8);
  EXPECT_EQ(m.cell_types(), std::vector<CellType>{CellType::Hex8});
  EXPECT_EQ(m.region_names(), (std::vector<std::string>{"", "brick"}));
  EXPECT_EQ(m.cell_region(0), 1);
  EXPECT_EQ(m.cell_source_tag(0), 2);
  ASSERT_EQ(m.boundary_part("base").facets.size(), 1u);
  EXPECT_EQ(m.boundary_part("base").facets[0].local, 0);  // the face z = -1 of the reference
  expect_box(m, 6.0, {{"base", 2, 0.0, -1.0, 2.0}}, "hex");
}

TEST(GmshReader, Bad3DFilesAreNamedWithTheElement) {
  // A tetrahedron and a hexahedron turned inside out (two nodes swapped; top and bottom
  // swapped), a degenerate one, and a triangle in a physical surface that no tetrahedron has.
  EXPECT_EQ(error_of(tet_cube({{3, "8 4 2 3 1 1 2 6 7"}})),
            "bad.msh: element 8 (tet4) is inverted: det J < 0 at a corner (Gmsh's node order "
            "gives det J > 0)");
  EXPECT_EQ(error_of(hex_41("5 6 7 8 1 2 3 4")),
            "bad.msh: element 2 (hex8) is inverted: det J < 0 at a corner (Gmsh's node order "
            "gives det J > 0)");
  EXPECT_EQ(error_of(tet_cube({{3, "8 4 2 3 1 1 6 2 6"}})),
            "bad.msh: element 8 (tet4) is degenerate: det J = 0 at a corner");
  EXPECT_EQ(error_of(tet_cube({}, "13 2 2 1 1 1 2 4")),
            "bad.msh: surface element 13 (physical group 'bottom') is not a face of any 3D "
            "element");
  // A node tag defined twice (one of its points would be dropped), a tetrahedron given twice.
  std::string twice = tet_cube();
  twice.replace(twice.find("$Nodes\n8\n"), 9, "$Nodes\n9\n7 0.5 0.5 0.5\n");
  EXPECT_EQ(error_of(twice),
            "bad.msh: node 7 is defined twice in $Nodes, at (0.5, 0.5, 0.5) and at (1, 1, 1): "
            "expected each node tag once");
  EXPECT_EQ(error_of(tet_cube({}, "13 4 2 3 1 1 2 3 7")),
            "bad.msh: element 5 and element 13 have the same nodes (a doubled cell, its stiffness "
            "counted twice): expected each cell once");
  // A second-order triangle on first-order tetrahedra: its middle nodes are not the face's.
  EXPECT_EQ(error_of(tet_cube({}, "13 9 2 2 1 1 2 3 5 6 7")),
            "bad.msh: surface element 13 (physical group 'top') is not a face of any 3D element");
}

// Boxes meshed by the gmsh program: tetrahedra (an unstructured mesh) and hexahedra (a
// transfinite one), of the first and second order, in the formats 4.1 and 2.2, ASCII and binary.
TEST(GmshReader, BoxesMeshedByGmsh) {
  if (std::system("command -v gmsh > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "the gmsh program is not installed (apt-get install gmsh)";
  const testing::TemporaryFolder dir;
  const std::string sides =
      "e = 1e-6;\n"
      "Physical Surface(\"bottom\") = Surface In BoundingBox{-e, -e, -e, 2 + e, 1 + e, e};\n"
      "Physical Surface(\"top\") = Surface In BoundingBox{-e, -e, 1 - e, 2 + e, 1 + e, 1 + e};\n"
      "Physical Volume(\"solid\") = {1};\n";
  std::ofstream(dir / "tet.geo") << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n"
                                 << sides << "Mesh.MeshSizeMax = 0.5;\n";
  std::ofstream(dir / "hex.geo") << "SetFactory(\"OpenCASCADE\");\nBox(1) = {0, 0, 0, 2, 1, 1};\n"
                                 << "Transfinite Curve{:} = 3;\nTransfinite Surface{:};\n"
                                    "Recombine Surface{:};\nTransfinite Volume{:};\n"
                                 << sides;
  const auto mesh = [&](const std::string& geo, const std::string& options,
                        const std::string& out) {
    const std::string command = "gmsh -3 " + options + " '" + (dir / geo).string() + "' -o '" +
                                (dir / out).string() + "' -v 0 > /dev/null 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << command;
    return read_gmsh_mesh(dir / out);
  };
  const std::vector<BoxSide> box_sides{{"bottom", 2, 0.0, -1.0, 2.0}, {"top", 2, 1.0, 1.0, 2.0}};
  struct Case {
    const char* geo;
    const char* options;
    CellType type;
  };
  for (const Case& k : {Case{"tet.geo", "-format msh41", CellType::Tet4},
                        Case{"tet.geo", "-order 2 -format msh41", CellType::Tet10},
                        Case{"hex.geo", "-format msh22", CellType::Hex8},
                        Case{"hex.geo", "-order 2 -format msh41 -bin", CellType::Hex27}}) {
    const std::string what = std::string(k.geo) + " " + k.options;
    const Mesh m = mesh(k.geo, k.options, "out.msh");
    EXPECT_EQ(m.cell_types(), std::vector<CellType>{k.type}) << what;
    EXPECT_EQ(m.region_names(), (std::vector<std::string>{"", "solid"})) << what;
    for (Index c = 0; c < m.num_cells(); ++c) EXPECT_EQ(m.cell_region(c), 1) << what;
    EXPECT_EQ(m.boundary_part_names(), (std::vector<std::string>{"bottom", "top"})) << what;
    expect_box(m, 2.0, box_sides, what);
    if (k.type == CellType::Hex8 || k.type == CellType::Hex27) {
      // 2 x 2 x 2 bricks on the 3 x 3 x 3 (or 5 x 5 x 5) lattice.
      EXPECT_EQ(m.num_cells(), 8) << what;
      EXPECT_EQ(m.num_nodes(), k.type == CellType::Hex8 ? 27 : 125) << what;
      EXPECT_EQ(m.boundary_part("bottom").facets.size(), 4u) << what;
    }
  }
  // A .geo given as the mesh file is meshed in 3D by the program: the mesh of gmsh -3.
  const auto same_mesh = [](const Mesh& x, const Mesh& y, const std::string& what) {
    ASSERT_EQ(x.num_nodes(), y.num_nodes()) << what;
    ASSERT_EQ(x.num_cells(), y.num_cells()) << what;
    EXPECT_EQ(x.cell_types(), y.cell_types()) << what;
    EXPECT_EQ((x.coordinates() - y.coordinates()).cwiseAbs().maxCoeff(), 0.0) << what;
    for (Index c = 0; c < x.num_cells(); ++c)
      EXPECT_TRUE(std::equal(x.cell(c).begin(), x.cell(c).end(), y.cell(c).begin())) << what;
    for (const auto& name : x.boundary_part_names())
      EXPECT_EQ(y.boundary_part_nodes(name), x.boundary_part_nodes(name)) << what << name;
  };
  for (const char* geo : {"tet.geo", "hex.geo"}) {
    const Mesh from_geo = read_mesh_file(dir / geo);
    EXPECT_EQ(from_geo.dim(), 3) << geo;
    same_mesh(from_geo, mesh(geo, "-format msh41", "geo.msh"), geo);
  }
  // The same second-order tetrahedra from the four formats: the same mesh, node for node and
  // cell for cell.
  const Mesh a = mesh("tet.geo", "-order 2 -format msh41", "a.msh");
  for (const char* options :
       {"-order 2 -format msh41 -bin", "-order 2 -format msh22", "-order 2 -format msh22 -bin"}) {
    const Mesh b = mesh("tet.geo", options, "b.msh");
    ASSERT_EQ(b.num_nodes(), a.num_nodes()) << options;
    ASSERT_EQ(b.num_cells(), a.num_cells()) << options;
    EXPECT_LT((b.coordinates() - a.coordinates()).cwiseAbs().maxCoeff(), 1e-15) << options;
    for (Index c = 0; c < a.num_cells(); ++c)
      EXPECT_TRUE(std::equal(a.cell(c).begin(), a.cell(c).end(), b.cell(c).begin())) << options;
    for (const auto& name : a.boundary_part_names())
      EXPECT_EQ(b.boundary_part_nodes(name), a.boundary_part_nodes(name)) << options << name;
  }
}

// A 3D file meshed in 2D only (no volumes): read as before, as a 2D mesh of its surfaces, which
// here do not lie in one plane.
TEST(GmshReader, SurfacesWithoutVolumesAreA2DMesh) {
  const std::string msh =
      "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n4\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n"
      "$EndNodes\n$Elements\n2\n1 2 2 0 1 1 2 3\n2 2 2 0 2 1 2 4\n$EndElements\n";
  EXPECT_EQ(error_of(msh),
            "bad.msh: the 2D elements do not lie in one plane z = constant (z from 0.000000 to "
            "1.000000); if it is a 3D body, its volumes need a physical group too (e.g. Physical "
            "Volume(\"body\") = {1};): where a geometry has physical groups, Gmsh saves only "
            "their elements");
}

}  // namespace
}  // namespace signorini

// The box generator: counts and numbering, positive cells whose volumes fill the box, six sides
// that cover their faces with outward normals, a conforming mesh whose boundary is exactly the six
// sides, and quadratic nodes at the middle of their edges; for every cell type.

#include "signorini/mesh/box_mesh.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <map>
#include <set>

#include "mesh/cell_geometry.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

using Vec = Eigen::Vector3d;

// The sorted corners of a facet: the same set from either cell that has it.
std::vector<Index> facet_key(const Mesh& m, const Facet& f) {
  const auto nodes = m.facet_nodes(f);
  std::vector<Index> k(nodes.begin(),
                       nodes.begin() + corners_per_cell(facet_type(m.cell_type(f.cell))));
  std::sort(k.begin(), k.end());
  return k;
}

struct Case {
  CellType type;
  Index cells, nodes, zmin_facets;
};

constexpr Index nx = 2, ny = 3, nz = 4;

std::vector<Case> all_cases() {
  const Index linear = (nx + 1) * (ny + 1) * (nz + 1);
  const Index quadratic = (2 * nx + 1) * (2 * ny + 1) * (2 * nz + 1);
  return {{CellType::Hex8, nx * ny * nz, linear, nx * ny},
          {CellType::Hex27, nx * ny * nz, quadratic, nx * ny},
          {CellType::Tet4, 6 * nx * ny * nz, linear, 2 * nx * ny},
          {CellType::Tet10, 6 * nx * ny * nz, quadratic, 2 * nx * ny}};
}

// [-1, 1] x [0.5, 2] x [2, 2.8]: cells of 1 x 0.5 x 0.2.
Mesh box(CellType t) {
  return make_box_mesh({-1.0, 0.5, 2.0, 2.0, 1.5, 0.8, nx, ny, nz, t});
}

std::string name_of(CellType t) {
  return std::string(enum_to_string(kCellTypeNames, t));
}

TEST(BoxMesh, CountsAndNumbering) {
  for (const Case& k : all_cases()) {
    const Mesh m = box(k.type);
    const std::string name = name_of(k.type);
    EXPECT_EQ(m.dim(), 3) << name;
    EXPECT_EQ(m.cell_types(), std::vector<CellType>{k.type}) << name;
    EXPECT_EQ(m.num_cells(), k.cells) << name;
    EXPECT_EQ(m.num_nodes(), k.nodes) << name;
    std::vector<char> used(static_cast<std::size_t>(m.num_nodes()), 0);
    for (Index c = 0; c < m.num_cells(); ++c)
      for (const Index v : m.cell(c)) used[static_cast<std::size_t>(v)] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 1), m.num_nodes()) << name;
    EXPECT_EQ(m.boundary_part_names(),
              (std::vector<std::string>{"xmax", "xmin", "ymax", "ymin", "zmax", "zmin"}));
    EXPECT_EQ(static_cast<Index>(m.boundary_part("zmin").facets.size()), k.zmin_facets) << name;
    EXPECT_EQ(m.point(m.num_nodes() - 1), Vec(1.0, 2.0, 2.8)) << name;  // far sides land exactly
  }
  // Hex8: node (i, j, k) is i + (nx + 1) (j + (ny + 1) k), cell (i, j, k) is i + nx (j + ny k)
  // with corner 0 at node (i, j, k).
  const Mesh m = box(CellType::Hex8);
  for (Index k = 0; k <= nz; ++k)
    for (Index j = 0; j <= ny; ++j)
      for (Index i = 0; i <= nx; ++i) {
        const Index n = i + (nx + 1) * (j + (ny + 1) * k);
        const Vec expected(-1.0 + 1.0 * static_cast<double>(i), 0.5 + 0.5 * static_cast<double>(j),
                           2.0 + 0.2 * static_cast<double>(k));
        EXPECT_LT((m.point(n) - expected).norm(), 1e-14) << n;
        if (i < nx && j < ny && k < nz) {
          EXPECT_EQ(m.cell(i + nx * (j + ny * k))[0], n);
        }
      }
}

TEST(BoxMesh, CellsArePositiveAndFillTheBox) {
  for (const Case& k : all_cases()) {
    const Mesh m = box(k.type);
    double volume = 0.0;
    for (Index c = 0; c < m.num_cells(); ++c) {
      for (const double d : testing::corner_dets(m, c))
        EXPECT_GT(d, 0.0) << name_of(k.type) << " cell " << c;
      volume += testing::cell_volume(m, c);
    }
    EXPECT_NEAR(volume, 2.0 * 1.5 * 0.8, 1e-12) << name_of(k.type);
  }
}

TEST(BoxMesh, SidesCoverTheirFacesWithOutwardNormals) {
  struct Side {
    const char* name;
    int axis;
    double value, sign, area;
  };
  const Side sides[] = {{"xmin", 0, -1.0, -1.0, 1.5 * 0.8}, {"xmax", 0, 1.0, 1.0, 1.5 * 0.8},
                        {"ymin", 1, 0.5, -1.0, 2.0 * 0.8},  {"ymax", 1, 2.0, 1.0, 2.0 * 0.8},
                        {"zmin", 2, 2.0, -1.0, 2.0 * 1.5},  {"zmax", 2, 2.8, 1.0, 2.0 * 1.5}};
  for (const Case& k : all_cases()) {
    const Mesh m = box(k.type);
    const std::string name = name_of(k.type);
    for (const Side& s : sides) {
      const auto& facets = m.boundary_part(s.name).facets;
      double area = 0.0;
      for (const Facet& f : facets) {
        for (const Index n : m.facet_nodes(f))
          EXPECT_DOUBLE_EQ(m.point(n)(s.axis), s.value) << name << " " << s.name;
        EXPECT_GT(testing::facet_normal(m, f)(s.axis) * s.sign, 0.0) << name << " " << s.name;
        area += testing::facet_area(m, f);
      }
      EXPECT_NEAR(area, s.area, 1e-12) << name << " " << s.name;
      // Listed in cell order (k, j, i loops).
      EXPECT_TRUE(std::is_sorted(facets.begin(), facets.end(),
                                 [](const Facet& x, const Facet& y) {
                                   return x.cell != y.cell ? x.cell < y.cell : x.local < y.local;
                                 }))
          << name << " " << s.name;
    }
  }
}

TEST(BoxMesh, ConformingWithTheSidesAsTheWholeBoundary) {
  for (const Case& k : all_cases()) {
    const Mesh m = box(k.type);
    const std::string name = name_of(k.type);
    std::map<std::vector<Index>, int> faces;
    for (Index c = 0; c < m.num_cells(); ++c)
      for (int f = 0; f < facets_per_cell(m.cell_type(c)); ++f) ++faces[facet_key(m, {c, f})];
    std::set<std::vector<Index>> boundary;
    for (const auto& [key, count] : faces) {
      EXPECT_LE(count, 2) << name;  // no face of three cells, no overlap
      if (count == 1) boundary.insert(key);
    }
    std::set<std::vector<Index>> parts;
    std::size_t listed = 0;
    for (const std::string& part : m.boundary_part_names())
      for (const Facet& f : m.boundary_part(part).facets) {
        parts.insert(facet_key(m, f));
        ++listed;
      }
    EXPECT_EQ(listed, parts.size()) << name;  // no facet on two sides, none twice
    EXPECT_EQ(parts, boundary) << name;
  }
}

TEST(BoxMesh, QuadraticNodesAreAtTheMiddles) {
  for (const CellType t : {CellType::Hex27, CellType::Tet10}) {
    const Mesh m = box(t);
    for (Index c = 0; c < m.num_cells(); ++c)
      EXPECT_LT(testing::middle_node_error(m, c), 1e-14) << name_of(t) << " cell " << c;
  }
}

TEST(BoxMesh, BadOptionsAreErrors) {
  BoxMeshOptions o;
  o.nz = 0;
  EXPECT_THROW(make_box_mesh(o), InputError);
  o = {};
  o.width = -1.0;
  EXPECT_THROW(make_box_mesh(o), InputError);
  o = {};
  o.height = std::numeric_limits<double>::infinity();
  EXPECT_THROW(make_box_mesh(o), InputError);
  o = {};
  o.cell = CellType::Quad4;
  try {
    (void)make_box_mesh(o);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "box mesh: cell type 'quad4' is not a 3D cell (expected hex8, hex27, tet4 or tet10)");
  }
  EXPECT_EQ(enum_to_string(kBoxCellNames, CellType::Tet10), "tet10");
}

// A part of the box is the whole box's cubes in a range, node for node and to the bit: its nodes
// at their whole numbers' coordinates, its cells those cells with the same nodes, its sides the
// whole sides' facets in the part, in the same order.
TEST(BoxMesh, PartsAreTheWholeBoxsCubes) {
  for (const Case& c : all_cases()) {
    SCOPED_TRACE(name_of(c.type));
    const BoxMeshOptions o{-1.0, 0.5, 2.0, 2.0, 1.5, 0.8, nx, ny, nz, c.type};
    const Mesh whole = make_box_mesh(o);
    for (const auto& [first, end] :
         std::vector<std::pair<std::array<Index, 3>, std::array<Index, 3>>>{
             {{0, 0, 0}, {nx, ny, nz}}, {{1, 0, 2}, {2, 2, 4}}, {{0, 1, 0}, {1, 3, 1}}}) {
      const BoxMeshPart part = make_box_mesh_part(o, first, end);
      const Mesh& m = part.mesh;
      ASSERT_EQ(static_cast<Index>(part.global_nodes.size()), m.num_nodes());
      ASSERT_EQ(static_cast<Index>(part.global_cells.size()), m.num_cells());
      EXPECT_TRUE(std::is_sorted(part.global_nodes.begin(), part.global_nodes.end()));
      for (Index v = 0; v < m.num_nodes(); ++v)
        EXPECT_EQ(m.node(v), whole.node(part.global_nodes[static_cast<std::size_t>(v)]));
      for (Index k = 0; k < m.num_cells(); ++k) {
        const Index g = part.global_cells[static_cast<std::size_t>(k)];
        const auto a = m.cell(k);
        const auto b = whole.cell(g);
        ASSERT_EQ(a.size(), b.size());
        for (std::size_t i = 0; i < a.size(); ++i)
          EXPECT_EQ(part.global_nodes[static_cast<std::size_t>(a[i])], b[i]);
      }
      const Index cubes = (end[0] - first[0]) * (end[1] - first[1]) * (end[2] - first[2]);
      EXPECT_EQ(m.num_cells(), cubes * c.cells / (nx * ny * nz));
      for (const char* side : {"xmin", "xmax", "ymin", "ymax", "zmin", "zmax"}) {
        std::vector<std::pair<Index, int>> expected, got;
        std::set<Index> in_part(part.global_cells.begin(), part.global_cells.end());
        for (const Facet& f : whole.boundary_part(side).facets)
          if (in_part.count(f.cell) != 0) expected.emplace_back(f.cell, f.local);
        for (const Facet& f : m.boundary_part(side).facets)
          got.emplace_back(part.global_cells[static_cast<std::size_t>(f.cell)], f.local);
        EXPECT_EQ(got, expected) << side;
      }
    }
  }
}

}  // namespace
}  // namespace signorini

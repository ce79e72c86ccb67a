// Patch test: a uniform stress state on a mesh of distorted cells of every 2D type (curved ones
// for the quadratic types) is reproduced exactly (displacements and stresses), for plane strain
// and plane stress.

#include <gtest/gtest.h>

#include "fem/uniaxial_tension.hpp"
#include "mesh/moved_mesh.hpp"
#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/linalg/linear_solver.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

// The rectangle (0,2)x(0,1) in 6x4 squares of `type` cells with interior nodes moved off the
// grid by a smooth map (so that quadratic cells get curved edges); boundary nodes stay on their
// edges so that the edges remain straight.
Mesh distorted_rectangle(CellType type = CellType::Quad4) {
  RectangleMeshOptions o{0.0, 0.0, 2.0, 1.0, 6, 4};
  o.cell = type;
  const Mesh grid = make_rectangle_mesh(o);
  Eigen::MatrixXd xy = grid.coordinates();
  for (Index n = 0; n < grid.num_nodes(); ++n) {
    const double x = xy(0, n), y = xy(1, n);
    const bool interior = x > 1e-12 && x < 2.0 - 1e-12 && y > 1e-12 && y < 1.0 - 1e-12;
    // Half the amplitude for quadratic cells, whose nodes are half as far apart, so that the
    // cells stay valid (det J > 0 at every node).
    const double a = 1.0 / cell_order(type);
    if (interior) {
      xy(0, n) += a * 0.09 * std::sin(7.0 * x + 3.0 * y);
      xy(1, n) += a * 0.06 * std::cos(5.0 * x - 4.0 * y);
    }
  }
  return testing::with_coordinates(grid, std::move(xy));
}

class PatchTest : public ::testing::TestWithParam<std::tuple<CellType, PlaneModel>> {};

TEST_P(PatchTest, UniformUniaxialStressIsExact) {
  const auto [type, model] = GetParam();
  const Mesh mesh = distorted_rectangle(type);
  ElasticityOptions opt;
  opt.material = {1000.0, 0.3};
  opt.plane_model = model;
  // Rollers: u_x = 0 on the left, u_y = 0 on the bottom; traction (sigma, 0) on the right.
  const double sigma = 2.5;
  const Vector full = testing::solve_uniaxial_tension(mesh, opt, sigma);

  const double E = opt.material.E, nu = opt.material.nu;
  const bool strain = model == PlaneModel::PlaneStrain;
  const double exx = strain ? (1.0 - nu * nu) / E * sigma : sigma / E;
  const double eyy = strain ? -nu * (1.0 + nu) / E * sigma : -nu * sigma / E;
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    EXPECT_NEAR(full(2 * n), exx * mesh.node(n)(0), 1e-12) << "node " << n;
    EXPECT_NEAR(full(2 * n + 1), eyy * mesh.node(n)(1), 1e-12) << "node " << n;
  }
  const NodalStress s = nodal_stress(mesh, opt, full);
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    EXPECT_NEAR(s.sigma(0, n), sigma, 1e-10);
    EXPECT_NEAR(s.sigma(1, n), 0.0, 1e-10);
    EXPECT_NEAR(s.sigma(2, n), strain ? nu * sigma : 0.0, 1e-10);
    EXPECT_NEAR(s.sigma(3, n), 0.0, 1e-10);
    const double vm = strain ? std::sqrt(sigma * sigma * (1.0 - nu + nu * nu)) : sigma;
    EXPECT_NEAR(s.von_mises(n), vm, 1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(
    CellTypesAndPlaneModels, PatchTest,
    ::testing::Combine(::testing::Values(CellType::Tri3, CellType::Tri6, CellType::Quad4,
                                         CellType::Quad8, CellType::Quad9),
                       ::testing::Values(PlaneModel::PlaneStrain, PlaneModel::PlaneStress)),
    [](const auto& param_info) {
      return std::string(enum_to_string(kCellTypeNames, std::get<0>(param_info.param))) + "_" +
             std::string(enum_to_string(kPlaneModelNames, std::get<1>(param_info.param)));
    });

// A mesh of triangles and quadrilaterals of both orders in one: the patch test again, through
// the mixed-type Mesh and every element in one assembly.
TEST(PatchTestMixed, TrianglesAndQuadrilateralsOfBothOrdersTogether) {
  // Quadrilaterals left of x = 1, triangles right of it, over the same nodes: Quad4 with Tri3,
  // and Quad9 with Tri6 (conforming: the same quadratic edges on x = 1).
  for (const bool quadratic : {false, true}) {
    const Mesh lin = distorted_rectangle(quadratic ? CellType::Quad9 : CellType::Quad4);
    const Mesh tri = distorted_rectangle(quadratic ? CellType::Tri6 : CellType::Tri3);
    // Take lin's cells in the left half and, over the same nodes, tri's in the right half: both
    // meshes number the lattice the same way (Quad9 and Tri6 use every lattice point).
    ASSERT_EQ(lin.num_nodes(), tri.num_nodes());
    std::vector<CellType> types;
    std::vector<Index> cells;
    const auto centre_x = [](const Mesh& m, Index c) {
      double x = 0.0;
      for (const Index v : m.cell(c)) x += m.node(v)(0);
      return x / static_cast<double>(m.cell(c).size());
    };
    for (Index c = 0; c < lin.num_cells(); ++c)
      if (centre_x(lin, c) < 1.0) {
        types.push_back(lin.cell_type(c));
        cells.insert(cells.end(), lin.cell(c).begin(), lin.cell(c).end());
      }
    const Index first_tri = static_cast<Index>(types.size());
    for (Index c = 0; c < tri.num_cells(); ++c)
      if (centre_x(tri, c) > 1.0) {
        types.push_back(tri.cell_type(c));
        cells.insert(cells.end(), tri.cell(c).begin(), tri.cell(c).end());
      }
    Mesh mesh(types, lin.coordinates(), cells);
    if (!quadratic) {
      EXPECT_EQ(mesh.cell_types(), (std::vector<CellType>{CellType::Tri3, CellType::Quad4}));
    } else {
      EXPECT_EQ(mesh.cell_types(), (std::vector<CellType>{CellType::Tri6, CellType::Quad9}));
    }
    // Rollers on the left (x = 0) and bottom (y = 0), traction (sigma, 0) on the right (x = 2),
    // taken from tri's facets there.
    std::vector<Facet> left, bottom, right;
    const auto remap = [&](const Mesh& from, const Facet& f, Index offset) {
      // The same cell in `mesh`: cells of `from` kept in order after `offset`.
      Index kept = 0;
      for (Index c = 0; c < f.cell; ++c)
        if ((offset == 0) == (centre_x(from, c) < 1.0)) ++kept;
      return Facet{offset + kept, f.local};
    };
    for (const Facet& f : lin.boundary_part("left").facets) left.push_back(remap(lin, f, 0));
    for (const Facet& f : lin.boundary_part("bottom").facets)
      if (centre_x(lin, f.cell) < 1.0) bottom.push_back(remap(lin, f, 0));
    for (const Facet& f : tri.boundary_part("bottom").facets)
      if (centre_x(tri, f.cell) > 1.0) bottom.push_back(remap(tri, f, first_tri));
    for (const Facet& f : tri.boundary_part("right").facets)
      right.push_back(remap(tri, f, first_tri));
    mesh.set_boundary_part("left", left);
    mesh.set_boundary_part("bottom", bottom);
    mesh.set_boundary_part("right", right);

    ElasticityOptions opt;
    opt.material = {1000.0, 0.3};
    const double sigma = 2.5;
    const Vector full = testing::solve_uniaxial_tension(mesh, opt, sigma);
    const double E = opt.material.E, nu = opt.material.nu;
    const double exx = (1.0 - nu * nu) / E * sigma, eyy = -nu * (1.0 + nu) / E * sigma;
    for (Index n = 0; n < mesh.num_nodes(); ++n) {
      EXPECT_NEAR(full(2 * n), exx * mesh.node(n)(0), 1e-12) << "node " << n;
      EXPECT_NEAR(full(2 * n + 1), eyy * mesh.node(n)(1), 1e-12) << "node " << n;
    }
  }
}

TEST(Assembly, StiffnessIsSymmetricAndLoadsBalance) {
  const Mesh mesh = distorted_rectangle();
  ElasticityOptions opt;
  const DofMap dofs = make_dof_map(mesh, {{"left", {true, true, true}}});
  const SparseMatrix A = assemble_stiffness(mesh, dofs, opt);
  EXPECT_LT((A - SparseMatrix(A.transpose())).norm(), 1e-12 * A.norm());
  // A linear traction p = (0, -(3 - x)) on the top edge (0,2) integrates exactly with 2 points:
  // total vertical load = -int_0^2 (3 - x) dx = -4, plus nothing clamped on that edge but x = 0.
  const DofMap none = make_dof_map(mesh, {});
  Vector b = Vector::Zero(none.num_free());
  add_traction_load(
      mesh, none, mesh.boundary_part("top"),
      [](const Point& x) { return Eigen::Vector3d(0.0, -(3.0 - x(0)), 0.0); }, 2, b);
  double fy = 0.0, moment = 0.0;
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    fy += b(2 * n + 1);
    moment += b(2 * n + 1) * mesh.node(n)(0);
  }
  EXPECT_NEAR(fy, -4.0, 1e-13);
  EXPECT_NEAR(moment, -(3.0 * 2.0 - 8.0 / 3.0), 1e-13);  // -int_0^2 x (3 - x) dx
}

TEST(Assembly, NonFiniteLoadIsReported) {
  const Mesh mesh = make_rectangle_mesh({0.0, 0.0, 1.0, 1.0, 2, 2});
  const DofMap dofs = make_dof_map(mesh, {{"left", {true, true, true}}});
  Vector b = Vector::Zero(dofs.num_free());
  EXPECT_THROW(
      add_traction_load(
          mesh, dofs, mesh.boundary_part("top"),
          [](const Point& x) { return Eigen::Vector3d(0.0, 1.0 / (x(0) - 0.25), 0.0); }, 1, b),
      InputError);
}

}  // namespace
}  // namespace signorini

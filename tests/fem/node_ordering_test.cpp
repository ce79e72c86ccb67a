// Unknowns numbered along the Z-order curve (fem/node_ordering.hpp, DofMap::finalize with a node
// order): the order itself, the numbering, the stiffness assembled in it (the same matrix,
// permuted), and the smoothed-aggregation hierarchy built on it (levels of the same sizes: the
// aggregation follows the nodes' own numbers, not the unknowns' order).

#include "signorini/fem/node_ordering.hpp"

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

TEST(ZOrder, VisitsTheCornersOfACubeInMortonOrder) {
  // The 2 x 2 x 2 nodes of one hex8 cube, numbered x fastest, then y, then z: Morton order
  // interleaves the bits as (z y x), which is that same order.
  BoxMeshOptions box;
  box.nx = box.ny = box.nz = 1;
  const Mesh cube = make_box_mesh(box);
  const std::vector<Index> order = z_order(cube);
  ASSERT_EQ(order.size(), 8U);
  for (Index i = 0; i < 8; ++i) {
    const Point x = cube.point(order[static_cast<std::size_t>(i)]);
    EXPECT_EQ(x(0), static_cast<double>(i & 1)) << i;
    EXPECT_EQ(x(1), static_cast<double>((i >> 1) & 1)) << i;
    EXPECT_EQ(x(2), static_cast<double>((i >> 2) & 1)) << i;
  }
  // On a larger block: a permutation that differs from the row-by-row numbering, and whose
  // consecutive nodes are close (the first eight are the cube at the origin).
  box.nx = box.ny = box.nz = 4;
  const Mesh block = make_box_mesh(box);
  std::vector<Index> o = z_order(block);
  ASSERT_EQ(static_cast<Index>(o.size()), block.num_nodes());
  EXPECT_FALSE(std::is_sorted(o.begin(), o.end()));
  for (Index i = 0; i < 8; ++i)
    EXPECT_LE(block.point(o[static_cast<std::size_t>(i)]).maxCoeff(), 0.25 + 1e-15);
  std::sort(o.begin(), o.end());
  for (Index i = 0; i < block.num_nodes(); ++i) EXPECT_EQ(o[static_cast<std::size_t>(i)], i);
}

TEST(DofMapNodeOrder, NumbersTheFreeDofsNodeByNodeInTheGivenOrder) {
  DofMap dofs(3, 2);
  dofs.clamp(1, 0);
  dofs.finalize({2, 0, 1});
  EXPECT_EQ(dofs.free_index(2, 0), 0);
  EXPECT_EQ(dofs.free_index(2, 1), 1);
  EXPECT_EQ(dofs.free_index(0, 0), 2);
  EXPECT_EQ(dofs.free_index(0, 1), 3);
  EXPECT_EQ(dofs.free_index(1, 0), -1);
  EXPECT_EQ(dofs.free_index(1, 1), 4);
  EXPECT_EQ(dofs.num_free(), 5);
  EXPECT_EQ(dofs.node_place(2), 0);
  EXPECT_EQ(dofs.node_place(1), 2);
  DofMap twice(3, 2);
  EXPECT_THROW(twice.finalize({0, 0, 1}), std::logic_error);
  DofMap short_order(3, 2);
  EXPECT_THROW(short_order.finalize({0, 1}), std::logic_error);
}

// The stiffness of a block of tetrahedra clamped on one face, numbered row by row and in
// Z-order: the same matrix up to the permutation of the unknowns, each column's rows sorted.
struct TwoNumberings {
  Mesh mesh;
  DofMap plain, ordered;
  SparseMatrix A, Az;
  std::vector<Index> to_ordered;  // free dof in `plain` -> free dof in `ordered`
};

TwoNumberings two_numberings(CellType cell) {
  BoxMeshOptions box;
  box.nx = 5;
  box.ny = 4;
  box.nz = 3;
  box.cell = cell;
  ClampSpec bottom;
  bottom.boundary = "zmin";
  const Mesh mesh = make_box_mesh(box);
  TwoNumberings t{
      mesh, make_dof_map(mesh, {bottom}), make_dof_map(mesh, {bottom}, {}, z_order(mesh)), {}, {},
      {}};
  ElasticityOptions elasticity;
  elasticity.material = {1000.0, 0.3};
  t.A = assemble_stiffness(t.mesh, t.plain, elasticity);
  t.Az = assemble_stiffness(t.mesh, t.ordered, elasticity);
  t.to_ordered.assign(static_cast<std::size_t>(t.plain.num_free()), -1);
  for (Index a = 0; a < t.mesh.num_nodes(); ++a)
    for (int k = 0; k < 3; ++k)
      if (t.plain.free_index(a, k) >= 0)
        t.to_ordered[static_cast<std::size_t>(t.plain.free_index(a, k))] =
            t.ordered.free_index(a, k);
  return t;
}

TEST(ZOrderAssembly, TheStiffnessIsTheSameMatrixPermuted) {
  for (const CellType cell : {CellType::Hex8, CellType::Tet4}) {
    const TwoNumberings t = two_numberings(cell);
    ASSERT_EQ(t.A.rows(), t.Az.rows());
    ASSERT_EQ(t.A.nonZeros(), t.Az.nonZeros());
    for (Index j = 0; j < t.Az.outerSize(); ++j) {
      Index previous = -1;
      for (SparseMatrix::InnerIterator it(t.Az, j); it; ++it) {
        EXPECT_GT(it.row(), previous) << "column " << j;
        previous = it.row();
      }
    }
    double largest = 0.0, difference = 0.0;
    for (Index j = 0; j < t.A.outerSize(); ++j)
      for (SparseMatrix::InnerIterator it(t.A, j); it; ++it) {
        const double z = t.Az.coeff(t.to_ordered[static_cast<std::size_t>(it.row())],
                                    t.to_ordered[static_cast<std::size_t>(j)]);
        difference = std::max(difference, std::abs(z - it.value()));
        largest = std::max(largest, std::abs(it.value()));
      }
    EXPECT_LT(difference, 1e-13 * largest);
  }
}

TEST(ZOrderAssembly, SmoothedAggregationFormsLevelsOfTheSameSizes) {
  // Aggregated in the nodes' own order whatever the unknowns' order: the same level sizes, and
  // coarse operators with nearly the same spectra. Not the same to rounding: the damping of the
  // smoothed prolongation comes from a Lanczos estimate of rho(D^-1 A) whose start vector is
  // laid out in the unknowns' order (12 steps: the estimates differ by some 1e-4).
  const TwoNumberings t = two_numberings(CellType::Hex8);
  SmoothedAggregationOptions o;
  o.max_coarse_unknowns = 60;
  const MultigridHierarchy h = smoothed_aggregation_hierarchy(
      t.A, rigid_body_modes(t.mesh, t.plain), free_dof_nodes(t.plain), o);
  const MultigridHierarchy hz = smoothed_aggregation_hierarchy(
      t.Az, rigid_body_modes(t.mesh, t.ordered), free_dof_nodes(t.ordered), o);
  ASSERT_GE(h.prolongations.size(), 1U);
  ASSERT_EQ(h.prolongations.size(), hz.prolongations.size());
  ASSERT_FALSE(h.jacobi_radii.empty());
  ASSERT_EQ(hz.jacobi_radii.size(), h.jacobi_radii.size());
  EXPECT_NEAR(hz.jacobi_radii[0], h.jacobi_radii[0], 1e-3 * h.jacobi_radii[0]);
  for (std::size_t l = 0; l < h.coarse_operators.size(); ++l) {
    ASSERT_EQ(h.coarse_operators[l].rows(), hz.coarse_operators[l].rows()) << l;
    const Eigen::VectorXd e =
        Eigen::SelfAdjointEigenSolver<Matrix>(Matrix(h.coarse_operators[l])).eigenvalues();
    const Eigen::VectorXd ez =
        Eigen::SelfAdjointEigenSolver<Matrix>(Matrix(hz.coarse_operators[l])).eigenvalues();
    EXPECT_LT((e - ez).norm(), 1e-3 * e.norm()) << l;
  }
}

}  // namespace
}  // namespace signorini

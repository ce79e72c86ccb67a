// The rigid-body modes are the null space of the stiffness of a body held nowhere, and
// free_dof_nodes gives each free dof its node.

#include "signorini/fem/rigid_body_modes.hpp"

#include <gtest/gtest.h>

#include <Eigen/QR>

#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

TEST(RigidBodyModes, SpanTheNullSpaceOfAFloatingBody) {
  const ProblemSpec spec = paper_benchmark(12, 4);
  const Mesh mesh = make_rectangle_mesh(spec.mesh);
  const DofMap free = make_dof_map(mesh, {});  // held nowhere: A is singular
  const SparseMatrix A = assemble_stiffness(mesh, free, spec.elasticity);
  const Matrix B = rigid_body_modes(mesh, free);
  ASSERT_EQ(B.rows(), free.num_free());
  ASSERT_EQ(B.cols(), 3);
  const double scale = Matrix(A).norm() * B.norm();
  EXPECT_LT((A * B).norm(), 1e-13 * scale);
  // ... and they are independent: the null space of a 2D floating body has dimension 3.
  Eigen::ColPivHouseholderQR<Matrix> qr(B);
  EXPECT_EQ(qr.rank(), 3);
  // A mode that is not rigid (a stretch) is not in it.
  Vector stretch = Vector::Zero(free.num_free());
  for (Index node = 0; node < mesh.num_nodes(); ++node) stretch[2 * node] = mesh.node(node)[0];
  EXPECT_GT((A * stretch).norm(), 1e-3 * Matrix(A).norm() * stretch.norm());
}

TEST(RigidBodyModes, LeaveOutClampedDofs) {
  const ProblemSpec spec = paper_benchmark(6, 2);
  const Mesh mesh = make_rectangle_mesh(spec.mesh);
  const DofMap dofs = make_dof_map(mesh, spec.clamps);
  const Matrix B = rigid_body_modes(mesh, dofs);
  EXPECT_EQ(B.rows(), dofs.num_free());
  const std::vector<Index> node = free_dof_nodes(dofs);
  ASSERT_EQ(static_cast<Index>(node.size()), dofs.num_free());
  for (Index a = 0; a < dofs.num_nodes(); ++a)
    for (int k = 0; k < 2; ++k) {
      const Index f = dofs.free_index(a, k);
      if (f < 0) continue;
      EXPECT_EQ(node[static_cast<std::size_t>(f)], a);
      EXPECT_EQ(B(f, k), 1.0);      // translation along k
      EXPECT_EQ(B(f, 1 - k), 0.0);  // not across
    }
}

// A rank of a distributed run makes its own rows only: the same numbers as the whole's.
TEST(RigidBodyModes, ARangeOfRowsIsThoseRowsOfTheWhole) {
  const ProblemSpec spec = paper_benchmark(6, 2);
  const Mesh mesh = make_rectangle_mesh(spec.mesh);
  const DofMap dofs = make_dof_map(mesh, spec.clamps);
  const Matrix whole = rigid_body_modes(mesh, dofs);
  const Index first = 5, end = dofs.num_free() - 3;
  const Matrix part = rigid_body_modes(mesh, dofs, first, end);
  ASSERT_EQ(part.rows(), end - first);
  EXPECT_EQ(part, whole.middleRows(first, end - first));
  EXPECT_EQ(rigid_body_modes(mesh, dofs, 0, 0).rows(), 0);
  EXPECT_THROW((void)rigid_body_modes(mesh, dofs, 3, dofs.num_free() + 1), NumericalError);
}

}  // namespace
}  // namespace signorini

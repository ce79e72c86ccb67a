// The contact nodes' tangential directions and the operator T (src/signorini/fem/
// contact_tangents.hpp), for friction.

#include "signorini/interface/contact_tangents.hpp"

#include <gtest/gtest.h>

#include <Eigen/LU>
#include <random>

#include "../problem/ball_on_block.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

TEST(ContactTangents, BasisIsOrthonormalAndRightHanded) {
  std::mt19937 random(3);
  std::normal_distribution<double> g;
  for (int i = 0; i < 200; ++i) {
    Eigen::Vector3d nu(g(random), g(random), g(random));
    if (i < 6) nu = Eigen::Vector3d::Unit(i % 3) * (i < 3 ? 1.0 : -1.0);  // the axes too
    nu.normalize();
    const Eigen::MatrixXd t = tangent_basis(nu);
    ASSERT_EQ(t.rows(), 3);
    ASSERT_EQ(t.cols(), 2);
    Eigen::Matrix3d frame;
    frame << nu, t;
    EXPECT_LT((frame.transpose() * frame - Eigen::Matrix3d::Identity()).norm(), 1e-14);
    EXPECT_NEAR(frame.determinant(), 1.0, 1e-14);
  }
  const Eigen::MatrixXd t2 = tangent_basis(Eigen::Vector2d(0.0, -1.0));  // the paper's bottom
  EXPECT_EQ(t2, Eigen::MatrixXd(Eigen::Vector2d(1.0, 0.0)));
}

// For a uniform displacement a of the body, node j's (N a)_j and (T a)_j are a in the node's
// frame (nu_j, t_j): on the paper's 2D mesh and on a 3D block with a curved contact normal.
void expect_frame_components(const Model& m) {
  const ContactSet& c = m.problem.contact;
  const SparseMatrix T = tangential_operator(c, m.dofs);
  const int dim = m.dofs.dim();
  ASSERT_EQ(T.rows(), (dim - 1) * c.size());
  ASSERT_EQ(T.cols(), m.problem.A.rows());
  const double values[3] = {0.3, -0.7, 0.2};
  Eigen::VectorXd a(dim);
  for (int k = 0; k < dim; ++k) a(k) = values[k];
  Vector full = Vector::Zero(m.dofs.num_dofs());
  for (Index node = 0; node < m.dofs.num_nodes(); ++node) full.segment(node * dim, dim) = a;
  const Vector x = m.dofs.restrict_to_free(full);
  const Vector Nx = c.N * x, Tx = T * x;
  int checked = 0;
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    bool all_free = true;
    for (int k = 0; k < dim; ++k) all_free = all_free && m.dofs.free_index(node, k) >= 0;
    if (!all_free) continue;
    const Eigen::MatrixXd t = tangent_basis(c.normals.col(j));
    EXPECT_NEAR(Nx(j), c.normals.col(j).dot(a), 1e-14);
    for (int k = 0; k < dim - 1; ++k) EXPECT_NEAR(Tx((dim - 1) * j + k), t.col(k).dot(a), 1e-14);
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

TEST(ContactTangents, OperatorGivesTheTangentialDisplacement2D) {
  expect_frame_components(build_model(paper_benchmark(30, 10)));
}

TEST(ContactTangents, OperatorGivesTheTangentialDisplacement3D) {
  ProblemSpec spec = testing::ball_on_block(6, 1e-3);
  spec.contacts.front().surface_normal = [](const Point& x) {
    return Eigen::Vector3d(x(0) - 0.5, x(1) - 0.5, -1.0);  // tilted normals, all components
  };
  expect_frame_components(build_model(spec));
}

}  // namespace
}  // namespace signorini

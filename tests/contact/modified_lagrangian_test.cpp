// The pieces of the modified Lagrangian used by GNM: the gradient is the derivative of Phi, the
// cancellation-free change of Phi equals the plain difference where the latter is accurate, and
// the Hessian is A plus the active contact terms.

#include "signorini/contact/modified_lagrangian.hpp"

#include <gtest/gtest.h>

#include "test_problems.hpp"

namespace signorini {
namespace {

double phi(const ContactProblem& p, const ModifiedLagrangian& m, const Vector& x) {
  return ModifiedLagrangian::value(p, m.r(), x, m.multipliers());
}

TEST(ModifiedLagrangian, GradientAndChangeMatchDirectEvaluation) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian m(p, 1e3);  // moderate r so that plain differences are accurate
  Vector l = Vector::LinSpaced(p.contact.size(), -0.5, 2.0);
  m.set_multipliers(l);
  Vector x = 1e-4 * Vector::LinSpaced(p.A.rows(), -1.0, 1.0).array().sin().matrix();
  Vector d = 1e-5 * Vector::LinSpaced(p.A.rows(), 0.0, 7.0).array().cos().matrix();
  const Vector Nx = p.contact.N * x;
  const Vector residual = p.A * x - p.b;
  const auto dir = m.direction(residual, Nx, d);
  for (const double t : {1.0, 0.5, 1e-3}) {
    const double direct = phi(p, m, x + t * d) - phi(p, m, x);
    EXPECT_NEAR(m.phi_change(dir, t), direct, 1e-9 * std::abs(direct) + 1e-18) << "t = " << t;
  }
  // Directional derivative from central differences.
  const double h = 1e-3;
  const double fd = (phi(p, m, x + h * d) - phi(p, m, x - h * d)) / (2.0 * h);
  EXPECT_NEAR(m.gradient(residual, Nx).dot(d), fd, 1e-6 * std::abs(fd));
}

TEST(ModifiedLagrangian, HessianAddsActiveContactTerms) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian m(p, 1e8);
  ActiveSet active(static_cast<std::size_t>(p.contact.size()), false);
  active[5] = active[6] = true;
  SparseMatrix H = p.A;
  m.hessian(active, H);
  SparseMatrix expected = p.A;
  for (const Index j : {5, 6}) {
    const Vector row = p.contact.N.row(j).transpose();
    expected += SparseMatrix((1e8 * p.contact.weights(j) * row * row.transpose()).sparseView());
  }
  EXPECT_LT((SparseMatrix(H - expected)).norm(), 1e-12 * expected.norm());
}

TEST(ModifiedLagrangian, ValueEqualsEnergyAtSaddlePointMultipliers) {
  // With l_j = (l_j + r (N u - g)_j)_+ exactly, M(u, l) = J(u).
  const ContactProblem& p = testing::paper_model(30).problem;
  const Vector u = Vector::Zero(p.A.rows());
  const Vector l = Vector::Zero(p.contact.size());
  EXPECT_DOUBLE_EQ(ModifiedLagrangian::value(p, 1e8, u, l), 0.0);
}

}  // namespace
}  // namespace signorini

// The per-node projections of Tresca and Coulomb friction and their generalised derivatives
// (src/signorini/contact/friction_projection.hpp).

#include "signorini/contact/friction_projection.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace signorini {
namespace {

// dP/dz by central differences, where P is smooth (away from z_n = 0 and |z_t| = radius).
template <class Project>
Eigen::MatrixXd finite_difference(const Project& project, const Eigen::VectorXd& z) {
  const double h = 1e-7;
  Eigen::MatrixXd D(z.size(), z.size());
  for (Eigen::Index k = 0; k < z.size(); ++k) {
    Eigen::VectorXd up = z, down = z;
    up(k) += h;
    down(k) -= h;
    D.col(k) = (project(up).force - project(down).force) / (2.0 * h);
  }
  return D;
}

// Points in 2D (d = 2) and 3D (d = 3), both signs of z_n, inside and outside the ball.
std::vector<Eigen::VectorXd> points() {
  std::mt19937 random(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<Eigen::VectorXd> out;
  for (int d = 2; d <= 3; ++d)
    for (int i = 0; i < 40; ++i) {
      Eigen::VectorXd z(d);
      for (int k = 0; k < d; ++k) z(k) = u(random);
      out.push_back(z);
    }
  return out;
}

TEST(FrictionProjection, TrescaDerivativeIsTheDerivativeAndSymmetric) {
  const double s = 0.8;
  const auto project = [&](const Eigen::VectorXd& z) { return project_tresca(z, s); };
  int sliding = 0, sticking = 0;
  for (const Eigen::VectorXd& z : points()) {
    const double norm = z.tail(z.size() - 1).norm();
    if (std::abs(z(0)) < 1e-3 || std::abs(norm - s) < 1e-3) continue;  // the kinks
    const FrictionProjection p = project(z);
    EXPECT_LT((p.derivative - finite_difference(project, z)).norm(), 1e-6) << z.transpose();
    EXPECT_LT((p.derivative - p.derivative.transpose()).norm(), 1e-14);
    EXPECT_LE(p.force.tail(z.size() - 1).norm(), s * (1.0 + 1e-15));
    EXPECT_EQ(p.sliding, norm >= s);
    EXPECT_EQ(p.in_contact, z(0) > 0.0);
    ++(p.sliding ? sliding : sticking);
  }
  EXPECT_GT(sliding, 10);
  EXPECT_GT(sticking, 10);
}

TEST(FrictionProjection, CoulombDerivativeIsTheDerivativeAndNotSymmetricWhenSliding) {
  const double mu = 0.6;
  const auto project = [&](const Eigen::VectorXd& z) { return project_coulomb(z, mu); };
  int sliding = 0;
  for (const Eigen::VectorXd& z : points()) {
    const double norm = z.tail(z.size() - 1).norm();
    if (std::abs(z(0)) < 1e-3 || std::abs(norm - mu * std::max(z(0), 0.0)) < 1e-3) continue;
    const FrictionProjection p = project(z);
    EXPECT_LT((p.derivative - finite_difference(project, z)).norm(), 1e-6) << z.transpose();
    const double radius = mu * std::max(z(0), 0.0);
    EXPECT_LE(p.force.tail(z.size() - 1).norm(), radius * (1.0 + 1e-15) + 1e-300);
    if (z(0) <= 0.0) {
      EXPECT_EQ(p.force.norm(), 0.0);  // separated: no force
      EXPECT_FALSE(p.sliding);
    } else if (p.sliding) {
      ++sliding;
      EXPECT_GT((p.derivative - p.derivative.transpose()).norm(), 1e-3);
    }
  }
  EXPECT_GT(sliding, 10);
}

// Tresca's potential psi has the force as its gradient (so the merit function's gradient is the
// GNM gradient G of (16) with friction), and psi is convex: the force is monotone.
TEST(FrictionProjection, TrescaForceIsTheGradientOfItsPotential) {
  const double s = 0.7, h = 1e-6;
  for (const Eigen::VectorXd& z : points()) {
    const FrictionProjection p = project_tresca(z, s);
    Eigen::VectorXd gradient(z.size());
    for (Eigen::Index k = 0; k < z.size(); ++k) {
      Eigen::VectorXd up = z, down = z;
      up(k) += h;
      down(k) -= h;
      gradient(k) = (project_tresca(up, s).potential - project_tresca(down, s).potential) / (2 * h);
    }
    EXPECT_LT((gradient - p.force).norm(), 1e-7) << z.transpose();
    for (const Eigen::VectorXd& w : points()) {
      if (w.size() == z.size()) {
        EXPECT_GE((project_tresca(w, s).force - p.force).dot(w - z), -1e-14);
      }
    }
  }
  EXPECT_TRUE(std::isnan(project_coulomb(points().front(), 0.5).potential));
}

// The projection onto the friction ball is the closest point: (z_t - P_t) . (w - P_t) <= 0 for
// every w in the ball.
TEST(FrictionProjection, TangentialForceIsTheClosestAdmissibleOne) {
  std::mt19937 random(11);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double s = 0.5;
  for (const Eigen::VectorXd& z : points()) {
    const Eigen::Index d = z.size();
    const Eigen::VectorXd pt = project_tresca(z, s).force.tail(d - 1);
    for (int i = 0; i < 20; ++i) {
      Eigen::VectorXd w(d - 1);
      for (Eigen::Index k = 0; k < d - 1; ++k) w(k) = u(random);
      if (w.norm() > s) w *= s / w.norm();
      EXPECT_LE((z.tail(d - 1) - pt).dot(w - pt), 1e-14);
    }
  }
}

// Coulomb is Tresca with the slip bound mu times the normal force, at the same z.
TEST(FrictionProjection, CoulombIsTrescaWithTheBoundOfItsNormalForce) {
  const double mu = 0.3;
  for (const Eigen::VectorXd& z : points()) {
    const FrictionProjection c = project_coulomb(z, mu);
    if (!c.in_contact) continue;
    const FrictionProjection t = project_tresca(z, mu * c.force(0));
    EXPECT_LT((c.force - t.force).norm(), 1e-15 * (1.0 + z.norm()));
    EXPECT_EQ(c.sliding, t.sliding);
  }
}

// mu = 0 is frictionless contact: the unilateral law's normal force and no tangential force; a
// slip bound beyond every |z_t| sticks everywhere (the nodes bonded tangentially).
TEST(FrictionProjection, LimitsAreFrictionlessAndBonded) {
  for (const Eigen::VectorXd& z : points()) {
    const Eigen::Index d = z.size();
    const FrictionProjection free = project_coulomb(z, 0.0);
    EXPECT_EQ(free.force(0), std::max(z(0), 0.0));
    EXPECT_EQ(free.force.tail(d - 1).norm(), 0.0);
    const FrictionProjection bonded = project_tresca(z, 1e6);
    EXPECT_FALSE(bonded.sliding);
    EXPECT_EQ(bonded.force.tail(d - 1), z.tail(d - 1));
    EXPECT_EQ(bonded.derivative.bottomRightCorner(d - 1, d - 1),
              Eigen::MatrixXd::Identity(d - 1, d - 1));
  }
}

TEST(FrictionProjection, RejectsBadInput) {
  EXPECT_THROW((void)project_tresca(Eigen::VectorXd::Zero(1), 1.0), std::invalid_argument);
  EXPECT_THROW((void)project_tresca(Eigen::VectorXd::Zero(4), 1.0), std::invalid_argument);
  EXPECT_THROW((void)project_tresca(Eigen::VectorXd::Zero(2), -1.0), std::invalid_argument);
  EXPECT_THROW((void)project_coulomb(Eigen::VectorXd::Zero(3), std::nan("")),
               std::invalid_argument);
}

}  // namespace
}  // namespace signorini

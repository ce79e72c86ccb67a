// Semismooth Newton for Tresca and Coulomb friction (src/signorini/contact/friction_ssn.hpp) on
// the paper's 2D problem: its limits against the frictionless solver, the tangential KKT
// conditions at its solutions, and Coulomb against Tresca with the bound of its pressure.

#include "signorini/contact/friction_ssn.hpp"

#include <gtest/gtest.h>

#include "../problem/ball_on_block.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/interface/contact_tangents.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

struct Paper {
  Model model = build_model(paper_benchmark(30, 10));
  SparseMatrix T = tangential_operator(model.problem.contact, model.dofs);
  FrictionSsnResult solve(FrictionKind kind, double bound) const {
    FrictionLawSpec law{kind, Vector::Constant(model.problem.contact.size(), bound)};
    return solve_friction_ssn(model.problem, T, law);
  }
};

double relative(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

// The tangential KKT conditions node by node: |lambda_t| <= bound; a sticking node does not
// slip; a sliding one slips along its tangential force.
void expect_tangential_kkt(const Paper& p, const FrictionSsnResult& r, FrictionKind kind,
                           double bound) {
  ASSERT_TRUE(r.converged) << r.equilibrium << " " << r.projection;
  const Vector slip = p.T * r.u;
  const double scale = r.u.lpNorm<Eigen::Infinity>();
  for (Index j = 0; j < p.model.problem.contact.size(); ++j) {
    if (!p.model.problem.contact.movable[static_cast<std::size_t>(j)]) continue;
    const double radius = kind == FrictionKind::Tresca ? bound : bound * r.force(0, j);
    const double lt = r.force(1, j);
    EXPECT_LE(std::abs(lt), radius * (1 + 1e-10) + 1e-12 * scale) << "node " << j;
    if (!r.sliding[static_cast<std::size_t>(j)] && radius > 0.0) {
      EXPECT_LE(std::abs(slip(j)), 1e-9 * scale) << "a sticking node slips: " << j;
    } else if (radius > 0.0) {
      EXPECT_GE(slip(j) * lt, -1e-12 * scale * radius) << "slip against the force: " << j;
    }
  }
}

TEST(FrictionSsn, ZeroFrictionIsTheFrictionlessSolution) {
  const Paper p;
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-12;
  const ContactResult frictionless = solve_contact(p.model.problem, o, &p.model.multigrid);
  for (const FrictionKind kind : {FrictionKind::Tresca, FrictionKind::Coulomb}) {
    const FrictionSsnResult r = p.solve(kind, 0.0);
    ASSERT_TRUE(r.converged) << r.equilibrium << " " << r.projection;
    EXPECT_LT(relative(r.u, frictionless.u), 1e-8);
    EXPECT_LT(relative(r.force.row(0).transpose(), frictionless.l), 1e-8);
    EXPECT_EQ(r.force.row(1).norm(), 0.0);
  }
}

TEST(FrictionSsn, TrescaSatisfiesTheTangentialConditionsAndChangesTheAnswer) {
  const Paper p;
  const FrictionSsnResult frictionless = p.solve(FrictionKind::Tresca, 0.0);
  // A bound of about a tenth of the largest pressure: some nodes stick, some slide.
  const double s = 0.1 * frictionless.force.row(0).maxCoeff();
  const FrictionSsnResult r = p.solve(FrictionKind::Tresca, s);
  expect_tangential_kkt(p, r, FrictionKind::Tresca, s);
  int sliding = 0, sticking = 0;
  for (Index j = 0; j < p.model.problem.contact.size(); ++j)
    ++(r.sliding[static_cast<std::size_t>(j)] ? sliding : sticking);
  EXPECT_GT(sliding, 0);
  EXPECT_GT(sticking, 0);
  EXPECT_GT(relative(r.u, frictionless.u), 1e-4);  // friction matters here
}

TEST(FrictionSsn, HugeBoundBondsTheContactTangentially) {
  const Paper p;
  const FrictionSsnResult r = p.solve(FrictionKind::Tresca, 1e12);
  ASSERT_TRUE(r.converged);
  EXPECT_LE((p.T * r.u).lpNorm<Eigen::Infinity>(), 1e-12 * r.u.lpNorm<Eigen::Infinity>());
}

// Coulomb at mu = 0.3 (every node in contact slides), 1, 2 and 5 (a stick zone in the middle,
// growing with mu): the tangential conditions, and the same answer as Tresca with s_j = mu times
// Coulomb's pressure. (With the complementarity constant c equal to the body's stiffness per
// area, the default before, the iteration cycled at mu = 5 on this problem; at mu = 20 one node
// still cycles between sticking and sliding on this coarse mesh, for every c tried.)
TEST(FrictionSsn, CoulombIsTrescaWithTheBoundOfItsPressure) {
  const Paper p;
  for (const double mu : {0.3, 1.0, 2.0, 5.0}) {
    SCOPED_TRACE(::testing::Message() << "mu = " << mu);
    const FrictionSsnResult coulomb = p.solve(FrictionKind::Coulomb, mu);
    expect_tangential_kkt(p, coulomb, FrictionKind::Coulomb, mu);
    FrictionLawSpec tresca{FrictionKind::Tresca, mu * coulomb.force.row(0).transpose()};
    const FrictionSsnResult r = solve_friction_ssn(p.model.problem, p.T, tresca);
    ASSERT_TRUE(r.converged) << "mu = " << mu;
    EXPECT_LT(relative(r.u, coulomb.u), 1e-8) << "mu = " << mu;
    EXPECT_LT((r.force - coulomb.force).norm() / coulomb.force.norm(), 1e-8) << "mu = " << mu;
    int in_contact = 0, sliding = 0;
    for (Index j = 0; j < p.model.problem.contact.size(); ++j) {
      in_contact += coulomb.in_contact[static_cast<std::size_t>(j)] ? 1 : 0;
      sliding += coulomb.sliding[static_cast<std::size_t>(j)] ? 1 : 0;
    }
    EXPECT_GT(in_contact, 0);
    if (mu >= 1.0) {
      EXPECT_GT(sliding, 0) << "mu = " << mu;
      EXPECT_LT(sliding, in_contact) << "mu = " << mu << ": a stick zone expected";
    }
  }
}

// A tolerance below what the factorisation resolves: the iteration stops at the rounding floor
// (the nodes' states settled and the residual no longer halving) and says so, with the same
// answer as the one that met the ordinary tolerance; without the floor rule it runs to its limit.
TEST(FrictionSsn, StopsAtTheRoundingFloorOfAnUnreachableTolerance) {
  const Paper p;
  const FrictionLawSpec law{FrictionKind::Coulomb,
                            Vector::Constant(p.model.problem.contact.size(), 1.0)};
  const FrictionSsnResult reached = solve_friction_ssn(p.model.problem, p.T, law);
  ASSERT_TRUE(reached.converged);
  EXPECT_FALSE(reached.at_rounding_floor);
  FrictionSsnOptions o;
  o.tolerance = 1e-20;
  const FrictionSsnResult floor = solve_friction_ssn(p.model.problem, p.T, law, o);
  ASSERT_TRUE(floor.converged);
  EXPECT_TRUE(floor.at_rounding_floor);
  EXPECT_LT(std::max(floor.equilibrium, floor.projection), 1e-11);
  EXPECT_LT(relative(floor.u, reached.u), 1e-12);
  o.floor_tolerance = 0.0;
  o.max_iterations = 30;
  const FrictionSsnResult limit = solve_friction_ssn(p.model.problem, p.T, law, o);
  EXPECT_FALSE(limit.converged);
  EXPECT_EQ(limit.iterations, 30);
}

// In 3D (a block pressed 0.03 onto a rigid ball, two tangential directions per node; b = 0, the
// load comes from the prescribed interference): Coulomb's
// tangential forces within mu times the pressure, sticking nodes without slip, sliding ones
// slipping along their force; and Tresca with s_j = mu times that pressure gives the same u.
TEST(FrictionSsn, CoulombIn3DMeetsTheConditionsAndIsTrescaWithItsBound) {
  const Model model = build_model(testing::ball_on_block(8, 3e-2));  // 21 nodes in contact
  const SparseMatrix T = tangential_operator(model.problem.contact, model.dofs);
  const double mu = 0.2;
  const Index nc = model.problem.contact.size();
  const FrictionSsnResult coulomb =
      solve_friction_ssn(model.problem, T, {FrictionKind::Coulomb, Vector::Constant(nc, mu)});
  ASSERT_TRUE(coulomb.converged) << coulomb.equilibrium << " " << coulomb.projection;
  ASSERT_EQ(coulomb.force.rows(), 3);
  const Vector slip = T * coulomb.u;
  const double scale = coulomb.u.lpNorm<Eigen::Infinity>();
  int in_contact = 0, sliding = 0;
  for (Index j = 0; j < nc; ++j) {
    if (!coulomb.in_contact[static_cast<std::size_t>(j)]) continue;
    ++in_contact;
    sliding += coulomb.sliding[static_cast<std::size_t>(j)] ? 1 : 0;
    const Eigen::Vector2d lt = coulomb.force.col(j).tail(2);
    const Eigen::Vector2d sj = slip.segment(2 * j, 2);
    EXPECT_LE(lt.norm(), mu * coulomb.force(0, j) * (1 + 1e-10)) << "node " << j;
    if (!coulomb.sliding[static_cast<std::size_t>(j)]) {
      EXPECT_LE(sj.norm(), 1e-9 * scale) << "a sticking node slips: " << j;
    } else if (sj.norm() > 1e-9 * scale) {
      // Along the force: parallel, same sense.
      EXPECT_LE(std::abs(sj(0) * lt(1) - sj(1) * lt(0)), 1e-8 * sj.norm() * lt.norm());
      EXPECT_GT(sj.dot(lt), 0.0);
    }
  }
  EXPECT_GT(in_contact, 10);
  EXPECT_GT(sliding, 0);
  EXPECT_LT(sliding, in_contact);  // a stick zone
  const FrictionSsnResult frictionless =
      solve_friction_ssn(model.problem, T, {FrictionKind::Tresca, Vector::Zero(nc)});
  EXPECT_GT(relative(coulomb.u, frictionless.u), 1e-2);  // friction matters here
  const FrictionSsnResult tresca = solve_friction_ssn(
      model.problem, T, {FrictionKind::Tresca, mu * coulomb.force.row(0).transpose()});
  ASSERT_TRUE(tresca.converged);
  EXPECT_LT(relative(tresca.u, coulomb.u), 1e-8);
}

}  // namespace
}  // namespace signorini

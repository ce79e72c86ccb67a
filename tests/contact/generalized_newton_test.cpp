// The one GNM loop (generalized_newton.cpp) against NewtonSpace: its failure exits, driven by a
// scripted space, and its agreement between the host and the CPU backend spaces.

#include "signorini/contact/generalized_newton.hpp"

#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <vector>

#include "../problem/ball_on_block.hpp"
#include "signorini/backend/make_backend.hpp"
#include "signorini/contact/armijo_rule.hpp"
#include "signorini/contact/backend_newton_space.hpp"
#include "signorini/contact/host_newton_space.hpp"
#include "signorini/contact/newton_system.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

// A space whose Newton solve and direction are scripted: no linear algebra at all.
class ScriptedSpace final : public NewtonSpace {
 public:
  explicit ScriptedSpace(Index nc) : Nx_(Vector::Zero(nc)) {}
  NewtonSolveStats next_solve;
  ModifiedLagrangian::Direction next_direction;
  int steps = 0;

  [[nodiscard]] const Vector& contact_values() const override { return Nx_; }
  void set_active(const ActiveSet&, double) override { ++refreshes_; }
  NewtonSolveStats solve(const Vector&) override {
    solve_tolerances.push_back(linear_tolerance);
    return next_solve;
  }
  double linear_tolerance = -1.0;
  std::vector<double> solve_tolerances;  // linear_tolerance at each solve
  void set_linear_tolerance(double tolerance) override { linear_tolerance = tolerance; }
  void direction(ModifiedLagrangian::Direction& dir) override {
    dir.residual_dot_d = next_direction.residual_dot_d;
    dir.d_A_d = next_direction.d_A_d;
    dir.Nd = next_direction.Nd;
  }
  void step(double) override { ++steps; }
  NewtonStepNorms norms(const Vector&) override { return {1.0, 1.0, 1.0, 1.0}; }
  [[nodiscard]] int factorizations() const override { return refreshes_; }

 private:
  Vector Nx_;
  int refreshes_ = 0;
};

TEST(GeneralizedNewton, AdaptiveInnerToleranceAsksForATenthOfItsToleranceFromTheLinearSolver) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian phi(p, 1e3);
  ContactSolverOptions o;
  ScriptedSpace space(p.contact.size());
  space.next_direction.residual_dot_d = -1.0;
  space.next_direction.d_A_d = 1.0;
  space.next_direction.Nd = Vector::Zero(p.contact.size());
  o.max_gnm_iterations = 1;
  o.inner_tolerance = InnerTolerance::Adaptive;
  static_cast<void>(GeneralizedNewton(o, 1.0).minimize(phi, space, 1, 1e-4));
  EXPECT_DOUBLE_EQ(space.linear_tolerance, 1e-5);
  // Never below the configured CG tolerance; and the exact method uses the configured one.
  o.linear.cg_tolerance = 1e-3;
  static_cast<void>(GeneralizedNewton(o, 1.0).minimize(phi, space, 1, 1e-4));
  EXPECT_DOUBLE_EQ(space.linear_tolerance, 1e-3);
  o.inner_tolerance = InnerTolerance::Fixed;
  static_cast<void>(GeneralizedNewton(o, 1.0).minimize(phi, space, 1, 1e-4));
  EXPECT_EQ(space.linear_tolerance, 0.0);
}

// The first Newton system with no node active (Uzawa's first step, from l = 0 and x = 0) is
// solved to kFirstNewtonTolerance. It is no minimiser: a repeat of its (empty) set does not end
// GNM, and the next system gets the step's own tolerance. The exact method keeps its own.
TEST(GeneralizedNewton, FirstSystemWithNoNodeActiveIsSolvedLoosely) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ASSERT_GE(p.contact.gaps.minCoeff(), 0.0);  // no node active at x = 0 with l = 0
  ModifiedLagrangian phi(p, 1e3);
  ContactSolverOptions o;
  o.max_gnm_iterations = 2;
  o.inner_tolerance = InnerTolerance::Adaptive;
  ScriptedSpace space(p.contact.size());
  space.next_direction.residual_dot_d = -1.0;  // full steps that decrease Phi
  space.next_direction.d_A_d = 1.0;
  space.next_direction.Nd = Vector::Zero(p.contact.size());
  const GnmResult g = GeneralizedNewton(o, 1.0).minimize(phi, space, 1, 1e-4);
  EXPECT_EQ(space.solve_tolerances, (std::vector<double>{kFirstNewtonTolerance, 1e-5}));
  EXPECT_EQ(space.steps, 2);  // the repeated empty set did not end GNM after the loose step
  EXPECT_EQ(g.termination, Termination::IterationLimit);
  EXPECT_EQ(space.linear_tolerance, 1e-5);

  o.inner_tolerance = InnerTolerance::Fixed;
  ScriptedSpace exact(p.contact.size());
  exact.next_direction = space.next_direction;
  const GnmResult f = GeneralizedNewton(o, 1.0).minimize(phi, exact, 1, 1e-4);
  EXPECT_EQ(exact.solve_tolerances, (std::vector<double>{0.0}));
  EXPECT_EQ(f.termination, Termination::Converged);  // the repeat after a full step
  EXPECT_EQ(exact.steps, 1);
}

// A body that never reaches its obstacle on the iterative path (inexact Uzawa-GNM): l stays 0,
// so the dual change is 0 after step 1, whose Newton systems were solved loosely (the first to
// kFirstNewtonTolerance, the rest to 1e-4); Uzawa goes on to a step solved tightly, and ends at
// the linear solution without contact (before, it stopped at step 1 and failed the KKT check).
TEST(GeneralizedNewton, NoContactStillEndsAtTheLinearSolution) {
  ProblemSpec spec = testing::ball_on_block(16, -0.05);  // the ball 0.05 below the block
  spec.body_force = [](const Point&) { return Eigen::Vector3d(0.0, 0.0, -1.0); };
  spec.solver.automatic_path = false;
  spec.solver.linear.type = LinearSolverType::ConjugateGradient;
  spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
  spec.solver.inner_tolerance = InnerTolerance::Adaptive;
  const Model model = build_model(spec);
  const ContactResult r = solve_contact(model.problem, model.solver, &model.multigrid);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_EQ(r.l.lpNorm<Eigen::Infinity>(), 0.0);
  const Vector linear = Eigen::SimplicialLDLT<SparseMatrix>(model.problem.A).solve(model.problem.b);
  ASSERT_GT(linear.norm(), 0.0);
  EXPECT_LT(testing::relative_difference(r.u, linear), 1e-9);
  EXPECT_GE(r.summary.steps.size(), 2U);  // step 1, solved to 1e-3, is not the answer
}

TEST(GeneralizedNewton, ArmijoFailureStopsWithTheHalvingsTried) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian phi(p, 1e3);
  ContactSolverOptions o;
  o.max_armijo_halvings = 3;
  ScriptedSpace space(p.contact.size());
  // A descent direction (slope -1) along which Phi rises at once (curvature 1e6): no step of
  // length 1, 1/2, 1/4 or 1/8 decreases Phi enough.
  space.next_direction.residual_dot_d = -1.0;
  space.next_direction.d_A_d = 1e6;
  space.next_direction.Nd = Vector::Zero(p.contact.size());
  const GeneralizedNewton gnm(o, 1.0);
  const GnmResult g = gnm.minimize(phi, space, 4);
  EXPECT_EQ(g.termination, Termination::LineSearchFailure);
  EXPECT_EQ(g.armijo_reductions, 3);  // the halvings tried, not one more
  EXPECT_EQ(g.iterations, 1);
  EXPECT_EQ(space.steps, 0);
  EXPECT_NE(g.message.find("Armijo rule found no decrease after 3 halvings in GNM iteration 1 of "
                           "Uzawa step 4"),
            std::string::npos)
      << g.message;
}

TEST(GeneralizedNewton, LinearSolverFailureNamesTheSolverAndItsResidual) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian phi(p, 1e3);
  ContactSolverOptions o;
  ScriptedSpace space(p.contact.size());
  space.next_solve.converged = false;
  space.next_solve.iterations = 17;
  space.next_solve.residual = 3.5e-4;
  space.next_solve.solver = "conjugate gradients";
  space.next_solve.tolerance = 1e-12;
  const GnmResult g = GeneralizedNewton(o, 1.0).minimize(phi, space, 2);
  EXPECT_EQ(g.termination, Termination::LinearSolverFailure);
  EXPECT_EQ(g.linear_iterations, 17);
  EXPECT_EQ(g.message,
            "conjugate gradients did not converge in GNM iteration 1 of Uzawa step 2 (17 "
            "iterations, relative residual 3.500e-04, tolerance 1.0e-12)");
}

// After a full step, the same active set again means x minimises Phi: GNM stops at m = 2 without
// another solve, although the (scripted) norms never fall below the tolerance.
TEST(GeneralizedNewton, RepeatedActiveSetAfterAFullStepEndsTheMinimisation) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ModifiedLagrangian phi(p, 1e3);
  ContactSolverOptions o;
  o.max_gnm_iterations = 2;
  ScriptedSpace space(p.contact.size());
  space.next_direction.residual_dot_d = -1.0;  // a full step that decreases Phi
  space.next_direction.d_A_d = 1.0;
  space.next_direction.Nd = Vector::Zero(p.contact.size());
  const GnmResult g = GeneralizedNewton(o, 1.0).minimize(phi, space, 1);
  EXPECT_EQ(g.termination, Termination::Converged);
  EXPECT_EQ(g.iterations, 2);
  EXPECT_EQ(space.steps, 1);
}

// The same minimisation in the host space (CHOLMOD) and in the CPU backend's space (PCG with a
// tight tolerance): the same iterates to the solvers' accuracy.
TEST(GeneralizedNewton, HostAndBackendSpacesAgree) {
  const ContactProblem& p = testing::paper_model(30).problem;
  ContactSolverOptions o;
  o.linear.cg_tolerance = 1e-14;
  ModifiedLagrangian phi(p, 1e3);
  phi.set_multipliers(Vector::Constant(p.contact.size(), 0.05));
  const GeneralizedNewton gnm(o, p.b.norm());

  const auto system = make_newton_system(p, phi, o.linear);
  HostNewtonSpace host(p, *system, Vector::Zero(p.A.rows()));
  const GnmResult gh = gnm.minimize(phi, host, 1);

  TimingTable timings;
  const auto backend = make_backend(DeviceKind::Cpu);
  BackendNewtonSpace device(p, o, nullptr, *backend, timings, Vector::Zero(p.A.rows()));
  const GnmResult gd = gnm.minimize(phi, device, 1);

  ASSERT_EQ(gh.termination, Termination::Converged) << gh.message;
  ASSERT_EQ(gd.termination, Termination::Converged) << gd.message;
  EXPECT_EQ(gh.iterations, gd.iterations);
  EXPECT_GT(gd.linear_iterations, 0);
  EXPECT_EQ(gh.linear_iterations, 0);
  const Vector xd = device.solution();
  EXPECT_LT((host.x() - xd).norm(), 1e-9 * host.x().norm());
}

}  // namespace
}  // namespace signorini

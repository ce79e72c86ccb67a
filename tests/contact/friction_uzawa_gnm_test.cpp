// The paper's Uzawa-GNM method and classical Uzawa with friction (contact/friction_law.hpp):
// the one loop with Tresca's and Coulomb's laws, checked against the independent semismooth
// Newton solver on the KKT system (friction_ssn.hpp) on the same discrete problems, in 2D and 3D,
// and against the frictionless solver at zero friction.

#include <gtest/gtest.h>

#include "../problem/ball_on_block.hpp"
#include "../test_problems.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/contact/friction_law.hpp"
#include "signorini/contact/friction_ssn.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/interface/contact_tangents.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

double relative(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

// A model with its frictional contact problem (N with the tangential rows).
struct Frictional {
  Model model;
  SparseMatrix T;
  ContactProblem problem;
  explicit Frictional(const ProblemSpec& spec)
      : model(build_model(spec)),
        T(tangential_operator(model.problem.contact, model.dofs)),
        problem(model.problem) {
    add_tangential_rows(problem.contact, T);
  }
  [[nodiscard]] int dim() const { return problem.contact.components; }
  // With Cholmod, `condensed` picks the condensed path (the default) or the sparse direct one.
  [[nodiscard]] ContactResult solve(const FrictionLaw& law, ContactMethod method,
                                    LinearSolverType linear = LinearSolverType::Cholmod,
                                    bool condensed = true) const {
    ContactSolverOptions o;
    o.method = method;
    o.schur_complement = condensed;
    o.uzawa_tolerance = 1e-12;
    o.linear.type = linear;
    o.linear.cg_tolerance = 1e-14;
    if (method == ContactMethod::ClassicalUzawa) o.max_classical_iterations = 200000;
    return solve_contact(testing::with_law(problem, law), o);
  }
  [[nodiscard]] FrictionSsnResult reference(FrictionKind kind, const Vector& bound) const {
    return solve_friction_ssn(model.problem, T, {kind, bound});
  }
};

// The reference's force per node against the solver's pressure and tangential traction.
double force_difference(const ContactResult& r, const FrictionSsnResult& ref) {
  Matrix f(ref.force.rows(), ref.force.cols());
  f.row(0) = r.l.transpose();
  f.bottomRows(ref.force.rows() - 1) = r.tangential;
  return (f - ref.force).norm() / ref.force.norm();
}

TEST(FrictionUzawaGnm, ZeroFrictionIsTheFrictionlessSolution) {
  const Frictional p(paper_benchmark(30, 10));
  ContactSolverOptions o;
  o.uzawa_tolerance = 1e-12;
  const ContactResult frictionless = solve_contact(p.model.problem, o);
  const Index nc = p.problem.contact.size();
  for (const FrictionKind kind : {FrictionKind::Tresca, FrictionKind::Coulomb}) {
    const FrictionLaw law(kind, 2, Vector::Zero(nc));
    const ContactResult r = p.solve(law, ContactMethod::UzawaGnm);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(relative(r.u, frictionless.u), 1e-9);
    EXPECT_LT(relative(r.l, frictionless.l), 1e-9);
    EXPECT_EQ(r.tangential.norm(), 0.0);
    EXPECT_EQ(r.summary.num_active, frictionless.summary.num_active);
  }
}

// A very large coefficient bonds the touching nodes: no tangential displacement where the node
// presses, the same as the reference solver's.
TEST(FrictionUzawaGnm, HugeCoulombCoefficientBondsTheTouchingNodes) {
  const Frictional p(paper_benchmark(30, 10));
  const Index nc = p.problem.contact.size();
  const FrictionLaw law(FrictionKind::Coulomb, 2, Vector::Constant(nc, 1e6));
  const ContactResult r = p.solve(law, ContactMethod::UzawaGnm);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  const Vector slip = p.T * r.u;
  const double scale = r.u.lpNorm<Eigen::Infinity>();
  int touching = 0;
  for (Index j = 0; j < nc; ++j)
    if (r.l(j) > 0.0) {
      ++touching;
      EXPECT_LE(std::abs(slip(j)), 1e-9 * scale) << "node " << j;
    }
  EXPECT_GT(touching, 3);
  const FrictionSsnResult ref = p.reference(FrictionKind::Coulomb, Vector::Constant(nc, 1e6));
  ASSERT_TRUE(ref.converged);
  EXPECT_LT(relative(r.u, ref.u), 1e-8);
}

TEST(FrictionUzawaGnm, TrescaAgreesWithSemismoothNewtonIn2D) {
  const Frictional p(paper_benchmark(30, 10));
  const Index nc = p.problem.contact.size();
  const FrictionSsnResult frictionless = p.reference(FrictionKind::Tresca, Vector::Zero(nc));
  // About a tenth of the peak pressure: a stick zone and slip zones.
  const Vector s = Vector::Constant(nc, 0.1 * frictionless.force.row(0).maxCoeff());
  const FrictionSsnResult ref = p.reference(FrictionKind::Tresca, s);
  ASSERT_TRUE(ref.converged);
  const FrictionLaw law(FrictionKind::Tresca, 2, s);
  for (const ContactMethod method : {ContactMethod::UzawaGnm, ContactMethod::ClassicalUzawa}) {
    const ContactResult r = p.solve(law, method);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(relative(r.u, ref.u), 1e-8) << enum_to_string(kContactMethodNames, method);
    EXPECT_LT(force_difference(r, ref), 1e-8) << enum_to_string(kContactMethodNames, method);
    EXPECT_LT(r.summary.kkt.max(), 1e-9);
    EXPECT_LT(r.summary.kkt.slip, 1e-9);
  }
  // Semismooth Newton through the solver (the reference on the whole KKT system).
  const ContactResult ssn = p.solve(law, ContactMethod::SemismoothNewton);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  EXPECT_LT(relative(ssn.u, ref.u), 1e-10);
  EXPECT_LT(ssn.summary.kkt.max(), 1e-10);
  // The host's CG path solves the same Newton systems.
  const ContactResult cg =
      p.solve(law, ContactMethod::UzawaGnm, LinearSolverType::ConjugateGradient);
  ASSERT_TRUE(cg.summary.converged()) << cg.summary.message;
  EXPECT_LT(relative(cg.u, ref.u), 1e-8);
}

TEST(FrictionUzawaGnm, CoulombAgreesWithSemismoothNewtonIn2D) {
  const Frictional p(paper_benchmark(30, 10));
  const Index nc = p.problem.contact.size();
  for (const double mu : {0.3, 1.0, 5.0}) {
    const FrictionSsnResult ref = p.reference(FrictionKind::Coulomb, Vector::Constant(nc, mu));
    ASSERT_TRUE(ref.converged);
    const FrictionLaw law(FrictionKind::Coulomb, 2, Vector::Constant(nc, mu));
    const ContactResult r = p.solve(law, ContactMethod::UzawaGnm);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(relative(r.u, ref.u), 1e-8) << "mu = " << mu;
    EXPECT_LT(force_difference(r, ref), 1e-8) << "mu = " << mu;
    EXPECT_LT(r.summary.kkt.friction_bound, 1e-10);
    EXPECT_LT(r.summary.kkt.slip, 1e-9);
  }
}

TEST(FrictionUzawaGnm, CoulombAndTrescaAgreeWithSemismoothNewtonIn3D) {
  const Frictional p(testing::ball_on_block(8, 3e-2));
  ASSERT_EQ(p.dim(), 3);
  const Index nc = p.problem.contact.size();
  const double mu = 0.2;
  const FrictionSsnResult ref = p.reference(FrictionKind::Coulomb, Vector::Constant(nc, mu));
  ASSERT_TRUE(ref.converged);
  const FrictionLaw coulomb(FrictionKind::Coulomb, 3, Vector::Constant(nc, mu));
  const ContactResult r = p.solve(coulomb, ContactMethod::UzawaGnm);
  ASSERT_TRUE(r.summary.converged()) << r.summary.message;
  EXPECT_LT(relative(r.u, ref.u), 1e-8);
  EXPECT_LT(force_difference(r, ref), 1e-8);
  EXPECT_LT(r.summary.kkt.max(), 1e-9);
  // Tresca with the bound of Coulomb's pressure: the same solution.
  const ContactResult ssn = p.solve(coulomb, ContactMethod::SemismoothNewton);
  ASSERT_TRUE(ssn.summary.converged()) << ssn.summary.message;
  EXPECT_LT(relative(ssn.u, r.u), 1e-8);
  const FrictionLaw tresca(FrictionKind::Tresca, 3, mu * ref.force.row(0).transpose());
  const ContactResult t = p.solve(tresca, ContactMethod::UzawaGnm);
  ASSERT_TRUE(t.summary.converged()) << t.summary.message;
  EXPECT_LT(relative(t.u, ref.u), 1e-8);
}

// The block on the ball of examples/box_on_sphere.toml (2,028 unknowns) with Coulomb friction,
// from a little to a lot: Uzawa-GNM's Newton steps there switch between linearisations with
// sliding nodes (blocks, a refactorisation) and without (0/1 rows, factor updates), and it
// converges and agrees with the semismooth Newton reference. (It stalled while the sparse
// system kept a factor of the other kind across such a switch: Newton directions that did not
// descend; and at the minimiser while the Armijo test took |z1| - |z0| with cancellation.)
TEST(FrictionUzawaGnm, BlockOnBallExampleConvergesForEveryCoefficient) {
  const Frictional p(read_problem_file(SIGNORINI_EXAMPLES_DIR "/box_on_sphere.toml").spec);
  const Index nc = p.problem.contact.size();
  for (const double mu : {0.2, 1.0, 5.0}) {
    const FrictionSsnResult ref = p.reference(FrictionKind::Coulomb, Vector::Constant(nc, mu));
    ASSERT_TRUE(ref.converged) << mu;
    const FrictionLaw coulomb(FrictionKind::Coulomb, 3, Vector::Constant(nc, mu));
    const ContactResult r =
        p.solve(coulomb, ContactMethod::UzawaGnm, LinearSolverType::Cholmod, false);
    ASSERT_EQ(r.summary.path, SolvePath::SparseDirect);
    ASSERT_TRUE(r.summary.converged()) << mu << ": " << r.summary.message;
    EXPECT_LT(relative(r.u, ref.u), 1e-8) << mu;
    EXPECT_LT(force_difference(r, ref), 1e-8) << mu;
    EXPECT_LT(r.summary.kkt.max(), 1e-9) << mu;
  }
}

// The condensed path (CondensedProblem onto the contact nodes' free dofs, the dense Newton
// system: in 2D the active rows with rank-one updates, in 3D the blocks formed densely) against
// the sparse direct path on the full problem, for Uzawa-GNM and classical Uzawa, Tresca and
// Coulomb; and from a warm start with a slip origin (a load step), as the load stepping runs it.
TEST(FrictionUzawaGnm, CondensedPathAgreesWithTheSparseDirectOne) {
  for (const bool three_d : {false, true}) {
    const Frictional p(three_d ? testing::ball_on_block(8, 3e-2) : paper_benchmark(30, 10));
    const Index nc = p.problem.contact.size();
    const FrictionLaw coulomb(FrictionKind::Coulomb, p.dim(), Vector::Constant(nc, 0.3));
    const FrictionLaw tresca(FrictionKind::Tresca, p.dim(), Vector::Constant(nc, 0.05));
    for (const FrictionLaw* law : {&coulomb, &tresca})
      for (const ContactMethod method : {ContactMethod::UzawaGnm, ContactMethod::ClassicalUzawa}) {
        if (three_d && method == ContactMethod::ClassicalUzawa) continue;  // slow, tested above
        SCOPED_TRACE(std::string(three_d ? "3D " : "2D ") + std::string(law->name()) + " " +
                     std::string(enum_to_string(kContactMethodNames, method)));
        const ContactResult condensed = p.solve(*law, method);
        const ContactResult full = p.solve(*law, method, LinearSolverType::Cholmod, false);
        ASSERT_EQ(condensed.summary.path, SolvePath::CondensedDirect);
        ASSERT_EQ(full.summary.path, SolvePath::SparseDirect);
        ASSERT_TRUE(condensed.summary.converged()) << condensed.summary.message;
        ASSERT_TRUE(full.summary.converged()) << full.summary.message;
        EXPECT_LT(relative(condensed.u, full.u), 1e-9);
        EXPECT_LT(relative(condensed.l, full.l), 1e-8);
        EXPECT_LT(relative(condensed.tangential.reshaped(), full.tangential.reshaped()), 1e-8);
        EXPECT_LT(condensed.summary.kkt.max(), 1e-9);
      }
    // A second step: loads 1.5 times, from the first step's solution, slip from there.
    Vector steps[2];
    for (const bool condensed : {true, false}) {
      ContactSolverOptions o;
      o.uzawa_tolerance = 1e-12;
      o.schur_complement = condensed;
      const ContactProblem with_coulomb = testing::with_law(p.problem, coulomb);
      ContactSolver solver(with_coulomb, o);
      const ContactResult first = solver.solve();
      solver.set_loads(1.5 * p.problem.b);
      solver.warm_start(first);
      solver.set_slip_origin(first.u);
      const ContactResult second = solver.solve();
      ASSERT_TRUE(second.summary.converged()) << second.summary.message;
      EXPECT_TRUE(second.summary.warm_started);
      steps[condensed ? 0 : 1] = second.u;
    }
    EXPECT_LT(relative(steps[0], steps[1]), 1e-9) << (three_d ? "3D" : "2D");
  }
}

// The backend path (CG with the multigrid V-cycle): in 2D the active rows, in 3D the nodes'
// blocks as weights of H, the coarse levels with their diagonal; the same solution as the sparse
// direct path to the CG tolerance.
TEST(FrictionUzawaGnm, MultigridPathAgreesWithTheDirectOne) {
  for (const bool three_d : {false, true}) {
    // The model with its multigrid hierarchy (the options ask for it).
    ProblemSpec spec = three_d ? testing::ball_on_block(12, 3e-2) : paper_benchmark(60, 20);
    spec.solver.linear.type = LinearSolverType::ConjugateGradient;
    spec.solver.linear.preconditioner = PreconditionerType::Multigrid;
    const Frictional p(spec);
    ASSERT_GT(p.model.multigrid.prolongations.size(), 0U);
    const Index nc = p.problem.contact.size();
    const FrictionLaw law(FrictionKind::Coulomb, p.dim(),
                          Vector::Constant(nc, three_d ? 0.2 : 0.5));
    const ContactResult direct = p.solve(law, ContactMethod::UzawaGnm);
    ASSERT_TRUE(direct.summary.converged()) << direct.summary.message;
    ContactSolverOptions o;
    // Above the floor that CG's tolerance leaves in the dual change (1.7e-12 in 3D).
    o.uzawa_tolerance = 1e-11;
    o.linear.type = LinearSolverType::ConjugateGradient;
    o.linear.preconditioner = PreconditionerType::Multigrid;
    o.linear.cg_tolerance = 1e-13;
    const ContactResult mg =
        solve_contact(testing::with_law(p.problem, law), o, &p.model.multigrid);
    ASSERT_TRUE(mg.summary.converged()) << mg.summary.message;
    EXPECT_EQ(mg.summary.path, SolvePath::Backend);
    EXPECT_LT(relative(mg.u, direct.u), 1e-9) << (three_d ? "3D" : "2D");
    EXPECT_LT(relative(mg.tangential.reshaped(), direct.tangential.reshaped()), 1e-8);
  }
}

TEST(FrictionUzawaGnm, RefusesAMismatchedLawAndTheFrictionlessPaths) {
  const Frictional p(paper_benchmark(12, 4));
  const Index nc = p.problem.contact.size();
  const FrictionLaw law(FrictionKind::Tresca, 2, Vector::Constant(nc, 1.0));
  ContactSolverOptions o;
  EXPECT_THROW(static_cast<void>(solve_contact(testing::with_law(p.model.problem, law), o)),
               InputError);                    // no T rows
  o.method = ContactMethod::SemismoothNewton;  // friction's SSN factorises: not on multigrid
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.preconditioner = PreconditionerType::Multigrid;
  EXPECT_THROW(static_cast<void>(solve_contact(testing::with_law(p.problem, law), o)), InputError);
  ContactSolverOptions frictionless;
  EXPECT_THROW(static_cast<void>(solve_contact(p.problem, frictionless)), InputError);
}

}  // namespace
}  // namespace signorini

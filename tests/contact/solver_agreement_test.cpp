// A second and third method on the same discrete problem: the modified-Lagrangian Uzawa-GNM, the
// semismooth Newton (primal-dual active set) method, which has no penalty parameter, and the
// classical Uzawa method agree on u and l; the KKT residuals vanish; r changes nothing.

#include <gtest/gtest.h>

#include <array>

#include "signorini/contact/kkt_residuals.hpp"
#include "test_problems.hpp"

namespace signorini {
namespace {

using testing::paper_model;
using testing::relative_difference;

ContactResult solve_with(const ContactProblem& p, ContactMethod method, double tol,
                         double r = 1e8) {
  ContactSolverOptions o;
  o.method = method;
  o.uzawa_tolerance = tol;
  o.r = r;
  o.max_uzawa_iterations = 20000;
  return solve_contact(p, o);
}

// The three methods on p: each converged with small KKT residuals, u and l equal to 1e-8, the
// same active set, not empty. Sets the Uzawa-GNM and semismooth Newton results.
void expect_three_methods_agree(const ContactProblem& p, ContactResult& gnm, ContactResult& ssn) {
  ssn = solve_with(p, ContactMethod::SemismoothNewton, 1e-12);
  gnm = solve_with(p, ContactMethod::UzawaGnm, 1e-12);
  const ContactResult cla = solve_with(p, ContactMethod::ClassicalUzawa, 1e-14);
  for (const ContactResult* r : std::array<const ContactResult*, 3>{&ssn, &gnm, &cla}) {
    ASSERT_TRUE(r->summary.converged()) << r->summary.message;
    EXPECT_LT(r->summary.kkt.max(), 1e-8) << enum_to_string(kContactMethodNames, r->summary.method);
  }
  EXPECT_LT(relative_difference(gnm.u, ssn.u), 1e-8);
  EXPECT_LT(relative_difference(gnm.l, ssn.l), 1e-8);
  EXPECT_LT(relative_difference(cla.u, ssn.u), 1e-8);
  EXPECT_LT(relative_difference(cla.l, ssn.l), 1e-8);
  EXPECT_EQ(ssn.summary.num_active, gnm.summary.num_active);
  EXPECT_GT(ssn.summary.num_active, 0);
}

TEST(SolverAgreement, ThreeMethodsAgreeOnUAndL) {
  const ContactProblem& p = paper_model(60).problem;
  ContactResult gnm, ssn;
  expect_three_methods_agree(p, gnm, ssn);
  // The semismooth Newton active set is exact: l > 0 exactly where the body touches.
  EXPECT_LT(ssn.summary.num_active, p.contact.size());
}

TEST(SolverAgreement, KktResidualsAtDefaultTolerances) {
  const ContactProblem& p = paper_model(120).problem;
  for (const auto method : {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton}) {
    ContactSolverOptions o;
    o.method = method;
    const ContactResult r = solve_contact(p, o);
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    EXPECT_LT(r.summary.kkt.equilibrium, 1e-8);
    EXPECT_LT(r.summary.kkt.penetration, 1e-8);
    EXPECT_LT(r.summary.kkt.sign, 1e-8);
    EXPECT_LT(r.summary.kkt.complementarity, 1e-8);
    // The summary's residuals are those of the returned (u, l).
    const KktResiduals k = kkt_residuals(p, r.u, r.l);
    EXPECT_DOUBLE_EQ(k.equilibrium, r.summary.kkt.equilibrium);
  }
}

TEST(SolverAgreement, SolutionDoesNotDependOnR) {
  const ContactProblem& p = paper_model(60).problem;
  const ContactResult ref = solve_with(p, ContactMethod::SemismoothNewton, 1e-12);
  for (const double r : {1e4, 1e8, 1e10}) {
    const ContactResult res = solve_with(p, ContactMethod::UzawaGnm, 1e-13, r);
    ASSERT_TRUE(res.summary.converged()) << "r = " << r << ": " << res.summary.message;
    EXPECT_LT(relative_difference(res.u, ref.u), 1e-8) << "r = " << r;
    EXPECT_LT(relative_difference(res.l, ref.l), 1e-8) << "r = " << r;
  }
}

TEST(SolverAgreement, ConjugateGradientsGiveTheDirectSolution) {
  const ContactProblem& p = paper_model(60).problem;
  ContactSolverOptions o;
  const ContactResult direct = solve_contact(p, o);
  o.linear.type = LinearSolverType::ConjugateGradient;
  o.linear.cg_tolerance = 1e-14;
  const ContactResult cg = solve_contact(p, o);
  ASSERT_TRUE(cg.summary.converged()) << cg.summary.message;
  EXPECT_NEAR(cg.summary.lagrangian, direct.summary.lagrangian,
              1e-8 * std::abs(direct.summary.lagrangian));
  EXPECT_LT(relative_difference(cg.u, direct.u), 1e-6);
  EXPECT_EQ(cg.summary.outer_iterations, direct.summary.outer_iterations);
  int cg_iterations = 0;
  for (const auto& s : cg.summary.steps) cg_iterations += s.linear_iterations;
  EXPECT_GT(cg_iterations, 0);  // the records count CG iterations
}

// The paper's problem on every 2D cell type (30x10 squares; quadratic cells put a contact node on
// every mid-edge node of the bottom): the three methods agree, the KKT residuals vanish, and the
// energies of the five discretisations lie close together, the quadratic ones lowest (they are
// the most flexible, closer to the continuous minimum).
class SolverAgreementCells : public ::testing::TestWithParam<CellType> {};

TEST_P(SolverAgreementCells, ThreeMethodsAgreeOnEveryCellType) {
  ProblemSpec spec = paper_benchmark(30, 10);
  spec.mesh.cell = GetParam();
  const Model model = build_model(spec);
  const ContactProblem& p = model.problem;
  EXPECT_EQ(p.contact.size(), cell_order(GetParam()) * 30 + 1);
  EXPECT_NEAR(p.contact.weights.sum(), 3.0, 1e-13);  // int_{Gamma_C} 1 ds = the bottom's length
  ContactResult gnm, ssn;
  expect_three_methods_agree(p, gnm, ssn);
  // r does not change the solution.
  const ContactResult other_r = solve_with(p, ContactMethod::UzawaGnm, 1e-12, 1e6);
  EXPECT_LT(relative_difference(other_r.u, gnm.u), 1e-8);
  // The energy M(u*, l*) = J(u*): near the Q1 value on 480x160 (-6.71574e-05), within 0.1 % for
  // quadratic cells and 5 % for P1 triangles (stiff on so coarse a mesh: 3.5 % here), and for
  // quadratic cells below the Q1 one on the same squares.
  EXPECT_NEAR(gnm.summary.energy / -6.71574494461115e-05, 1.0,
              cell_order(GetParam()) == 2 ? 1e-3 : 5e-2);
  if (cell_order(GetParam()) == 2) {
    static const double q1 = [] {
      const Model m = build_model(paper_benchmark(30, 10));
      return solve_with(m.problem, ContactMethod::SemismoothNewton, 1e-12).summary.energy;
    }();
    EXPECT_LT(gnm.summary.energy, q1);
  }
}

INSTANTIATE_TEST_SUITE_P(CellTypes, SolverAgreementCells,
                         ::testing::Values(CellType::Tri3, CellType::Tri6, CellType::Quad8,
                                           CellType::Quad9),
                         [](const auto& param_info) {
                           return std::string(enum_to_string(kCellTypeNames, param_info.param));
                         });

}  // namespace
}  // namespace signorini

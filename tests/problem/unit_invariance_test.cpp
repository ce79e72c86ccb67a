// Right answers in any consistent units: the same physical problem in m and MPa, m and Pa, and mm
// and N (N/mm^2 = MPa) gives the same iterations and the same solution, scaled, with the default
// (automatic) r, for every method; so do the steel block (m, Pa) and the rubber pad (mm, N)
// against their conversions. An r far from the automatic one either converges with small KKT
// residuals or says it did not: never "converged" with a residual above the tolerance.

#include <gtest/gtest.h>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

struct SolvedRun {
  Model model;
  ContactResult result;
};

SolvedRun solve(const std::string& example, std::vector<std::string> overrides,
                ContactMethod method) {
  overrides.push_back("solver.method=" + std::string(enum_to_string(kContactMethodNames, method)));
  const LoadedProblem p =
      read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/" + example, overrides);
  EXPECT_FALSE(p.spec.solver.r.has_value()) << "the automatic r is what is tested";
  Model model = build_model(p.spec);
  ContactResult result = solve_contact(model.problem, p.spec.solver);
  return {std::move(model), std::move(result)};
}

// Same iteration path, and u, l equal after scaling by the unit changes (to 1e-9).
void expect_same_solution(const SolvedRun& a, const SolvedRun& b, double length_scale,
                          double stress_scale, const std::string& what) {
  const SolveSummary& sa = a.result.summary;
  const SolveSummary& sb = b.result.summary;
  ASSERT_TRUE(sa.converged()) << what << ": " << sa.message;
  ASSERT_TRUE(sb.converged()) << what << ": " << sb.message;
  EXPECT_EQ(sa.outer_iterations, sb.outer_iterations) << what;
  EXPECT_EQ(sa.inner_iterations(), sb.inner_iterations()) << what;
  EXPECT_LT((b.result.u - length_scale * a.result.u).norm(), 1e-9 * b.result.u.norm()) << what;
  EXPECT_LT((b.result.l - stress_scale * a.result.l).norm(), 1e-9 * b.result.l.norm()) << what;
  // r is a stress per length.
  EXPECT_NEAR(sb.r, sa.r * stress_scale / length_scale, 1e-12 * sb.r) << what;
}

class UnitInvariance : public ::testing::TestWithParam<ContactMethod> {};

TEST_P(UnitInvariance, PaperProblemInMetresAndMegapascalsPascalsAndMillimetres) {
  const ContactMethod m = GetParam();
  // The example keeps the paper's r = 1e8; "auto" asks for the automatic choice.
  const std::vector<std::string> base = {"solver.r=auto"};
  const SolvedRun mpa = solve("paper_small.toml", base, m);
  std::vector<std::string> pa = base;
  for (const char* o : {"material.E=21.19e10", "traction.0.p=[0, 1e6]",
                        "traction.1.p=[\"0\", \"-2/3*(3 - x)*1e6\"]"})
    pa.emplace_back(o);
  expect_same_solution(mpa, solve("paper_small.toml", pa, m), 1.0, 1e6, "Pa");
  std::vector<std::string> mm = base;
  for (const char* o :
       {"mesh.length=3000", "mesh.height=1000", "traction.1.p=[\"0\", \"-2/3*(3 - x/1000)\"]"})
    mm.emplace_back(o);
  expect_same_solution(mpa, solve("paper_small.toml", mm, m), 1e3, 1.0, "N, mm");
}

TEST_P(UnitInvariance, SteelBlockInPascalsAndInMillimetres) {
  const ContactMethod m = GetParam();
  const std::vector<std::string> coarse = {"mesh.nx=40", "mesh.ny=20"};
  const SolvedRun pa = solve("steel_block_cylinder.toml", coarse, m);
  std::vector<std::string> mm = coarse;
  for (const char* o : {"units=mm-MPa", "mesh.length=40", "mesh.height=20", "material.E=210e3",
                        "contact.gap=500 - sqrt(500^2 - (x - 20)^2) - 10e-3"})
    mm.emplace_back(o);
  expect_same_solution(pa, solve("steel_block_cylinder.toml", mm, m), 1e3, 1e-6, "steel, mm");
}

TEST_P(UnitInvariance, RubberPadInMillimetresAndInMetres) {
  const ContactMethod m = GetParam();
  const std::vector<std::string> coarse = {"mesh.nx=40", "mesh.ny=10"};
  const SolvedRun mm = solve("rubber_pad.toml", coarse, m);
  std::vector<std::string> metres = coarse;
  for (const char* o : {"units=m-Pa", "mesh.length=0.04", "mesh.height=0.01", "material.E=5e6",
                        "traction.0.p=[0, -0.2e6]", "contact.gap=0.05e-3"})
    metres.emplace_back(o);
  expect_same_solution(mm, solve("rubber_pad.toml", metres, m), 1e-3, 1e6, "rubber, m");
}

INSTANTIATE_TEST_SUITE_P(Methods, UnitInvariance,
                         ::testing::Values(ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton,
                                           ContactMethod::ClassicalUzawa),
                         [](const auto& param_info) {
                           return std::string(
                               enum_to_string(kContactMethodNames, param_info.param));
                         });

// Converged means the KKT residuals are small, whatever r is: r = 1e20 loses the Newton systems'
// digits (equilibrium residual 4e-2), r = 1e2 barely moves the multipliers (1000 steps).
TEST(ExtremeR, NeverConvergedWithLargeResiduals) {
  for (const char* r : {"solver.r=1e20", "solver.r=1e2", "solver.r=1e14", "solver.r=1e4"}) {
    const LoadedProblem p =
        read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/paper_small.toml", {r});
    const Model model = build_model(p.spec);
    const ContactResult res = solve_contact(model.problem, p.spec.solver);
    const SolveSummary& s = res.summary;
    EXPECT_TRUE(s.converged() == (s.kkt.max() <= p.spec.solver.kkt_tolerance))
        << r << ": " << s.message;
    if (!s.converged()) {
      // The message says what to try, starting with the automatic r.
      EXPECT_NE(s.message.find("remove solver.r to use the automatic choice"), std::string::npos)
          << r << ": " << s.message;
    }
  }
  // The two cases of the report, precisely.
  const auto run = [](const char* r) {
    const LoadedProblem p =
        read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/paper_small.toml", {r});
    const Model model = build_model(p.spec);
    return solve_contact(model.problem, p.spec.solver).summary;
  };
  const SolveSummary huge = run("solver.r=1e20");
  EXPECT_EQ(huge.termination, Termination::KktResidualsTooLarge) << huge.message;
  EXPECT_GT(huge.kkt.equilibrium, 1e-6);
  const SolveSummary tiny = run("solver.r=1e2");
  EXPECT_EQ(tiny.termination, Termination::IterationLimit) << tiny.message;
}

}  // namespace
}  // namespace signorini

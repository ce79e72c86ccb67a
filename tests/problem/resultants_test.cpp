// Resultants: the applied load against its value by hand, loads on part of an edge integrated
// exactly, point loads where they land, and the balance of applied load, clamp reactions and
// contact force on every example.

#include "signorini/problem/resultants.hpp"

#include <gtest/gtest.h>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/input/problem_file.hpp"

namespace signorini {
namespace {

struct Solved {
  Model model;
  ContactResult result;
  Resultants resultants;
};

Solved solve_file(const std::string& name, const std::vector<std::string>& overrides = {}) {
  const LoadedProblem p =
      read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/" + name, overrides);
  Model model = build_model(p.spec);
  ContactResult result = solve_contact(model.problem, p.spec.solver);
  Resultants r = compute_resultants(model, result.u, result.l);
  return {std::move(model), std::move(result), r};
}

TEST(Resultants, EveryExampleBalances) {
  for (const char* example : {"paper_small.toml", "steel_block_cylinder.toml", "rubber_pad.toml",
                              "beam_on_curved_support.toml"}) {
    const Solved s = solve_file(example, {"mesh.nx=40", "mesh.ny=10"});
    ASSERT_TRUE(s.result.summary.converged()) << example << ": " << s.result.summary.message;
    EXPECT_LT(s.resultants.relative_balance, 1e-10) << example;
    EXPECT_LT(s.resultants.relative_moment_balance, 1e-10) << example;
    // The foundation pushes, along its normal (0, -1) turned inward: up.
    EXPECT_GE(s.resultants.contact(1), 0.0) << example;
    EXPECT_NEAR(s.resultants.contact(1), s.result.summary.contact_force,
                1e-12 * std::abs(s.result.summary.contact_force))
        << example;
  }
}

TEST(Resultants, AppliedLoadOfThePaperAndTheBeamByHand) {
  // Paper: (0, 1) on the right edge (length 1) and (0, -2/3 (3 - x)) on the top (integral -3).
  const Solved paper = solve_file("paper_small.toml");
  EXPECT_NEAR(paper.resultants.applied(0), 0.0, 1e-14);
  EXPECT_NEAR(paper.resultants.applied(1), -2.0, 1e-13);
  // Beam: -0.5 over x in [0.75, 1.25] (ends between nodes on a 40-cell mesh) and -0.02 at the end.
  const Solved beam = solve_file("beam_on_curved_support.toml", {"mesh.nx=40", "mesh.ny=4"});
  EXPECT_NEAR(beam.resultants.applied(1), -0.27, 1e-14);
  ASSERT_EQ(beam.model.point_loads.size(), 1U);
  EXPECT_EQ(beam.model.point_loads[0].at, Point(2.0, 0.2, 0.0));
  EXPECT_EQ(beam.model.point_loads[0].distance, 0.0);
}

TEST(Resultants, WithoutContactTheClampTakesTheWholeLoad) {
  const Solved s = solve_file("paper_small.toml", {"contact.gap=1"});
  ASSERT_EQ(s.result.summary.num_active, 0);
  ASSERT_EQ(s.resultants.reactions.size(), 1U);
  EXPECT_EQ(s.resultants.reactions[0].boundary, "left");
  EXPECT_NEAR(s.resultants.reactions[0].force(0), -s.resultants.applied(0), 1e-11);
  EXPECT_NEAR(s.resultants.reactions[0].force(1), -s.resultants.applied(1), 1e-11);
  EXPECT_NEAR(s.resultants.reactions[0].moment(2), -s.resultants.applied_moment(2), 1e-11);
}

TEST(Resultants, LoadOnPartOfAnEdgeIsIntegratedExactly) {
  // 25 over x in [1.999, 2.001] on cells 0.05 long: the range lies inside one facet, between its
  // Gauss points, which a formula with "?" would miss entirely.
  const Solved ranged = solve_file("paper_small.toml",
                                   {"traction.1.p=[0, -25]", "traction.1.x_range=[1.999, 2.001]"});
  EXPECT_NEAR(ranged.resultants.applied(1), 1.0 - 0.05, 1e-13);
  const Solved sampled =
      solve_file("paper_small.toml", {"traction.1.p=[0, \"abs(x - 2.0) < 0.001 ? -25 : 0\"]"});
  EXPECT_GT(std::abs(sampled.resultants.applied(1) - (1.0 - 0.05)), 0.01);  // why ranges exist
  // A linear load over a range that cuts two facets: exact, int_0.33^1.27 x dx.
  const Solved linear = solve_file("paper_small.toml",
                                   {"traction.1.p=[0, \"x\"]", "traction.1.x_range=[0.33, 1.27]"});
  EXPECT_NEAR(linear.resultants.applied(1), 1.0 + (1.27 * 1.27 - 0.33 * 0.33) / 2.0, 1e-13);
  // Its moment about the reference point: int x (x - x_ref) dx over the range, plus the right
  // edge's unit force at x = 3.
  const double xr = linear.resultants.reference(0);
  const auto cube = [](double x) { return x * x * x; };
  const double expected =
      (cube(1.27) - cube(0.33)) / 3.0 - xr * (1.27 * 1.27 - 0.33 * 0.33) / 2.0 + (3.0 - xr) * 1.0;
  EXPECT_NEAR(linear.resultants.applied_moment(2), expected, 1e-12);
}

TEST(Resultants, PointLoadLandsOnTheNearestNode) {
  const LoadedProblem p = parse_problem_string(
      read_problem_file(std::string(SIGNORINI_EXAMPLES_DIR) + "/paper_small.toml").effective_toml +
          "\n[[point_load]]\nat = [1.01, 0.98]\nforce = [0.5, -1]\n",
      "t.toml");
  const Model model = build_model(p.spec);
  ASSERT_EQ(model.point_loads.size(), 1U);
  const PlacedPointLoad& pl = model.point_loads[0];
  EXPECT_NEAR(pl.at(0), 1.0, 1e-14);  // the 60 x 20 grid has nodes every 0.05
  EXPECT_NEAR(pl.at(1), 1.0, 1e-14);
  EXPECT_NEAR(pl.distance, std::hypot(0.01, 0.02), 1e-14);
  const ContactResult r = solve_contact(model.problem, p.spec.solver);
  const Resultants res = compute_resultants(model, r.u, r.l);
  EXPECT_NEAR(res.applied(0), 0.5, 1e-14);
  EXPECT_NEAR(res.applied(1), -2.0 - 1.0, 1e-13);
  EXPECT_LT(res.relative_balance, 1e-10);
}

}  // namespace
}  // namespace signorini

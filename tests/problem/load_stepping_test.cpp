// Loading histories (problem/load_stepping.hpp): without friction each step is the solution of
// its own loads (the path does not matter, and with zero gaps the solution is proportional to
// the load); prescribed displacements and gaps scale as the issue says (loads and prescribed
// displacements by the factor, not the gaps); with Coulomb friction the path matters (loading
// to 1 and back to 0.5 leaves a different state than loading to 0.5), each step meets the
// tangential conditions with its own slip increment, and the slip accumulates.

#include "signorini/problem/load_stepping.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"

namespace signorini {
namespace {

double relative(const Vector& a, const Vector& b) {
  return (a - b).norm() / b.norm();
}

ContactSolverOptions tight(const Model& model) {
  ContactSolverOptions o = model.solver;
  o.uzawa_tolerance = 1e-12;
  return o;
}

TEST(LoadStepping, FrictionlessStepsAreTheSolutionsOfTheirLoads) {
  const Model model = build_model(paper_benchmark(30, 10));
  const ContactResult one = solve_contact(model.problem, tight(model));
  std::vector<ContactResult> steps;
  const ContactResult last = solve_load_steps(
      model, tight(model), {0.5, 1.0}, [&](int, const ContactResult& r) { steps.push_back(r); });
  ASSERT_EQ(steps.size(), 2U);
  ASSERT_TRUE(last.summary.converged());
  EXPECT_TRUE(steps[1].summary.warm_started);
  EXPECT_EQ(last.summary.load_steps.size(), 2U);
  EXPECT_EQ(steps[0].load_factor, 0.5);
  EXPECT_LT(relative(last.u, one.u), 1e-9);
  // Zero gaps: the solution is homogeneous of degree one in the load.
  EXPECT_LT(relative(steps[0].u, 0.5 * one.u), 1e-9);
  EXPECT_LT(relative(steps[0].l, 0.5 * one.l), 1e-9);
}

// A block pushed down onto a ball by its prescribed top displacement: at factor t the top
// moves t times as far, while the ball (the gaps) stays where it is.
TEST(LoadStepping, PrescribedDisplacementsScaleAndGapsStay) {
  const std::string file = SIGNORINI_EXAMPLES_DIR "/box_on_sphere.toml";
  const std::vector<std::string> coarse = {"mesh.nx=6", "mesh.ny=6", "mesh.nz=3"};
  const Model model = build_model(read_problem_file(file, coarse).spec);
  std::vector<ContactResult> steps;
  static_cast<void>(solve_load_steps(model, tight(model), {0.6, 1.0},
                                     [&](int, const ContactResult& r) { steps.push_back(r); }));
  ASSERT_EQ(steps.size(), 2U);
  const ContactResult full = solve_contact(model.problem, tight(model));
  EXPECT_LT(relative(steps[1].u, full.u), 1e-8);
  // The same problem with its top moved 0.6 times as far, solved directly.
  ProblemSpec reduced = read_problem_file(file, coarse).spec;
  for (DisplacementSpec& d : reduced.displacements)
    for (ScalarField& f : d.values)
      if (f) f = [g = f](const Point& x) { return 0.6 * g(x); };
  const Model partial = build_model(reduced);
  const ContactResult direct = solve_contact(partial.problem, tight(partial));
  ASSERT_GT(direct.summary.num_active, 0);
  EXPECT_LT(relative(steps[0].u, direct.u), 1e-8);
  EXPECT_LT(relative(steps[0].l, direct.l), 1e-8);
  EXPECT_LT(relative(model.full_displacement(steps[0]), partial.dofs.expand(direct.u)), 1e-8);
}

TEST(LoadStepping, CoulombDependsOnThePathAndAccumulatesSlip) {
  ProblemSpec spec = paper_benchmark(30, 10);
  spec.contacts[0].friction = FrictionModel::Coulomb;
  spec.contacts[0].mu = 0.5;
  const Model model = build_model(spec);
  ASSERT_TRUE(contact_law(model.problem).has_friction());
  std::vector<ContactResult> steps;
  const ContactResult back =
      solve_load_steps(model, tight(model), {0.5, 1.0, 0.5},
                       [&](int, const ContactResult& r) { steps.push_back(r); });
  ASSERT_EQ(steps.size(), 3U);
  for (const ContactResult& r : steps) {
    ASSERT_TRUE(r.summary.converged()) << r.summary.message;
    // Each step's slip is measured from the previous step: its tangential conditions hold.
    EXPECT_LT(r.summary.kkt.friction_bound, 1e-9);
    EXPECT_LT(r.summary.kkt.slip, 1e-9);
  }
  // Loading to 0.5 directly is the first step; coming back from 1 leaves another state.
  EXPECT_GT(relative(back.u, steps[0].u), 1e-3);
  // The slip accumulates: at least the step's own, and the path length.
  const Vector& s0 = steps[0].slip;
  const Vector& s2 = steps[2].slip;
  ASSERT_EQ(s2.size(), model.problem.contact.size());
  for (Index j = 0; j < s2.size(); ++j) EXPECT_GE(s2(j), s0(j) - 1e-15);
  EXPECT_GT((s2 - s0).maxCoeff(), 0.0);
}

// Loads and displacements with factors of their own: at each step the model is the one whose
// entries are each scaled by their factor (the others by the history's), built directly; so are
// its free loads, gaps, applied loads and full displacements, and (frictionless: the path does
// not matter) the solution of each step.
TEST(LoadStepping, OwnFactorsActAsTheEntriesScaledAlone) {
  const std::vector<double> history = {0.8, 1.0};
  const std::vector<double> traction = {0.0, 0.5}, point = {0.0, 3.0}, pull = {1.0, 0.25};
  const auto spec_of = [&](std::optional<std::size_t> step) {
    ProblemSpec spec = paper_benchmark(12, 4);
    PointLoadSpec pl;
    pl.at = Point(1.5, 1.0, 0.0);
    pl.force = Eigen::Vector3d(0.0, -0.2, 0.0);
    spec.point_loads = {pl};
    DisplacementSpec d;
    d.boundary = "right";
    d.values[0] = [](const Point&) { return -2e-6; };
    d.texts[0] = "-2e-6";
    spec.displacements = {d};
    if (!step) {  // the loading history, each entry's own factors
      spec.load_factors = history;
      spec.tractions[0].factors = traction;
      spec.point_loads[0].factors = point;
      spec.displacements[0].factors = pull;
      return spec;
    }
    const std::size_t k = *step;  // the same, each entry scaled by its factor of step k
    const auto scaled = [](VectorField f, double t) {
      return [f, t](const Point& x) -> Eigen::Vector3d { return t * f(x); };
    };
    spec.tractions[0].p = scaled(spec.tractions[0].p, traction[k]);
    spec.tractions[1].p = scaled(spec.tractions[1].p, history[k]);
    spec.point_loads[0].force *= point[k];
    spec.displacements[0].values[0] = [t = pull[k]](const Point&) { return -2e-6 * t; };
    return spec;
  };
  const Model model = build_model(spec_of(std::nullopt));
  ASSERT_EQ(model.load_groups.size(), 3U);
  std::vector<ContactResult> steps;
  static_cast<void>(solve_load_steps(model, tight(model), history,
                                     [&](int, const ContactResult& r) { steps.push_back(r); }));
  ASSERT_EQ(steps.size(), 2U);
  for (std::size_t k = 0; k < history.size(); ++k) {
    const Model direct = build_model(spec_of(k));
    const int step = static_cast<int>(k) + 1;
    const double t = history[k];
    EXPECT_LT(relative(model.free_loads(t, step), direct.problem.b), 1e-13) << step;
    EXPECT_LT(relative(model.applied_loads(t, step), direct.loads), 1e-13) << step;
    EXPECT_LT((model.contact_gaps(t, step) - direct.problem.contact.gaps).norm(), 1e-18) << step;
    const ContactResult r = solve_contact(direct.problem, tight(direct));
    ASSERT_TRUE(r.summary.converged());
    ASSERT_GT(r.summary.num_active, 0);
    ASSERT_TRUE(steps[k].summary.converged());
    EXPECT_EQ(steps[k].load_step, step);
    EXPECT_LT(relative(steps[k].u, r.u), 1e-8) << step;
    EXPECT_LT(relative(steps[k].l, r.l), 1e-8) << step;
    EXPECT_LT(relative(model.full_displacement(steps[k]), direct.dofs.expand(r.u)), 1e-8) << step;
  }
  // A history of another length than the entries' own factors is refused, naming the entry.
  try {
    static_cast<void>(solve_load_steps(model, tight(model), {1.0}));
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("traction[0].factors: expected 1"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace signorini

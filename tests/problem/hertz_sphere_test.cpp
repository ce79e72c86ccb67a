// Hertz's contact of an elastic ball on a rigid plane (examples/gmsh/hertz_sphere.geo: a quarter
// of the lower half of a ball of radius R = 1, its flat top pushed down by d, rollers on the
// symmetry planes). From the total force F the solver finds, Hertz gives the contact radius
// a = (3 F R / (4 E*))^(1/3) with E* = E / (1 - nu^2), and the pressure p(r) = p0 sqrt(1 - r^2/a^2)
// with p0 = 3 F / (2 pi a^2). The nodes in contact must straddle a, the pressure follow the
// profile, and the errors fall from the coarse mesh to the fine one; the methods agree.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <numbers>

#include "problem/each_method.hpp"
#include "problem/hertz_ball.hpp"
#include "signorini/contact/contact_solver.hpp"
#include "signorini/core/error.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

constexpr double kE = 1.0, kNu = 0.3, kR = 1.0, kD = 1e-3;

// (kE, kNu and kD are the ball's of hertz_ball.hpp.)
ProblemSpec ball(const std::string& mesh) {
  return testing::hertz_ball(mesh);
}

struct HertzErrors {
  double radius;    // |a_found - a| / a, a_found halfway between the last node in and the first out
  double peak;      // |l(pole) - p0| / p0
  double profile;   // max_j |l_j - p(r_j)| / p0
  double rms;       // the root mean square of l_j - p(r_j) over the nodes within a, / p0
  double straddle;  // the gap between the last node in contact and the first out, / a
};

HertzErrors hertz_errors(const Model& model, const ContactResult& r) {
  const ContactSet& c = model.problem.contact;
  const double F = 4.0 * r.summary.contact_force;  // the whole ball: four quarters
  const double a = std::cbrt(3.0 * F * kR / (4.0 * kE / (1.0 - kNu * kNu)));
  const double p0 = 3.0 * F / (2.0 * std::numbers::pi * a * a);
  double in = 0.0, out = 1e9, pole = 0.0, profile = 0.0, sum2 = 0.0;
  int inside = 0;
  for (Index j = 0; j < c.size(); ++j) {
    const Point x = model.mesh.point(c.nodes[static_cast<std::size_t>(j)]);
    const double rr = std::hypot(x(0), x(1));
    if (r.l(j) > 0.0)
      in = std::max(in, rr);
    else
      out = std::min(out, rr);
    if (rr < 1e-12) pole = r.l(j);
    const double p = rr < a ? p0 * std::sqrt(1.0 - rr * rr / (a * a)) : 0.0;
    profile = std::max(profile, std::abs(r.l(j) - p));
    if (rr < a) {
      sum2 += (r.l(j) - p) * (r.l(j) - p);
      ++inside;
    }
  }
  return {std::abs(0.5 * (in + out) - a) / a, std::abs(pole - p0) / p0, profile / p0,
          std::sqrt(sum2 / std::max(inside, 1)) / p0, (out - in) / a};
}

TEST(HertzSphere, ContactRadiusAndPressureApproachHertzUnderRefinement) {
  std::vector<HertzErrors> errors;
  for (const char* mesh : {"hertz_sphere_coarse.msh", "hertz_sphere.msh"}) {
    SCOPED_TRACE(mesh);
    const ProblemSpec spec = ball(mesh);
    const Model model = build_model(spec);
    std::vector<ContactResult> results;
    ASSERT_NO_FATAL_FAILURE(testing::solve_by_each(
        model, spec.solver, {ContactMethod::UzawaGnm, ContactMethod::SemismoothNewton}, results));
    testing::expect_same_solution(results, 1e-8, 1e-7);
    const HertzErrors e = hertz_errors(model, results[0]);
    std::cout << mesh << ": " << model.mesh.num_nodes() << " nodes, "
              << model.problem.contact.size() << " contact nodes, " << results[0].summary.num_active
              << " in contact; errors: radius " << e.radius << ", peak " << e.peak << ", profile "
              << e.profile << " (root mean square " << e.rms << "; node spacing at the edge "
              << e.straddle << " a)\n";
    errors.push_back(e);
  }
  // What the fine mesh reaches (cells 0.004 long, a = 0.038: about 10 along a radius of the
  // contact zone); the errors of the whole profile, largest at the edge where p falls like a
  // square root, halve from the coarse mesh. The peak, one node's value on an unstructured mesh,
  // stays within a few percent on both.
  EXPECT_LT(errors[1].radius, 0.01);
  EXPECT_LT(errors[1].peak, 0.03);
  EXPECT_LT(errors[1].rms, 0.06);
  EXPECT_LT(errors[1].rms, 0.6 * errors[0].rms);
  EXPECT_LT(errors[1].profile, 0.17);
  EXPECT_LT(errors[1].profile, 0.7 * errors[0].profile);
  EXPECT_LT(errors[1].radius, errors[0].radius);
}

// Against the rigid plane each constraint acts along the plane's normal (method.md section 3,
// "Rigid obstacles"), the gap is the node's height above it and the weight its facets' area
// projected onto the plane: the ball's exact normal (x, y, z - R) / R, given as
// contact.surface_normal, then only tells which nodes face the plane (all of them here), so the
// contact set and the answer are those of the facets' averaged normals to the bit. With a gap
// formula the constraint acts along the body's normal: there the exact one replaces the facets'
// average (off by up to a few degrees on the coarse mesh).
TEST(HertzSphere, ThePlanesNormalWhateverTheBodysNormal) {
  ProblemSpec averaged = ball("hertz_sphere_coarse.msh");
  ProblemSpec exact = averaged;
  const auto ball_normal = [](const Point& x) { return Eigen::Vector3d(x(0), x(1), x(2) - kR); };
  exact.contacts[0].surface_normal = ball_normal;
  const Model a = build_model(averaged), e = build_model(exact);
  const ContactSet &ca = a.problem.contact, &ce = e.problem.contact;
  ASSERT_EQ(ca.size(), ce.size());
  for (Index j = 0; j < ce.size(); ++j) {
    const Point x = e.mesh.point(ce.nodes[static_cast<std::size_t>(j)]);
    EXPECT_EQ(ce.normals.col(j), Eigen::Vector3d(0.0, 0.0, -1.0));
    EXPECT_EQ(ca.normals.col(j), ce.normals.col(j));
    // (less what the prescribed displacement of the top moves a node of the rim down)
    const Index node = ce.nodes[static_cast<std::size_t>(j)];
    EXPECT_NEAR(ce.gaps(j), x(2) - ce.normals.col(j).dot(e.dofs.prescribed_at(node)), 1e-15);
    EXPECT_EQ(ca.weights(j), ce.weights(j));
  }
  const ContactResult ra = solve_contact(a.problem, averaged.solver);
  const ContactResult re = solve_contact(e.problem, exact.solver);
  ASSERT_TRUE(re.summary.converged()) << re.summary.message;
  EXPECT_LT(re.summary.kkt.max(), 1e-8);
  EXPECT_EQ(re.summary.contact_force, ra.summary.contact_force);
  const HertzErrors ee = hertz_errors(e, re);
  std::cout << "coarse mesh: radius " << ee.radius << ", peak " << ee.peak << ", rms " << ee.rms
            << "\n";
  EXPECT_LT(ee.rms, 0.15);
  EXPECT_LT(ee.radius, 0.05);

  // A gap formula: the constraint along the body's normal, the exact one where it is given.
  for (ProblemSpec* spec : {&averaged, &exact}) {
    spec->contacts[0].obstacle = RigidObstacle{};
    spec->contacts[0].gap = [](const Point& x) { return x(2); };
  }
  const Model ga = build_model(averaged), ge = build_model(exact);
  double largest_angle = 0.0;
  for (Index j = 0; j < ge.problem.contact.size(); ++j) {
    const Point x = ge.mesh.point(ge.problem.contact.nodes[static_cast<std::size_t>(j)]);
    const Eigen::Vector3d n = ball_normal(x).normalized();
    EXPECT_LT((ge.problem.contact.normals.col(j) - n).norm(), 1e-14);
    largest_angle =
        std::max(largest_angle, std::acos(std::min(1.0, ga.problem.contact.normals.col(j).dot(n))));
  }
  std::cout << "largest angle between the averaged and the exact normal: " << largest_angle
            << " rad\n";
  EXPECT_GT(largest_angle, 1e-3);  // the facets' average is not exact on the curved surface
}

// A normal field that vanishes or points into the ball is refused in one line.
TEST(HertzSphere, SurfaceNormalMustPointOutOfTheBody) {
  ProblemSpec spec = ball("hertz_sphere_coarse.msh");
  spec.contacts[0].surface_normal = [](const Point& x) {
    return Eigen::Vector3d(-x(0), -x(1), kR - x(2));
  };
  try {
    (void)build_model(spec);
    FAIL() << "an inward normal was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("contact.surface_normal at x = ("), std::string::npos);
    EXPECT_NE(std::string(err.what()).find("points into the body"), std::string::npos);
  }
  spec.contacts[0].surface_normal = [](const Point&) { return Eigen::Vector3d::Zero(); };
  try {
    (void)build_model(spec);
    FAIL() << "a zero normal was accepted";
  } catch (const InputError& err) {
    EXPECT_NE(std::string(err.what()).find("contact.surface_normal is zero"), std::string::npos);
  }
}

}  // namespace
}  // namespace signorini

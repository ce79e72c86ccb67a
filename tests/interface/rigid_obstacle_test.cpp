// Where a point is against a rigid obstacle: the signed distance from its surface (negative
// inside) and the obstacle's outward normal at the closest point, for planes, discs, balls and
// cylinders (body outside or inside); descriptions for messages; and the problem file's
// obstacle keys.

#include "signorini/interface/rigid_obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"

namespace signorini {
namespace {

void expect_at(const ObstacleDistance& d, double distance, const Eigen::Vector3d& normal) {
  EXPECT_NEAR(d.distance, distance, 1e-15);
  EXPECT_NEAR((d.normal - normal).norm(), 0.0, 1e-15) << d.normal.transpose();
}

const Eigen::Vector3d kNone = Eigen::Vector3d::Zero();

TEST(RigidObstacle, PlaneDistanceAndNormal) {
  RigidObstacle o;
  o.shape = ObstacleShape::Plane;
  o.point = {0.0, -1.0, 0.0};
  o.normal = {0.0, 2.0, 0.0};  // any length: the obstacle is y <= -1
  const Eigen::Vector3d up(0.0, 1.0, 0.0);
  expect_at(obstacle_distance(o, Point(0.3, 0.5, 0.0), kNone), 1.5, up);
  expect_at(obstacle_distance(o, Point(-7.0, 0.5, 0.0), kNone), 1.5, up);     // the same anywhere
  expect_at(obstacle_distance(o, Point(0.0, -1.25, 0.0), kNone), -0.25, up);  // inside
  EXPECT_EQ(describe(o, 2), "plane through (0, -1) with normal (0, 2)");
  EXPECT_EQ(describe(o, 3), "plane through (0, -1, 0) with normal (0, 2, 0)");
}

TEST(RigidObstacle, DiscDistanceOutsideAndInside) {
  RigidObstacle o;
  o.shape = ObstacleShape::Disc;
  o.centre = {0.0, -2.0, 0.0};
  o.radius = 1.0;
  expect_at(obstacle_distance(o, Point(0.0, 0.0, 0.0), kNone), 1.0, {0.0, 1.0, 0.0});
  // Off the axis: along the radius through the point, 5 from the centre.
  expect_at(obstacle_distance(o, Point(3.0, 2.0, 0.0), kNone), 4.0, {0.6, 0.8, 0.0});
  expect_at(obstacle_distance(o, Point(0.0, -1.1, 0.0), kNone), -0.1, {0.0, 1.0, 0.0});  // inside
  // At the centre every point of the circle is closest: the fallback normal.
  expect_at(obstacle_distance(o, Point(0.0, -2.0, 0.0), {1.0, 0.0, 0.0}), -1.0, {1.0, 0.0, 0.0});
  EXPECT_EQ(describe(o, 2), "disc of radius 1 about (0, -2)");
  // A body inside the disc (a shaft in a bore of radius 1): the material lies outside the
  // circle, its normal points to the centre.
  o.body_inside = true;
  expect_at(obstacle_distance(o, Point(0.0, -2.5, 0.0), kNone), 0.5, {0.0, 1.0, 0.0});
  expect_at(obstacle_distance(o, Point(0.6, -2.0, 0.0), kNone), 0.4, {-1.0, 0.0, 0.0});
  expect_at(obstacle_distance(o, Point(0.0, -3.5, 0.0), kNone), -0.5, {0.0, 1.0, 0.0});
  EXPECT_EQ(describe(o, 2), "disc of radius 1 about (0, -2), the body inside");
  o.radius = 0.0;
  EXPECT_THROW(validate(o), InputError);
  RigidObstacle gap;
  EXPECT_THROW((void)obstacle_distance(gap, Point::Zero(), kNone), std::logic_error);
}

TEST(RigidObstacle, HalfSpaceBallAndCylinderIn3D) {
  RigidObstacle plane;
  plane.shape = ObstacleShape::Plane;
  plane.point = {0.0, 0.0, -1.0};
  plane.normal = {0.0, 0.0, 3.0};  // the obstacle is z <= -1
  expect_at(obstacle_distance(plane, Point(0.4, -0.7, 0.5), kNone), 1.5, {0.0, 0.0, 1.0});
  // A ball of radius 1 centred at (1, 2, -2): from (1, 2 + 1.2, -2 + 1.6), 2 from the centre.
  RigidObstacle ball;
  ball.shape = ObstacleShape::Disc;
  ball.centre = {1.0, 2.0, -2.0};
  ball.radius = 1.0;
  expect_at(obstacle_distance(ball, Point(1.0, 3.2, -0.4), kNone), 1.0, {0.0, 0.6, 0.8});
  EXPECT_EQ(describe(ball, 3), "ball of radius 1 about (1, 2, -2)");
  // A roller of radius 1 along the y axis through (1, 0, -2): the same section for every y.
  RigidObstacle roller;
  roller.shape = ObstacleShape::Cylinder;
  roller.centre = {1.0, 0.0, -2.0};
  roller.axis = {0.0, 5.0, 0.0};
  expect_at(obstacle_distance(roller, Point(1.6, 7.0, -1.2), kNone), 0.0, {0.6, 0.0, 0.8});
  expect_at(obstacle_distance(roller, Point(1.0, -3.0, 0.0), kNone), 1.0, {0.0, 0.0, 1.0});
  // On the axis: the fallback.
  expect_at(obstacle_distance(roller, Point(1.0, 4.0, -2.0), {0.0, 0.0, 1.0}), -1.0,
            {0.0, 0.0, 1.0});
  roller.body_inside = true;  // a bore of radius 1
  expect_at(obstacle_distance(roller, Point(1.0, 4.0, -2.5), kNone), 0.5, {0.0, 0.0, 1.0});
  roller.axis = Eigen::Vector3d::Zero();
  EXPECT_THROW(validate(roller), InputError);
}

std::string error_of(const std::string& contact) {
  const std::string base =
      "[mesh]\nlength = 3.0\nheight = 1.0\nnx = 6\nny = 2\n[material]\nE = 1.0\nnu = 0.3\n"
      "[[clamp]]\nboundary = \"left\"\n";
  try {
    (void)parse_problem_string(base + contact, "t.toml");
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(RigidObstacle, ProblemFileKeys) {
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"disc\"\ncentre = [1, -1]\n"
                     "radius = 1\n"),
            "no error");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"plane\"\npoint = [0, 0]\n"
                     "normal = [0, 1]\n"),
            "no error");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"sphere\"\n"),
            "t.toml:13: contact.obstacle = \"sphere\": expected \"gap\", \"plane\", \"disc\" or "
            "\"cylinder\"");
  // The cylinder is a 3D obstacle: in 2D its section, a disc, stands for it.
  EXPECT_EQ(
      error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"cylinder\"\n"),
      "t.toml:13: key 'contact.obstacle' gives a cylinder (3D problems only), but the mesh is "
      "2D (mesh.type = \"rectangle\"): expected obstacle = \"disc\" (the cylinder's "
      "section)");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"plane\"\npoint = [0, 0]\n"
                     "normal = [0, 1]\nradius = 2\n"),
            "t.toml:16: contact.radius applies with obstacle = \"disc\" or \"cylinder\" only; "
            "this obstacle is \"plane\"");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"disc\"\ncentre = [1, -1]\n"
                     "radius = 1\naxis = [0, 0, 1]\n"),
            "t.toml:16: contact.axis applies with obstacle = \"cylinder\" only; this obstacle is "
            "\"disc\"");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"disc\"\ncentre = [0, 0]\n"
                     "radius = -1\n"),
            "t.toml:15: key 'contact.radius' = -1.0: expected a positive number");
  EXPECT_EQ(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"plane\"\npoint = [0, 0]\n"
                     "normal = [0, 0]\n"),
            "t.toml:15: contact.normal = [0, 0]: expected a non-zero vector pointing from the "
            "obstacle towards the body");
  EXPECT_NE(error_of("[contact]\nboundary = \"bottom\"\nobstacle = \"plane\"\npoint = [0, 0]\n")
                .find("missing required key 'contact.normal'"),
            std::string::npos);
}

}  // namespace
}  // namespace signorini

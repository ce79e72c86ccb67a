// Gaps to rigid obstacles, measured along the body's normal: exact distances for planes and discs
// (body outside or inside), negative inside the obstacle, `far` where the normal misses it; and
// the problem file's obstacle keys.

#include "signorini/fem/rigid_obstacle.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "signorini/core/error.hpp"
#include "signorini/io/problem_file.hpp"

namespace signorini {
namespace {

TEST(RigidObstacle, PlaneGapAlongTheNormal) {
  RigidObstacle o;
  o.shape = ObstacleShape::Plane;
  o.point = {0.0, -1.0, 0.0};
  o.normal = {0.0, 2.0, 0.0};  // any length: the obstacle is y <= -1
  const Eigen::Vector3d down(0.0, -1.0, 0.0);
  EXPECT_DOUBLE_EQ(obstacle_gap(o, Point(0.3, 0.5, 0.0), down, 99.0), 1.5);
  // Along a normal at 60 degrees from the vertical the way is twice as long.
  const Eigen::Vector3d slanted(std::sqrt(3.0) / 2.0, -0.5, 0.0);
  EXPECT_NEAR(obstacle_gap(o, Point(0.0, 0.0, 0.0), slanted, 99.0), 2.0, 1e-15);
  EXPECT_DOUBLE_EQ(obstacle_gap(o, Point(0.0, -1.25, 0.0), down, 99.0), -0.25);  // inside
  EXPECT_EQ(obstacle_gap(o, Point(0.0, 0.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0), 99.0), 99.0);
  EXPECT_EQ(obstacle_gap(o, Point(0.0, 0.0, 0.0), Eigen::Vector3d(0.0, 1.0, 0.0), 99.0), 99.0);
}

TEST(RigidObstacle, DiscGapOutsideAndInside) {
  RigidObstacle o;
  o.shape = ObstacleShape::Disc;
  o.centre = {0.0, -2.0, 0.0};
  o.radius = 1.0;
  const Eigen::Vector3d down(0.0, -1.0, 0.0);
  EXPECT_DOUBLE_EQ(obstacle_gap(o, Point(0.0, 0.0, 0.0), down, 99.0), 1.0);
  // Off the axis: x = 0.6 meets the circle at y = -2 + 0.8.
  EXPECT_NEAR(obstacle_gap(o, Point(0.6, 0.0, 0.0), down, 99.0), 1.2, 1e-15);
  EXPECT_EQ(obstacle_gap(o, Point(1.5, 0.0, 0.0), down, 99.0), 99.0);   // passes beside it
  EXPECT_EQ(obstacle_gap(o, Point(0.0, 0.0, 0.0), -down, 99.0), 99.0);  // looks away from it
  EXPECT_NEAR(obstacle_gap(o, Point(0.0, -1.1, 0.0), down, 99.0), -0.1, 1e-15);  // inside it
  // A body inside the disc (a shaft in a bore of radius 1): the way out along the normal.
  o.body_inside = true;
  EXPECT_NEAR(obstacle_gap(o, Point(0.0, -2.5, 0.0), down, 99.0), 0.5, 1e-15);
  EXPECT_NEAR(obstacle_gap(o, Point(0.0, -2.0, 0.0), Eigen::Vector3d(1.0, 0.0, 0.0), 99.0), 1.0,
              1e-15);
  o.radius = 0.0;
  EXPECT_THROW(validate(o), InputError);
}

TEST(RigidObstacle, HalfSpaceAndSphereIn3D) {
  RigidObstacle plane;
  plane.shape = ObstacleShape::Plane;
  plane.point = {0.0, 0.0, -1.0};
  plane.normal = {0.0, 0.0, 3.0};  // the obstacle is z <= -1
  const Eigen::Vector3d down(0.0, 0.0, -1.0);
  EXPECT_DOUBLE_EQ(obstacle_gap(plane, Point(0.4, -0.7, 0.5), down, 99.0), 1.5);
  const Eigen::Vector3d slanted(std::sqrt(3.0 / 8.0), std::sqrt(3.0 / 8.0), -0.5);  // 60 degrees
  EXPECT_NEAR(obstacle_gap(plane, Point(0.0, 0.0, 0.0), slanted, 99.0), 2.0, 1e-15);
  // A ball of radius 1 centred at (1, 2, -2): the ray down from (1.6, 2.0, 0) meets it at
  // z = -2 + 0.8, and the ray from (1, 2.6, 0) too.
  RigidObstacle ball;
  ball.shape = ObstacleShape::Disc;
  ball.centre = {1.0, 2.0, -2.0};
  ball.radius = 1.0;
  EXPECT_NEAR(obstacle_gap(ball, Point(1.6, 2.0, 0.0), down, 99.0), 1.2, 1e-15);
  EXPECT_NEAR(obstacle_gap(ball, Point(1.0, 2.6, 0.0), down, 99.0), 1.2, 1e-15);
  EXPECT_EQ(obstacle_gap(ball, Point(1.8, 2.8, 0.0), down, 99.0), 99.0);  // passes beside it
  // A roller of radius 1 along the y axis through (1, 0, -2): the same section for every y, and
  // nothing along the axis.
  RigidObstacle roller;
  roller.shape = ObstacleShape::Cylinder;
  roller.centre = {1.0, 0.0, -2.0};
  roller.axis = {0.0, 5.0, 0.0};
  EXPECT_NEAR(obstacle_gap(roller, Point(1.6, 7.0, 0.0), down, 99.0), 1.2, 1e-15);
  EXPECT_NEAR(obstacle_gap(roller, Point(1.6, -3.0, 0.0), down, 99.0), 1.2, 1e-15);
  const Eigen::Vector3d tilted = Eigen::Vector3d(0.0, 1.0, -1.0).normalized();  // 45 degrees
  EXPECT_NEAR(obstacle_gap(roller, Point(1.0, 0.0, 0.0), tilted, 99.0), std::sqrt(2.0), 1e-14);
  EXPECT_EQ(obstacle_gap(roller, Point(1.0, 0.0, -2.0), Eigen::Vector3d(0, 1, 0), 99.0), 99.0);
  roller.body_inside = true;  // a bore of radius 1: out along the normal
  EXPECT_NEAR(obstacle_gap(roller, Point(1.0, 4.0, -2.5), down, 99.0), 0.5, 1e-15);
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

#pragma once
// Hertz's ball (examples/hertz_sphere.toml): a quarter of the lower half of an elastic ball of
// radius 1 (E = 1, nu = 0.3; examples/gmsh/<mesh>), on rollers on its symmetry planes, its flat
// top pushed down by 0.001 onto the rigid plane z = 0. The problem of the Hertz tests and of the
// partition test of the distributed path.

#include <string>

#include "signorini/problem/problem_spec.hpp"

namespace signorini::testing {

inline ProblemSpec hertz_ball(const std::string& mesh) {
  ProblemSpec spec;
  spec.name = "hertz_sphere";
  spec.mesh_type = MeshType::Gmsh;
  spec.mesh_file = std::string(SIGNORINI_EXAMPLES_DIR) + "/gmsh/" + mesh;
  spec.elasticity.material = {1.0, 0.3};
  spec.clamps = {{"xsym", {true, false, false}}, {"ysym", {false, true, false}}};
  DisplacementSpec top;
  top.boundary = "top";
  top.values[2] = [](const Point&) { return -1e-3; };
  top.texts[2] = "-0.001";
  spec.displacements = {top};
  ContactSpec plane;
  plane.boundary = "contact";
  plane.obstacle.shape = ObstacleShape::Plane;
  plane.obstacle.point = Eigen::Vector3d::Zero();
  plane.obstacle.normal = Eigen::Vector3d(0.0, 0.0, 1.0);
  spec.contacts = {plane};
  return spec;
}

}  // namespace signorini::testing

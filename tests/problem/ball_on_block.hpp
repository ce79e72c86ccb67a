#pragma once
// A rigid ball (a sphere obstacle of radius 2, centred over the middle of the face) pressed
// `interference` into the bottom face zmin of a 1 x 1 x 0.5 block of n x n x n/2 cells clamped on
// its top: the 3D problem of the path tests, the plot test and bench/micro_benchmarks.cpp.

#include "signorini/problem/problem_spec.hpp"

namespace signorini::testing {

inline ProblemSpec ball_on_block(Index n, double interference, CellType cell = CellType::Hex8) {
  ProblemSpec spec;
  spec.name = "ball";
  spec.mesh_type = MeshType::Box;
  spec.box.height = 0.5;
  spec.box.nx = spec.box.ny = n;
  spec.box.nz = n / 2;
  spec.box.cell = cell;
  spec.elasticity.material = {1000.0, 0.3};
  spec.clamps = {{"zmax", {true, true, true}}};
  ContactSpec ball;
  ball.boundary = "zmin";
  ball.obstacle.shape = ObstacleShape::Disc;  // a sphere in 3D
  ball.obstacle.radius = 2.0;
  ball.obstacle.centre = Eigen::Vector3d(0.5, 0.5, -2.0 + interference);
  spec.contacts = {ball};
  return spec;
}

}  // namespace signorini::testing

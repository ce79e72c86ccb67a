#pragma once
// The obstacle shapes in one table: per shape, the parameters a problem file gives it (their
// keys, what each is, where it goes in RigidObstacle) and the words that describe it. The
// problem file's reader, its writer (the effective settings, summary.json) and the reference's
// [contact] keys loop over it (input/), so a new shape is its fields and name in
// rigid_obstacle.hpp and its row and geometry in rigid_obstacle.cpp, nothing else.

#include <Eigen/Core>
#include <span>

#include "signorini/interface/rigid_obstacle.hpp"

namespace signorini {

enum class ObstacleParameterKind {
  Formula,    ///< an expression of x, y, z (the gap formula: read and written by the section)
  Position,   ///< a point: 2 numbers in 2D, 3 in 3D
  Direction,  ///< the same, not all zero (any length)
  Axis,       ///< 3 numbers, not all zero (any length): a direction that only 3D has
  Positive,   ///< a number > 0
  Flag,       ///< true or false, false where not given
};

struct ObstacleParameter {
  const char* key;
  ObstacleParameterKind kind;
  /// What the value is, for the messages: "[x, y] ([x, y, z] in 3D): a point of the plane".
  const char* expected;
  /// The reference's words, after "shape: " ("a point of the plane's surface").
  const char* doc;
  /// "L" for a length (a point, a radius), "" for a number without units (docs' unit column).
  const char* unit = "";
  /// Where it goes: one of these is set, as the kind says (none for a Formula).
  Eigen::Vector3d RigidObstacle::*vector = nullptr;
  double RigidObstacle::*number = nullptr;
  bool RigidObstacle::*flag = nullptr;
  /// Direction and Axis: which way it must point, for the message on a zero vector ("pointing
  /// from the obstacle towards the body").
  const char* direction_words = "";
};

struct ObstacleShapeRow {
  ObstacleShape shape;
  /// 3 where only 3D problems have the shape, 0 otherwise; `instead`: what a 2D problem uses.
  int only_dimension = 0;
  const char* instead = "";
  /// The reference's words for it after "the rigid partner:" ("a half-plane (a half-space in
  /// 3D)"); its keys follow in parentheses.
  const char* doc = "";
  std::span<const ObstacleParameter> parameters;
};

/// Every shape, in the order of ObstacleShape.
[[nodiscard]] std::span<const ObstacleShapeRow> obstacle_shapes();
[[nodiscard]] const ObstacleShapeRow& obstacle_shape(ObstacleShape shape);

}  // namespace signorini

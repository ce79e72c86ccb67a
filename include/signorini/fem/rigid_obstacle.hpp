#pragma once
// The rigid partner of a contact boundary, and the gap g_j from each contact node to it measured
// along the body's outward unit normal nu_j (method.md section 3): a gap formula g(x) as the
// paper has it, a half-plane (a half-space in 3D), or a disc (a sphere in 3D: a roller, punch or
// ball outside the body, or a bore the body sits in). For planes and discs the gap is exact: the
// distance from x_j along nu_j to the obstacle's surface, negative where the node starts inside
// the obstacle. Points and vectors have three coordinates; 2D problems leave z at 0.

#include <Eigen/Core>

#include "signorini/core/enum_names.hpp"
#include "signorini/fem/vector_field.hpp"

namespace signorini {

enum class ObstacleShape { Gap, Plane, Disc, Cylinder };

inline constexpr EnumNames<ObstacleShape, 4> kObstacleShapeNames{{
    {ObstacleShape::Gap, "gap"},
    {ObstacleShape::Plane, "plane"},
    {ObstacleShape::Disc, "disc"},
    {ObstacleShape::Cylinder, "cylinder"},
}};

struct RigidObstacle {
  ObstacleShape shape = ObstacleShape::Gap;
  /// Gap: g(x), read as the gap along the normal at x.
  ScalarField gap = [](const Point&) { return 0.0; };
  /// Plane: a point of its surface, and its unit normal pointing out of the obstacle (towards
  /// the body): the obstacle is the half-plane (x - point) . normal <= 0.
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d(0.0, 1.0, 0.0);
  /// Disc (sphere in 3D): centre and radius; the body outside it (a roller, a punch) or, with
  /// body_inside, inside it (a bore, a groove).
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  double radius = 1.0;
  bool body_inside = false;
  /// Cylinder (3D): the points within `radius` of the line through `centre` along `axis` (any
  /// length, not zero); body_inside as for a disc. In 2D a disc is the cylinder's section.
  Eigen::Vector3d axis = Eigen::Vector3d(0.0, 0.0, 1.0);
};

/// Throws InputError unless the obstacle is well defined (a non-zero, finite plane normal, a
/// positive radius, finite coordinates).
void validate(const RigidObstacle& obstacle);

/// The gap from x along the unit vector nu to the obstacle: the t >= 0 of the first point
/// x + t nu on its surface, or t < 0 where x is inside it already. Where the ray x + t nu never
/// meets the obstacle (a node whose normal faces away from it), `far`.
double obstacle_gap(const RigidObstacle& obstacle, const Point& x, const Eigen::Vector3d& nu,
                    double far);

}  // namespace signorini

#pragma once
// The rigid partner of a contact boundary (method.md section 3): a gap formula g(x) as the paper
// has it, read along the body's outward unit normal, or an obstacle of known shape: a half-plane
// (a half-space in 3D), a disc (a sphere in 3D: a roller, punch or ball outside the body, or a
// bore the body sits in) or a cylinder. Against a shape the constraint at a contact node acts
// along the obstacle's normal at the node's closest point of its surface, and the gap is the
// signed distance to that surface (negative where the node starts inside the obstacle), as for
// any rigid master surface. Points and vectors have three coordinates; 2D problems leave z at 0.

#include <Eigen/Core>
#include <string>

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

/// Where a point is against an obstacle of known shape (not ObstacleShape::Gap): the signed
/// distance from the obstacle's surface (negative inside the obstacle) and the obstacle's
/// outward unit normal at the closest point of its surface (pointing towards the body).
struct ObstacleDistance {
  double distance = 0.0;
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
};

/// The distance of x from the obstacle's surface and the normal there. On a disc's centre (or a
/// cylinder's axis), where every point of the surface is closest, the normal is `fallback`.
/// std::logic_error for ObstacleShape::Gap, which has no shape.
[[nodiscard]] ObstacleDistance obstacle_distance(const RigidObstacle& obstacle, const Point& x,
                                                 const Eigen::Vector3d& fallback);

/// "plane through (0, 0) with normal (0, 1)", "disc of radius 1 about (0, 2)": an obstacle in
/// messages (z left out where dim is 2).
[[nodiscard]] std::string describe(const RigidObstacle& obstacle, int dim);

}  // namespace signorini

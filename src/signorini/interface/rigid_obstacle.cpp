#include "signorini/interface/rigid_obstacle.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <stdexcept>

#include "signorini/core/error.hpp"
#include "signorini/interface/obstacle_parameters.hpp"

namespace signorini {

namespace {

using K = ObstacleParameterKind;
using O = RigidObstacle;

// The parameters of each shape (obstacle_parameters.hpp), in the order a problem file's writer
// gives them.
constexpr std::array kGapParameters{
    ObstacleParameter{"gap", K::Formula, "an expression of x, y, z", "the gap formula", "L",
                      nullptr, nullptr, nullptr, ""},
};
constexpr std::array kPlaneParameters{
    ObstacleParameter{"point", K::Position, "[x, y] ([x, y, z] in 3D): a point of the plane",
                      "a point of the plane's surface", "L", &O::point, nullptr, nullptr, ""},
    ObstacleParameter{"normal", K::Direction,
                      "[nx, ny] ([nx, ny, nz] in 3D): the plane's normal, towards the body",
                      "its normal, pointing out of the obstacle towards the body (any length)", "",
                      &O::normal, nullptr, nullptr, "pointing from the obstacle towards the body"},
};
constexpr std::array kDiscParameters{
    ObstacleParameter{"centre", K::Position, "[x, y] ([x, y, z] in 3D): the disc's centre",
                      "its centre", "L", &O::centre, nullptr, nullptr, ""},
    ObstacleParameter{"radius", K::Positive, "a positive number", "the radius", "L", nullptr,
                      &O::radius, nullptr, ""},
    ObstacleParameter{"inside", K::Flag, "true or false",
                      "true when the body lies inside it (a shaft in a bore), false when outside "
                      "(a roller or a punch pressing on it)",
                      "", nullptr, nullptr, &O::body_inside, ""},
};
constexpr std::array kCylinderParameters{
    ObstacleParameter{"centre", K::Position, "[x, y, z]: a point of the cylinder's axis",
                      "a point of its axis", "L", &O::centre, nullptr, nullptr, ""},
    ObstacleParameter{"axis", K::Axis, "[ax, ay, az]: the direction of the cylinder's axis",
                      "the direction of its axis (any length)", "", &O::axis, nullptr, nullptr,
                      "along the cylinder's axis"},
    kDiscParameters[1],
    kDiscParameters[2],
};
constexpr std::array kShapes{
    ObstacleShapeRow{ObstacleShape::Gap, 0, "", "the foundation of `gap` (the paper's)",
                     kGapParameters},
    ObstacleShapeRow{ObstacleShape::Plane, 0, "", "a half-plane (a half-space in 3D)",
                     kPlaneParameters},
    ObstacleShapeRow{ObstacleShape::Disc, 0, "", "a disc (a ball in 3D)", kDiscParameters},
    ObstacleShapeRow{ObstacleShape::Cylinder, 3, "obstacle = \"disc\" (the cylinder's section)",
                     "a cylinder, in 3D only,", kCylinderParameters},
};

static_assert(kShapes.size() == kObstacleShapeNames.size(), "a row for every obstacle shape");

}  // namespace

std::span<const ObstacleShapeRow> obstacle_shapes() {
  return kShapes;
}

const ObstacleShapeRow& obstacle_shape(ObstacleShape shape) {
  for (const ObstacleShapeRow& row : kShapes)
    if (row.shape == shape) return row;
  throw std::logic_error("obstacle_shape: a shape without a row");
}

void validate(const RigidObstacle& o) {
  switch (o.shape) {
    case ObstacleShape::Gap:
      if (!o.gap) throw InputError("contact: a gap obstacle needs a gap function");
      return;
    case ObstacleShape::Plane:
      if (!o.point.allFinite())
        throw InputError("contact.point: expected finite coordinates [x, y]");
      if (!o.normal.allFinite() || !(o.normal.norm() > 0.0))
        throw InputError(
            "contact.normal: expected a non-zero vector [nx, ny] pointing from the "
            "obstacle towards the body");
      return;
    case ObstacleShape::Disc:
    case ObstacleShape::Cylinder:
      if (!o.centre.allFinite())
        throw InputError("contact.centre: expected finite coordinates [x, y]");
      if (!(o.radius > 0.0) || !std::isfinite(o.radius))
        throw InputError("contact.radius = " + std::to_string(o.radius) +
                         ": expected a positive number");
      if (o.shape == ObstacleShape::Cylinder && (!o.axis.allFinite() || !(o.axis.norm() > 0.0)))
        throw InputError(
            "contact.axis: expected a non-zero vector [ax, ay, az] along the cylinder");
      return;
  }
}

ObstacleDistance obstacle_distance(const RigidObstacle& o, const Point& x,
                                   const Eigen::Vector3d& fallback) {
  ObstacleDistance out;
  switch (o.shape) {
    case ObstacleShape::Gap:
      break;
    case ObstacleShape::Plane:
      // The half-space (x - p) . n <= 0: its surface's normal is n everywhere.
      out.normal = o.normal.normalized();
      out.distance = (x - o.point).dot(out.normal);
      return out;
    case ObstacleShape::Disc:
    case ObstacleShape::Cylinder: {
      // The closest point of a circle (sphere) lies on the ray from its centre through x; for a
      // cylinder the same in the plane across its axis.
      Eigen::Vector3d d = x - o.centre;
      if (o.shape == ObstacleShape::Cylinder) {
        const Eigen::Vector3d e = o.axis.normalized();
        d -= d.dot(e) * e;
      }
      const double r = d.norm();
      const Eigen::Vector3d radial = r > 0.0 ? Eigen::Vector3d(d / r) : fallback;
      // Outside a ball the surface's outward normal points away from the centre; a bore's
      // material lies outside the circle, so its normal points towards the centre.
      out.distance = o.body_inside ? o.radius - r : r - o.radius;
      out.normal = o.body_inside ? Eigen::Vector3d(-radial) : radial;
      if (r == 0.0) out.normal = fallback;
      return out;
    }
  }
  throw std::logic_error("obstacle_distance: a gap formula has no shape");
}

namespace {
std::string coordinates(const Eigen::Vector3d& v, int dim) {
  std::string out = "(";
  for (int k = 0; k < dim; ++k) out += (k > 0 ? ", " : "") + fmt::format("{:g}", v(k));
  return out + ")";
}
}  // namespace

std::string describe(const RigidObstacle& o, int dim) {
  switch (o.shape) {
    case ObstacleShape::Gap:
      return "gap formula";
    case ObstacleShape::Plane:
      return fmt::format("plane through {} with normal {}", coordinates(o.point, dim),
                         coordinates(o.normal, dim));
    case ObstacleShape::Disc:
      return fmt::format("{} of radius {:g} about {}{}", dim == 3 ? "ball" : "disc", o.radius,
                         coordinates(o.centre, dim), o.body_inside ? ", the body inside" : "");
    case ObstacleShape::Cylinder:
      return fmt::format("cylinder of radius {:g} about {} along {}{}", o.radius,
                         coordinates(o.centre, dim), coordinates(o.axis, dim),
                         o.body_inside ? ", the body inside" : "");
  }
  return "obstacle";
}

}  // namespace signorini

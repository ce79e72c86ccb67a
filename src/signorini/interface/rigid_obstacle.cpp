#include "signorini/interface/rigid_obstacle.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "signorini/core/error.hpp"

namespace signorini {

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

#include "signorini/fem/rigid_obstacle.hpp"

#include <cmath>

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

double obstacle_gap(const RigidObstacle& o, const Point& x, const Eigen::Vector3d& nu, double far) {
  switch (o.shape) {
    case ObstacleShape::Gap:
      return o.gap(x);
    case ObstacleShape::Plane: {
      // x + t nu on the line (plane): ((x + t nu) - p) . n = 0.
      const Eigen::Vector3d n = o.normal.normalized();
      const double approach = nu.dot(n);  // < 0 where nu points into the obstacle's side
      if (!(approach < -1e-12)) return far;
      return (o.point - x).dot(n) / approach;
    }
    case ObstacleShape::Disc:
    case ObstacleShape::Cylinder: {
      // |x + t nu - c| = R: t^2 + 2 b t + q = 0 with b = nu . (x - c), q = |x - c|^2 - R^2; for a
      // cylinder the same in the plane across its axis (both vectors without their components
      // along it), a t^2 + 2 b t + q = 0 with a = |nu_perp|^2, divided by a.
      Eigen::Vector3d d = x - o.centre;
      Eigen::Vector3d n = nu;
      double a = 1.0;
      if (o.shape == ObstacleShape::Cylinder) {
        const Eigen::Vector3d e = o.axis.normalized();
        d -= d.dot(e) * e;
        n -= n.dot(e) * e;
        a = n.squaredNorm();
        if (!(a > 1e-24)) return far;  // a normal along the axis never meets the surface
      }
      const double b = n.dot(d) / a;
      const double q = (d.squaredNorm() - o.radius * o.radius) / a;
      const double disc = b * b - q;
      if (o.body_inside) {  // leaves the disc at the larger root (q < 0 inside: always real)
        if (disc < 0.0) return far;
        return -b + std::sqrt(disc);
      }
      if (disc < 0.0) return far;             // the ray passes the disc
      const double t = -b - std::sqrt(disc);  // the first point of the circle on the ray
      if (t < 0.0 && q > 0.0) return far;     // the disc lies behind the node
      return t;
    }
  }
  return far;
}

}  // namespace signorini

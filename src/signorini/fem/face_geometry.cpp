#include "signorini/fem/face_geometry.hpp"

#include <Eigen/Geometry>

namespace signorini {

FacePoint face_point(const Mesh& mesh, CellType type, std::span<const Index> nodes,
                     const Eigen::Vector3d& xi, ShapeValues& N) {
  ShapeGradients dN;
  shape_functions(type, xi, N);
  shape_gradients(type, xi, dN);
  FacePoint p{Point::Zero(), Eigen::Vector3d::Zero()};
  Point t1 = Point::Zero(), t2 = Point::Zero();
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const Point xa = mesh.point(nodes[a]);
    const auto i = static_cast<Index>(a);
    p.x += N(i) * xa;
    t1 += dN(0, i) * xa;
    t2 += dN(1, i) * xa;
  }
  p.area = t1.cross(t2);
  return p;
}

}  // namespace signorini

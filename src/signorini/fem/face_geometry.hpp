#pragma once
// The geometry of a face of a 3D cell at a point of its reference cell (a triangle or a
// quadrilateral, fem/reference_element.hpp), mapped by its own shape functions: what surface
// integrals need (loads on faces, contact weights and normals).
#include <span>

#include "signorini/fem/reference_element.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

struct FacePoint {
  Point x;               ///< the point in space
  Eigen::Vector3d area;  ///< dx/ds1 x dx/ds2: |area| is the surface element, its direction the
                         ///< outward normal (faces' corners run counterclockwise seen from outside,
                         ///< mesh/cell_type.hpp)
};

/// The face with nodes `nodes` (of type `type`) at the reference point xi; N gets the shape
/// values there.
FacePoint face_point(const Mesh& mesh, CellType type, std::span<const Index> nodes,
                     const Eigen::Vector3d& xi, ShapeValues& N);

}  // namespace signorini

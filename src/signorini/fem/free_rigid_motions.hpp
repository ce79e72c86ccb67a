#pragma once
// Rigid motions that the clamps leave free. A body that can translate or rotate without
// straining has a singular stiffness; frictionless contact cannot hold it either (the
// foundation only pushes, and never along its surface), so such a problem is refused before any
// solve, naming the free motions.

#include <string>
#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// One free rigid motion u(x) = translation + rotation x (x - centre) of one connected piece of
/// the mesh (in 2D the rotation is about z: only rotation(2) may be nonzero).
struct RigidMotion {
  Index piece = 0;       ///< connected piece of the mesh (0 where there is one)
  Index piece_node = 0;  ///< a node of that piece, to name it
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Vector3d rotation = Eigen::Vector3d::Zero();
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();  ///< a point on the rotation axis
  /// "translation in x", "rotation about (0, 0)", "translation along (0.6, 0.8)", ...
  [[nodiscard]] std::string description() const;
};

/// A basis of the rigid motions of each connected piece of the mesh that vanish at every clamped
/// dof: empty when the clamps hold the body. Translations first, then rotations about a point
/// that the motion leaves fixed.
std::vector<RigidMotion> free_rigid_motions(const Mesh& mesh, const DofMap& dofs);

/// Number of connected pieces of the mesh (cells sharing a node are connected).
Index count_mesh_pieces(const Mesh& mesh);

}  // namespace signorini

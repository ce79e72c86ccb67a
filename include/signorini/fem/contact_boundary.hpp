#pragma once
// From a mesh to the discrete contact boundary (contact/contact_set.hpp): the nodes of a
// boundary part in order, their normals, trapezoid weights and gaps, and N (method.md section 3).
// The discretisation side of contact; the solvers in contact/ see only the ContactSet.

#include "signorini/contact/contact_set.hpp"
#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/rigid_obstacle.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// Builds the contact set of a boundary part. Throws InputError if the part is empty, has no
/// movable node (it lies on the clamped boundary entirely), or a gap value is not finite.
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const ScalarField& gap);
/// The same against a rigid obstacle: g_j is the gap from node j along its normal nu_j
/// (obstacle_gap); where nu_j never meets the obstacle, 10 times the mesh's extent.
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const RigidObstacle& obstacle);

}  // namespace signorini

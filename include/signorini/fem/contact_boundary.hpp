#pragma once
// From a mesh to the discrete contact boundary (contact/contact_set.hpp): the nodes of a
// boundary part in order, their normals, trapezoid weights and gaps, and N (method.md section 3).
// The discretisation side of contact; the solvers in contact/ see only the ContactSet.

#include <string>
#include <vector>

#include "signorini/contact/contact_set.hpp"
#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/rigid_obstacle.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// The nodes of a 2D boundary part in order along it (walking its facets), their outward unit
/// normals (along int N_j nu ds) and weights h_j = int N_j ds, and the facets as positions in
/// `nodes`. Throws InputError (naming `what`, e.g. "contact.boundary") for a part without facets
/// or a node without a normal.
struct BoundaryNodes {
  std::vector<Index> nodes;
  Eigen::MatrixXd normals;  ///< dim x nodes
  Vector weights;
  std::vector<std::vector<Index>> facets;
};
BoundaryNodes boundary_nodes(const Mesh& mesh, const BoundaryPart& part, const std::string& what);

/// Builds the contact set of a boundary part. Throws InputError if the part is empty, has no
/// movable node (it lies on the clamped boundary entirely), or a gap value is not finite.
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const ScalarField& gap);
/// The same against a rigid obstacle: g_j is the gap from node j along its normal nu_j
/// (obstacle_gap); where nu_j never meets the obstacle, 10 times the mesh's extent. With a
/// `surface_normal` (the body's exact outward normal, any length) the normals are its values at
/// the nodes instead of the facets' average; InputError where it vanishes or points into the
/// body (more than 90 degrees from the facets' normal).
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const RigidObstacle& obstacle,
                            const VectorField& surface_normal = nullptr);

/// make_contact_set's rows without its check that some node can move, and with the gap of a
/// node whose normal never meets the obstacle given (`far`: make_contact_set takes 10 times the
/// mesh's extent): the rows of a part of the mesh (docs/distributed.md), which is measured and
/// checked whole.
ContactSet make_contact_rows(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                             const RigidObstacle& obstacle, const VectorField& surface_normal,
                             double far);

/// Appends the rows of `more` (a contact set over the same free dofs) to `into`: several
/// contact boundaries as one contact set, their nodes in order (a node in two parts gets a row in
/// each).
void append_contact_set(ContactSet& into, const ContactSet& more);
}  // namespace signorini

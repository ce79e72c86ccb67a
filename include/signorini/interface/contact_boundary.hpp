#pragma once
// From a mesh to the discrete contact boundary (interface/contact_set.hpp): the nodes of a
// boundary part in order, their normals, trapezoid weights and gaps, and N (method.md section 3).
// The discretisation side of contact; the solvers in contact/ see only the ContactSet.

#include <string>
#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/interface/contact_set.hpp"
#include "signorini/interface/rigid_obstacle.hpp"
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
  /// Per facet and node of it (facets' order, then the facet's nodes): int_f N_j n dA, node j's
  /// share of the facet's area as a vector along the facet's outward normal (on a lumped Tri6
  /// face, h_j times the face's normal at the node). `normals` is their sum per node; the weight
  /// against a rigid obstacle projects each onto the obstacle's direction.
  Eigen::MatrixXd facet_shares;  ///< dim x (sum of the facets' node counts)
};
BoundaryNodes boundary_nodes(const Mesh& mesh, const BoundaryPart& part, const std::string& what);

/// Builds the contact set of a boundary part. Throws InputError if the part is empty, if no
/// node can move towards the obstacle (check_contact_can_occur), if a gap value is not finite,
/// or if the body starts deep inside the obstacle (check_body_outside, and a gap below
/// -interference_limit).
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const ScalarField& gap);
/// The same against a rigid obstacle (method.md section 3). With a gap formula, g_j = g(x_j)
/// along the body's normal nu_j. Against a shape (plane, disc, cylinder), the obstacle's:
/// nu_j = -n(y_j), the obstacle's inward normal at the node's closest point y_j of its surface,
/// and g_j the signed distance from it; the weight h_j is the node's share of the facets'
/// area projected across nu_j (sum of max(int_f N_j n dA . nu_j, 0): the obstacle's surface
/// that the node presses on), or its plain share where that is zero (every facet at right
/// angles to nu_j); a node whose outward normal points away from the obstacle gets no row in N
/// (movable false: it never touches). A `surface_normal` (the body's
/// exact outward normal, any length) replaces the facets' average as the body's normal;
/// InputError where it vanishes or points into the body (more than 90 degrees from the facets'
/// normal).
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const RigidObstacle& obstacle,
                            const VectorField& surface_normal = nullptr);

/// The initial interference allowed between the body and an obstacle: a tenth of the body's
/// smallest extent (its bounding box's sides, `extent`; zero sides are left out). A deeper one
/// is a body placed inside the obstacle, an input error: the small-strain model cannot push a
/// body that far out, and it is nearly always an obstacle normal or position given wrong.
[[nodiscard]] double interference_limit(const Eigen::VectorXd& extent);

/// Throws InputError naming the deepest node, the obstacle and the depth where a node of `mesh`
/// lies more than `limit` inside an obstacle of known shape (a gap formula is checked at the
/// contact nodes by make_contact_rows). `what` names the contact ("contact.boundary = 'bottom'").
void check_body_outside(const Mesh& mesh, const RigidObstacle& obstacle, double limit,
                        const std::string& what);

/// Throws InputError unless some node of the contact set can move towards the obstacle (its
/// normal component free, its outward normal not turned away from the obstacle).
void check_contact_can_occur(const ContactSet& cs, const std::string& boundary);

/// make_contact_set's rows without its whole-body checks (the gaps of a gap formula are still
/// checked against `limit`): the rows of a part of the mesh (docs/distributed.md), which is
/// measured and checked whole.
ContactSet make_contact_rows(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                             const RigidObstacle& obstacle, const VectorField& surface_normal,
                             double limit);

/// Appends the rows of `more` (a contact set over the same free dofs) to `into`: several
/// contact boundaries as one contact set, their nodes in order (a node in two parts gets a row in
/// each).
void append_contact_set(ContactSet& into, const ContactSet& more);
}  // namespace signorini

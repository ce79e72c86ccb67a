#pragma once
// The discrete contact boundary (method.md section 3): contact nodes P in boundary order, their
// outward unit normals nu_j, nodal quadrature weights h_j (trapezoid rule) and gaps g_j, and the
// sparse operator N with (N x)_j = (x . nu)_j over the free dofs of node j.

#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

struct ContactSet {
  std::vector<Index> nodes;  ///< mesh node numbers, in order along the boundary part
  Eigen::MatrixXd normals;   ///< dim x size(): outward unit normal nu_j
  Vector weights;            ///< h_j: half the lengths of the contact facets that touch node j
  Vector gaps;               ///< g_j = g(x_j), the initial gap to the foundation
  SparseMatrix N;            ///< size() x num_free
  /// false where node j has no free unknown in its normal direction (clamped): its multiplier is
  /// kept at 0 (method.md section 4, last paragraph).
  std::vector<bool> movable;

  [[nodiscard]] Index size() const { return static_cast<Index>(nodes.size()); }
  [[nodiscard]] Index num_movable() const;
};

/// Builds the contact set of a boundary part. Throws InputError if the part is empty, has no
/// movable node (it lies on the clamped boundary entirely), or a gap value is not finite.
ContactSet make_contact_set(const Mesh& mesh, const BoundaryPart& part, const DofMap& dofs,
                            const ScalarField& gap);

}  // namespace signorini

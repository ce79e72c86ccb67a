#pragma once
// The rigid-body modes of linear elasticity on the free dofs: the near-null space that
// smoothed-aggregation multigrid (iterative/smoothed_aggregation.hpp) carries to coarse levels.

#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// num_free x 3 in 2D (the two translations and the rotation about the centroid) and num_free x 6
/// in 3D (three translations, three rotations about axes through the centroid), restricted to
/// the free dofs. With a range [first, end) of the free dofs, only its rows (a rank's, on the
/// distributed path: ContactProblem::near_null_space); end < 0: to the last. The rotations are
/// about `centre` where given (dim entries: a rank's part of a mesh takes the whole mesh's
/// centroid, problem/model_part.hpp), else about the mesh's centroid.
Matrix rigid_body_modes(const Mesh& mesh, const DofMap& dofs, Index first = 0, Index end = -1,
                        const Eigen::VectorXd* centre = nullptr);

/// The node of every free dof, in free-dof order (the dofs of a node are consecutive).
std::vector<Index> free_dof_nodes(const DofMap& dofs);

}  // namespace signorini

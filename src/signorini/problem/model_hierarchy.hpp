#pragma once
// The multigrid levels of a model (docs/gpu.md), chosen by solver.linear.coarsening: geometric
// levels while the rectangle mesh halves, then smoothed aggregation down to a level small
// enough for the dense coarsest solve.

#include "signorini/fem/dof_map.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"
#include "signorini/mesh/mesh.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// "geometric": the rectangle's levels only (an InputError unless the mesh halves down to a
/// level the dense coarsest solve takes, MultigridOptions::max_dense_coarse unknowns);
/// "aggregation": smoothed aggregation from A and the rigid-body modes; "auto": the geometric
/// levels, continued by aggregation from the coarsest of them while it is larger than the dense
/// coarsest solve allows (MultigridOptions::max_dense_coarse). `A` is the model's stiffness on
/// `dofs`.
MultigridHierarchy make_model_hierarchy(const ProblemSpec& spec, const Mesh& mesh,
                                        const DofMap& dofs, const SparseMatrix& A);

}  // namespace signorini

#pragma once
// The multigrid hierarchy of a structured rectangle mesh (docs/gpu.md): the nested meshes
// nx x ny, nx/2 x ny/2, ... and the bilinear interpolation between them, on the free dofs.

#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// Prolongations P_1, P_2, ...: P_l interpolates level l onto level l-1 (level 0 = `mesh` with
/// `fine_dofs`). Coarse node (I, J) is fine node (2I, 2J); each fine node takes the bilinear
/// interpolant of the four coarse nodes of its coarse cell, per component. Coarse dofs on the
/// clamped boundary (clamps and prescribed displacements) are dropped (the corrections vanish
/// there). Coarsening continues while nx and ny are even and the current level has more than
/// `min_coarse_unknowns` free dofs; a mesh with odd nx or ny has no coarser level (the result is
/// empty).
std::vector<SparseMatrix> make_rectangle_prolongations(
    const RectangleMeshOptions& mesh, const std::vector<ClampSpec>& clamps, const DofMap& fine_dofs,
    Index min_coarse_unknowns = 400, const std::vector<DisplacementSpec>& displacements = {});

}  // namespace signorini

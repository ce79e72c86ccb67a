#pragma once
// How the free dofs are spread over the MPI ranks of a distributed solve
// (docs/distributed.md): each rank owns one contiguous range of the problem's numbering, the
// ranges of nearly equal length, and no range boundary falls inside a mesh node's dofs or a
// contact node's row of N, so that every node block of the stiffness and every contact term
// stays on one rank. The numbering is the model's: node by node along a Z-order curve for Gmsh
// meshes (fem/node_ordering.hpp), row by row for generated ones, so a contiguous range is a
// compact piece of the body (the space-filling-curve partitions of p4est and deal.II).

#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

/// The first dof of each of `ranks` ranges of [0, n), and n: ranks + 1 increasing numbers. A
/// boundary may move forward from k n / ranks only to the start of a node: where dof i - 1 and
/// dof i share a node (`node_of_unknown`, empty: every dof its own) or a row of N (`N`, any
/// number of columns n; empty: none). Throws InputError for fewer than one rank or more ranks
/// than dofs.
[[nodiscard]] std::vector<Index> row_partition(Index n, int ranks,
                                               const std::vector<Index>& node_of_unknown,
                                               const SparseMatrix& N);

}  // namespace signorini

#pragma once
// How much memory a solve of a mesh will take, roughly: enough to refuse, before any work, a mesh
// that surely cannot fit (input/problem_file.cpp does, against the machine's memory).

#include "signorini/linalg/linear_solver.hpp"

namespace signorini {

/// Rough peak memory of a 2D solve with `num_nodes` mesh nodes: 4 KB per node with the sparse
/// Cholesky factor, 2 KB with CG, and the full dense matrix (8 bytes per entry) on top with the
/// dense solver. Measured peaks on the paper's meshes: 3.4 KB/node (240 x 80)
/// and 3.8 KB/node (480 x 160) with CHOLMOD, the factor's fill growing slowly with the mesh;
/// 2.2 KB/node with CG, mostly the assembly. Used only to refuse meshes that surely cannot fit,
/// before any time is spent on them: a mesh below the limit may still be too large.
double estimated_memory_bytes(double num_nodes, LinearSolverType solver);

}  // namespace signorini

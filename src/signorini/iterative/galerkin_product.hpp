#pragma once
// The Galerkin coarse operator P^T A P of multigrid (multigrid_preconditioner.hpp), formed in one
// pass per coarse column with a dense accumulator, in parallel over the columns: a few times
// faster than Eigen's two general sparse products on one thread, and it scales with the cores
// (it is the largest part of the multigrid set-up on meshes of millions of unknowns).

#include "signorini/core/types.hpp"

namespace signorini {

/// P^T A P for a symmetric A (n x n, both triangles stored) and P (n x m); the result is m x m,
/// symmetric, with explicit zeros dropped.
SparseMatrix galerkin_product(const SparseMatrix& A, const SparseMatrix& P);

}  // namespace signorini

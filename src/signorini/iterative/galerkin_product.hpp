#pragma once
// The Galerkin coarse operator P^T A P of multigrid (multigrid_preconditioner.hpp), formed in one
// pass per coarse column with a dense accumulator, in parallel over the columns: a few times
// faster than Eigen's two general sparse products on one thread, and it scales with the cores
// (it is the largest part of the multigrid set-up on meshes of millions of unknowns).

#include "signorini/core/types.hpp"

namespace signorini {

/// P^T A P for a symmetric A (n x n, both triangles stored) and P (n x m); the result is m x m,
/// symmetric, with explicit zeros dropped.
///
/// A may also be given by its first k < n columns only (n x k): A's rows of the unknowns
/// 0 .. k-1, by symmetry, which is what one rank holds of a distributed matrix whose unknowns
/// k .. n-1 are another rank's (petsc/aggregation_levels.hpp). The result is then (P^T E P)^T,
/// E = A with the rows k .. n-1 set to zero: this rank's share of the whole product, which the
/// ranks' shares sum to (it is not symmetric by itself).
SparseMatrix galerkin_product(const SparseView& A, const SparseMatrix& P);
inline SparseMatrix galerkin_product(const SparseMatrix& A, const SparseMatrix& P) {
  return galerkin_product(view_of(A), P);
}

}  // namespace signorini

#pragma once
// Smoothed-aggregation coarsening (Vanek, Mandel and Brezina, Computing 56, 1996): the multigrid
// hierarchy built from the matrix alone, for meshes that do not halve (docs/gpu.md).
//
// Per level: the unknowns are grouped by node; nodes are grouped into aggregates (a node with its
// strongly coupled neighbours); the near-null space B (rigid-body modes for elasticity) is
// orthonormalised on each aggregate, B_a = Q_a R_a, and the tentative prolongation is the block
// diagonal of the Q_a, so that it reproduces B exactly; one damped Jacobi step smooths it,
// P = (I - omega D^{-1} A) P_tent with omega = 4 / (3 rho(D^{-1} A)); the coarse matrix is the
// Galerkin product P^T A P and the coarse near-null space is the stack of the R_a, with each
// aggregate a coarse "node".

#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

struct SmoothedAggregationOptions {
  /// Nodes a and b are strongly coupled if ||A_ab||_F >= theta sqrt(||A_aa||_F ||A_bb||_F) (node
  /// blocks); 0 takes every matrix neighbour.
  double strength_threshold = 0.0;
  /// Coarsening stops once a level has at most this many unknowns (it is then solved densely by
  /// the multigrid preconditioner, up to kDenseCoarsestUnknowns): half that limit, so that the
  /// level which stops it, one coarsening below a level just above, is well inside the limit.
  Index max_coarse_unknowns = kDenseCoarsestUnknowns / 2;
  /// ... or when a level has fewer than this fraction of unknowns less than the one above.
  double min_reduction = 0.2;
  int max_levels = 25;
};

/// The smoothed-aggregation hierarchy of the symmetric positive definite A (n x n, both
/// triangles stored). `near_null_space` is n x k (k >= 1); `node_of_unknown[i]` is the node of
/// unknown i, nodes numbered from 0 and the unknowns of a node consecutive. The coarse operators
/// are formed (kind Aggregation); an empty hierarchy (kind None) if A already has at most
/// max_coarse_unknowns unknowns. The nodes are aggregated in the order of their numbers, whatever
/// the order of the unknowns (which a renumbering for locality may have changed: the aggregates
/// stay those of the mesh's own order), and the coarse unknowns follow the order of the fine
/// ones.
MultigridHierarchy smoothed_aggregation_hierarchy(const SparseMatrix& A, Matrix near_null_space,
                                                  std::vector<Index> node_of_unknown,
                                                  const SmoothedAggregationOptions& options = {});

/// One level's aggregation and tentative prolongation, for a caller that smooths the
/// prolongation and forms the Galerkin product itself (the distributed path's levels,
/// petsc/aggregation_levels.hpp).
struct AggregationLevel {
  SparseMatrix tentative;          ///< P_tent: the numbered unknowns x the coarse unknowns
  Matrix coarse_null_space;        ///< the near-null space's coarse rows (the stacked R_a)
  std::vector<Index> coarse_node;  ///< the aggregate of each coarse unknown
  std::vector<Index> place_of;     ///< per aggregate, its place in the aggregation's order
};

/// Aggregates the nodes of the unknowns 0 .. n-1 (n = node_of_unknown.size()) and forms the
/// tentative prolongation. A holds the columns of those unknowns (n columns, both triangles);
/// it may have more rows (another rank's unknowns), which are not aggregated and do not count
/// as couplings. `place_of`: per node number, its place in the order of aggregation (empty:
/// the number itself); the result's place_of is the next level's.
AggregationLevel aggregate_level(const SparseView& A, const Matrix& near_null_space,
                                 const std::vector<Index>& node_of_unknown,
                                 const std::vector<Index>& place_of, double strength_threshold);
inline AggregationLevel aggregate_level(const SparseMatrix& A, const Matrix& near_null_space,
                                        const std::vector<Index>& node_of_unknown,
                                        const std::vector<Index>& place_of,
                                        double strength_threshold) {
  return aggregate_level(view_of(A), near_null_space, node_of_unknown, place_of,
                         strength_threshold);
}

/// rho(D^{-1} A) of a symmetric positive definite A by Lanczos steps from the fixed start
/// (eigenvalue_estimate.hpp), on the process's threads: the damping omega = 4 / (3 rho) of the
/// prolongation smoother below.
[[nodiscard]] double jacobi_spectral_radius(const SparseMatrix& A);

/// The smoothed prolongation P = (I - omega D^{-1} A) T for a symmetric A (n x n), in parallel
/// over groups of columns (those of an aggregate share their rows in T); exact zeros kept.
SparseMatrix smoothed_prolongation(const SparseView& A, const SparseMatrix& T, double omega);
inline SparseMatrix smoothed_prolongation(const SparseMatrix& A, const SparseMatrix& T,
                                          double omega) {
  return smoothed_prolongation(view_of(A), T, omega);
}

/// The rows 0 .. k-1 of the smoothed prolongation P = (I - omega D^{-1} A) T, with A given by
/// its first k columns (n x k, both triangles: A's rows of the unknowns 0 .. k-1, by symmetry)
/// and T (n x m) by all its rows: what one rank forms of the prolongation of its own unknowns
/// when T's rows k .. n-1 are its neighbours' (petsc/aggregation_levels.hpp). k x m, exact
/// zeros kept (as smoothed_prolongation keeps them); in parallel over the rows.
SparseMatrix smoothed_prolongation_rows(const SparseView& A, const SparseMatrix& T, double omega);
inline SparseMatrix smoothed_prolongation_rows(const SparseMatrix& A, const SparseMatrix& T,
                                               double omega) {
  return smoothed_prolongation_rows(view_of(A), T, omega);
}

/// The aggregation step alone (exposed for tests): the aggregate of every node of the node graph
/// given by the CSR-like arrays (neighbours of node a are adjacency[offsets[a] .. offsets[a+1]),
/// strong couplings only, without a itself). Every node gets an aggregate; the numbers are
/// 0 .. count-1, in the order the aggregates were formed. The nodes are visited in `order` (a
/// permutation of 0 .. m-1; empty: 0, 1, ...).
std::vector<Index> aggregate_nodes(const std::vector<Index>& offsets,
                                   const std::vector<Index>& adjacency,
                                   std::vector<Index> order = {});

}  // namespace signorini

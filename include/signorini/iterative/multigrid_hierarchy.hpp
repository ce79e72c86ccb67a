#pragma once
// The levels of the multigrid preconditioner (multigrid_preconditioner.hpp): transfer operators
// and, where their maker formed them, the coarse matrices; and how they were made.

#include <vector>

#include "signorini/core/enum_names.hpp"
#include "signorini/core/types.hpp"

namespace signorini {

/// How a hierarchy was made (summary.json's multigrid_coarsening).
enum class HierarchyKind { None, Geometric, Aggregation, GeometricThenAggregation };

inline constexpr EnumNames<HierarchyKind, 4> kHierarchyKindNames{{
    {HierarchyKind::None, "none"},
    {HierarchyKind::Geometric, "geometric"},
    {HierarchyKind::Aggregation, "aggregation"},
    {HierarchyKind::GeometricThenAggregation, "geometric+aggregation"},
}};

/// The largest coarsest level that the multigrid preconditioner solves exactly, by a dense
/// factorisation (MultigridOptions::max_dense_coarse); the makers of hierarchies aim below it
/// (SmoothedAggregationOptions::max_coarse_unknowns, problem/model_hierarchy.cpp). The one owner
/// of the coarsest size: a dense solve of 2,000 unknowns costs a product with a 2,000 x 2,000
/// inverse per V-cycle, about that of a fine level of a few hundred thousand unknowns.
inline constexpr Index kDenseCoarsestUnknowns = 2000;

struct MultigridHierarchy {
  /// prolongations[l] maps level l+1 to level l (level 0: the free dofs of the mesh).
  std::vector<SparseMatrix> prolongations;
  /// coarse_operators[l] is the matrix of level l+1 (P^T A P); empty: the multigrid
  /// preconditioner forms them.
  std::vector<SparseMatrix> coarse_operators;
  HierarchyKind kind = HierarchyKind::None;
  /// lambda_max(D^-1 A_l) of level l (0: the fine one) where the maker estimated it (smoothed
  /// aggregation does on every level that it coarsens, for the damping of its prolongation);
  /// missing or 0 where unknown. The multigrid preconditioner's smoothers need the same numbers
  /// (MultigridOptions::lambda_max).
  std::vector<double> jacobi_radii;
  /// Smoothed aggregation's tentative prolongations T_l (prolongations[l] = (I - omega_l
  /// D_l^-1 A_l) T_l) and their omega_l, where kept (empty: not kept; a geometric level has
  /// none): the multigrid preconditioner smooths their rows at the active contact unknowns of
  /// each level again with the Newton matrix (contact_prolongation.hpp). Only the rows that the
  /// contact rows touch are needed: the model keeps only those of the fine T_0 (6 values per
  /// unknown in 3D; keep_contact_rows()), the coarse ones whole (a few percent of T_0).
  std::vector<SparseMatrix> tentatives;
  std::vector<double> omegas;
};

}  // namespace signorini

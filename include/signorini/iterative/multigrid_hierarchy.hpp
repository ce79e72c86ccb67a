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
  /// Smoothed aggregation's fine tentative prolongation T (prolongations[0] = (I - omega D^-1 A)
  /// T) and its omega, where kept: the multigrid preconditioner smooths T's rows at the active
  /// contact nodes again with the Newton matrix (contact_prolongation.hpp). Only the rows of the
  /// unknowns that the contact rows touch are needed (keep_contact_rows(), there); empty: not
  /// kept.
  SparseMatrix fine_tentative;
  double fine_omega = 0.0;
};

}  // namespace signorini

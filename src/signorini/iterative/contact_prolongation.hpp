#pragma once
// A prolongation of smoothed aggregation smoothed with the Newton matrix of the active set
// instead of the stiffness alone (docs/performance.md, "Why the systems with contact cost more
// CG iterations than the linear solve", and "Every level's prolongation smoothed with its Newton
// matrix").
//
// Smoothed aggregation's P = (I - omega D_A^-1 A) T carries, near the contact zone, displacements
// that the contact terms E = N^T diag(c) N of H = A + E penalise: the V-cycle of H then needs
// a fifth more CG iterations than that of A (39 against 32 at a million unknowns on Hertz's
// ball). Smoothed with H, P_H = (I - omega D_H^-1 H) T. H's pattern is A's (E couples the
// unknowns of one node) and E lives on the unknowns Z of the active rows, so P_H differs from P
// in the rows Z alone, and there, with (A T)_Z = D_A (T_Z - P_Z) / omega from P's definition,
//   P_H,Z - P_Z = (1 - D_A / D_H) (T_Z - P_Z) - omega D_H^-1 E_ZZ T_Z,   D_H = D_A + diag(E):
// only the rows of P and T at the unknowns that the contact rows touch are needed, kept here.
// The same holds on a coarse level l, with A_l, its tentative T_l and omega_l, and its current
// contact rows N P_H,0 ... P_H,l-1 (their pattern known in advance: that of N P_0 ... P_l-1).
// The multigrid preconditioner transfers with P_l + (P_H,l - P_l) on every level and carries the
// contact rows down with them (coarse A_l unchanged): the whole contact solve at a million
// unknowns took 63 CG iterations with A's prolongations, 54 with the fine one smoothed with H,
// 43 with every level's.

#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/iterative/multigrid_hierarchy.hpp"

namespace signorini {

/// Keeps of hierarchy.tentatives[0] (the fine T) only the rows of the unknowns of the nodes that
/// N's rows touch (ContactProlongation reads those of N's unknowns; all of each node's, so that
/// contact rows with other components, friction's tangents, find theirs too); the others are
/// dropped (6 values per unknown in 3D). node_of_unknown[i]: the node of unknown i.
void keep_contact_rows(MultigridHierarchy& hierarchy, const SparseMatrix& N,
                       const std::vector<Index>& node_of_unknown);

class ContactProlongation {
 public:
  /// A: the level's matrix (n x n, for its diagonal); N: the contact rows (n_c x n), or on a
  /// coarse level rows whose pattern holds that of every N_l the level will have (N P_0 ...
  /// P_{l-1} does: P_H's rows have P's pattern); P: the smoothed prolongation (I - omega D_A^-1
  /// A) T (n x m); T: the tentative one, at least its rows at N's unknowns. Throws if a row of T
  /// that N touches is empty (T not kept there).
  ContactProlongation(const SparseMatrix& A, const SparseMatrix& N, const SparseMatrix& P,
                      const SparseMatrix& T, double omega);
  /// The same with A's diagonal given (n values; only those at N's unknowns are read): for a
  /// level held elsewhere (the distributed path's, petsc/level_contact_prolongation.hpp).
  ContactProlongation(const Vector& diagonal_of_A, const SparseMatrix& N, const SparseMatrix& P,
                      const SparseMatrix& T, double omega);

  /// P_H - P for the weights c (n_c values; c_j > 0 on the active rows) and the contact rows N
  /// of the constructor, or the current ones given as their transpose Nt (n x n_c; a coarse
  /// level's N P_H ..., whose values change with the active set): n x m, nonzero only in the
  /// rows of the active rows' unknowns; empty (no nonzeros) where no c_j > 0. An entry of Nt
  /// outside the constructor's pattern is left out (the preconditioner stays symmetric).
  [[nodiscard]] SparseMatrix change(const Vector& c, const SparseMatrix* Nt = nullptr) const;

  /// D P for rows D (r x n) whose columns lie among the kept rows' unknowns (those where the
  /// constructor's N has a nonzero; entries elsewhere are left out): r x m, from the kept rows
  /// of P alone. N P itself, or the next level's contact rows carried down.
  [[nodiscard]] SparseMatrix carry(const SparseMatrix& D) const;

 private:
  Index n_ = 0, m_ = 0;
  double omega_ = 0.0;
  SparseMatrix Nt_;             // N^T: column j is row j of N
  std::vector<Index> slot_;     // per unknown, its place among the kept rows (-1: none)
  std::vector<Index> unknown_;  // per kept row, its unknown
  Vector diag_a_;               // D_A at the kept rows
  using Rows = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;
  Rows P_rows_, T_rows_;  // P's and T's kept rows
};

}  // namespace signorini

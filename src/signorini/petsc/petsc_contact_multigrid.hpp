#pragma once
// Multigrid for the Newton matrices H(c) = A + N^T diag(c) N of Uzawa-GNM on PETSc objects, with
// GAMG's levels formed once (docs/distributed.md, "The multigrid of the Newton systems").
//
// The serial multigrid (multigrid_preconditioner.hpp) keeps its levels for every active set:
// since P^T (N^T diag(c) N) P = N_l^T diag(c) N_l with N_l = N P, a new active set only changes
// c, and each level's matrix is A_l + N_l^T diag(c) N_l. Here GAMG builds its smoothed-aggregation
// levels once, from A with the rigid-body modes; its prolongators P_l and Galerkin products A_l
// become the levels of a PCMG, and a new c costs the small products N_l^T diag(c) N_l (rows only
// where there is contact) instead of GAMG's set-up again (whose Galerkin products with the
// finest level cost as much as a dozen CG iterations). Smoothing is Chebyshev-Jacobi as in GAMG.
// Its interval [0.1, 1.1] lambda_max(D^-1 H_l) follows each c without CG steps on a whole level:
// on a coarse level lambda_max is the larger of A_l's (estimated once) and that of H_l's principal
// submatrix on the unknowns that the active rows touch (as the serial multigrid's refresh(),
// contact_zone_estimate.hpp), on the fine level a bound from A's; the coarsest level is
// factorised (LU, redundantly on every rank).

#include <petscksp.h>

#include <memory>
#include <string>
#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/petsc/corrected_transfer.hpp"
#include "signorini/petsc/level_contact_prolongation.hpp"
#include "signorini/petsc/threaded_product.hpp"

namespace signorini::petsc {

/// A contact node's row of N on the rank that owns its dofs.
struct ContactRow {
  Index j;                     ///< contact node
  std::vector<PetscInt> dofs;  ///< global rows of its dofs (all on this rank)
  std::vector<double> normal;  ///< its row of N on them
};

class ContactMultigrid {
 public:
  /// Sets GAMG up on `A_setup` (the fine level's A as an AIJ matrix, with its near-null space
  /// attached; only needed during the call) and makes `pc` a PCMG on GAMG's levels, whose finest
  /// operator is the one the KSP of `pc` is given. `rows`: this rank's contact rows (of the fine
  /// level's unknowns).
  /// Where the levels come from: GAMG's set-up, or signorini's smoothed aggregation on each
  /// rank's nodes (aggregation_levels.hpp; A_setup then needs its block size set too).
  /// On our own levels, `contact_prolongation` (the default) smooths the finest prolongations
  /// with the Newton matrix at the active contact unknowns (level_contact_prolongation.hpp);
  /// false keeps A's prolongations (for comparison: more CG iterations).
  enum class Levels { Gamg, Aggregation };
  ContactMultigrid(PC pc, Mat A_setup, const std::vector<ContactRow>& rows, MPI_Comm comm,
                   Levels levels = Levels::Gamg, bool contact_prolongation = true);
  ~ContactMultigrid();
  ContactMultigrid(const ContactMultigrid&) = delete;
  ContactMultigrid& operator=(const ContactMultigrid&) = delete;

  /// The coarse levels' matrices A_l + N_l^T diag(c) N_l for c_j (every rank the whole vector,
  /// indexed by row of N). The fine level's is the KSP's operator, which the caller updates.
  /// `block_unknowns`: with friction's coupled blocks on the fine level (c then their
  /// diagonal), the most unknowns that one node's rows touch on this rank, which bounds the
  /// fine smoother's eigenvalue in place of the rows' own counts; 0 without.
  void set_weights(const Vector& c, int block_unknowns = 0);

  /// The levels whose transfers carry the contact prolongation (the finest ones; 0 on GAMG's).
  [[nodiscard]] std::size_t contact_prolongation_levels() const { return corrected_.size(); }

  /// Level `depth`'s change P_H - P of its prolongation (0: the fine level's) for the last
  /// weights, or null (no change, or no contact prolongation there); and the contact rows of
  /// level `depth` >= 1 as the coarse levels have them. For the tests.
  [[nodiscard]] Mat prolongation_change(std::size_t depth) const {
    return depth < changes_.size() ? changes_[depth] : nullptr;
  }
  [[nodiscard]] Mat contact_rows(std::size_t depth) const {
    return depth >= 1 && depth <= levels_.size() ? levels_[levels_.size() - depth].N : nullptr;
  }

  /// Unknowns per level, finest first.
  [[nodiscard]] const std::vector<PetscInt>& level_sizes() const { return sizes_; }

 private:
  struct Coarse {
    Mat A = nullptr;       // the Galerkin product, until H is made
    Mat N = nullptr;       // the contact rows on this level: N_{l+1} P_l
    Mat Q = nullptr;       // N^T diag(c) N
    Mat H = nullptr;       // A + Q, on A's pattern (below) or on the union of both patterns
    Mat A_in_H = nullptr;  // on the union: A on H's pattern, copied into H before Q is added
    // Where Q's pattern lies in A's: H on A's pattern (A_in_H null; on our own levels A itself,
    // changed in place), and A's values in Q's rows (this rank's) written back before Q is added.
    std::vector<PetscInt> q_rows;
    std::vector<PetscScalar> q_row_values;
    std::unique_ptr<ThreadedProduct> threaded;  // H's products on the rank's threads, if made
    double lambda_a = 0.0;                      // lambda_max(D^-1 A_l), where the level is smoothed
    [[nodiscard]] Mat op() const { return threaded ? threaded->shell() : H; }
  };
  // A level's transfers on the rank's threads (threaded_product.hpp): P_l, and its transpose
  // formed once, so that the restriction is a product by rows too.
  struct Transfer {
    Mat R = nullptr;
    std::unique_ptr<ThreadedProduct> prolongation, restriction;
  };
  PC pc_;
  MPI_Comm comm_;
  std::vector<Index> row_j_;      // this rank's rows of the contact matrices: contact node
  std::vector<int> row_entries_;  // and the nonzero entries of its normal
  double fine_lambda_a_ = 0.0;    // lambda_max(D_A^-1 A) on the fine level
  Mat C_ = nullptr;               // diag(c) on the contact rows
  Vec c_ = nullptr;
  std::vector<Coarse> levels_;       // coarsest first, as PCMG numbers them (without the finest)
  std::vector<Mat> P_;               // P_[l]: level l to level l + 1
  std::vector<Transfer> transfers_;  // transfers_[l] for P_[l], where threaded
  std::vector<PetscInt> sizes_;
  // On our own levels: each level's prolongation smoothed with its Newton matrix at the active
  // contact unknowns (level_contact_prolongation.hpp), finest first: the changes dP_l and the
  // transfers P_l + dP_l that PCMG is given. Null / empty on GAMG's levels.
  std::unique_ptr<LevelContactProlongations> contact_;
  PetscInt first_row_ = 0;  // this rank's first row of the contact matrices
  std::vector<Mat> changes_;
  std::vector<std::unique_ptr<CorrectedTransfer>> corrected_;
  // lambda_max(D_ZZ^-1 H_ZZ) on the level's contact zone Z (the unknowns where Q's diagonal is
  // not 0): PETSc's CG estimate on the submatrix; 0 where Z is empty. Collective.
  [[nodiscard]] double zone_lambda_max(const Coarse& level) const;
};

}  // namespace signorini::petsc

#pragma once
// The contact prolongation (iterative/contact_prolongation.hpp) on the distributed path's own
// levels (aggregation_levels.hpp; docs/distributed.md, "Each level's prolongation smoothed with
// its Newton matrix"): each level's transfer P_l + (P_H,l - P_l), with P_H,l smoothed with the
// level's Newton matrix H_l instead of A_l at the unknowns that the active contact rows touch,
// and the coarse contact rows carried down by the P_H, as the serial multigrid does
// (MultigridPreconditioner::update_contact_prolongation). The serial tool's contact solve on
// Hertz's ball at a million unknowns took 63 CG iterations with A's prolongations and 43 with
// these.
//
// Each rank holds its own contact rows (every contact row lies on its node's dofs, one rank's)
// and, level by level, the rows of its P and T at the unknowns those rows touch. That is all a
// level needs while each rank's contact rows touch only its own unknowns of the level (always on
// one rank; on several, the fine level's always, a coarse level's while the prolongations keep
// the contact rows on their ranks). The levels are taken finest first while that holds on every
// rank; the first level whose rows reach another rank's unknowns gets its contact rows carried
// down, and it and the levels below keep A's prolongations.

#include <petscmat.h>

#include <memory>
#include <vector>

#include "signorini/core/types.hpp"
#include "signorini/iterative/contact_prolongation.hpp"
#include "signorini/petsc/level_numbering.hpp"

namespace signorini::petsc {

class LevelContactProlongations {
 public:
  /// N: this rank's contact rows (rows in the rank's order, columns its own unknowns of the fine
  /// level, local numbers).
  explicit LevelContactProlongations(RowMatrix N);

  /// Whether the next level may be added (the rows of the last one stay on their ranks).
  [[nodiscard]] bool open() const { return open_; }
  /// Adds the next level, finest first, while open(): its A's diagonal at the rank's unknowns
  /// (`fine`'s numbering: own first, then the ghosts, whose entries are not read), its
  /// prolongation's rows there (P: fine.size() x coarse.size()) and the tentative one's (T, the
  /// same sizes; its own rows suffice), omega. Collective: a level that any rank cannot take (a
  /// contact row's unknown without a row of T) closes the list without it.
  void add_level(MPI_Comm comm, const Vector& diagonal, const SparseMatrix& P,
                 const SparseMatrix& T, double omega, const ExtNumbering& fine,
                 const ExtNumbering& coarse);
  /// Levels with a prolongation change (the finest ones).
  [[nodiscard]] std::size_t levels() const { return levels_.size(); }

  /// For the weights c of this rank's rows (c_j > 0: active): `changes[l]` becomes level l's
  /// P_H,l - P_l as a distributed AIJ matrix (the previous one destroyed; null where no rank
  /// has a change), and the contact rows of levels 1 .. levels() (`rows[l]`: PETSc's contact
  /// matrix of level l, this rank's rows from global row `first_row`) are written with the
  /// current rows N P_H,0 ... P_H,l-1 where they are active, and with N P_0 ... P_l-1 where they
  /// were active before and are no more. Collective.
  void update(MPI_Comm comm, const Vector& c, PetscInt first_row, const std::vector<Mat>& rows,
              std::vector<Mat>& changes);

 private:
  struct Level {
    std::unique_ptr<ContactProlongation> prolongation;
    Index own = 0;        // the level's own unknowns on this rank
    Index extended = 0;   // with its ghosts (P's rows)
    ExtNumbering coarse;  // the next level's, as P's columns
  };
  // Writes this rank's rows of `current` (level l's numbering `numbering`) into M where
  // `write[r]`, then assembles M.
  static void write_rows(Mat M, const RowMatrix& current, const ExtNumbering& numbering,
                         PetscInt first_row, const std::vector<char>& write);

  RowMatrix N_;                // the fine level's rows
  std::vector<Level> levels_;  // finest first
  // coarse_N_[l - 1]: level l's rows N P_0 ... P_l-1, its columns numbered as levels_[l - 1]'s
  // coarse.
  std::vector<RowMatrix> coarse_N_;
  std::vector<char> was_active_;  // the rows written with the P_H's last time
  bool open_ = true;
};

}  // namespace signorini::petsc

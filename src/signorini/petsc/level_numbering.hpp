#pragma once
// A multigrid level's unknowns as one rank sees them, and a distributed matrix made from rows in
// that numbering: shared by the levels' maker (aggregation_levels.cpp) and their contact
// prolongations (level_contact_prolongation.cpp).

#include <petscmat.h>

#include <algorithm>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini::petsc {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor, int>;

// A level's numbering on one rank: the rank's own unknowns (global first .. first + count - 1)
// first, then the others' it needs (`foreign`, ascending).
struct ExtNumbering {
  PetscInt first = 0;
  PetscInt count = 0;
  std::vector<PetscInt> foreign;

  [[nodiscard]] Index size() const { return count + static_cast<Index>(foreign.size()); }
  [[nodiscard]] bool own(PetscInt g) const { return g >= first && g < first + count; }
  [[nodiscard]] Index local(PetscInt g) const {
    if (own(g)) return g - first;
    return count + static_cast<Index>(std::lower_bound(foreign.begin(), foreign.end(), g) -
                                      foreign.begin());
  }
  [[nodiscard]] PetscInt global(Index i) const {
    return i < count ? first + static_cast<PetscInt>(i)
                     : foreign[static_cast<std::size_t>(i - count)];
  }
  // Adds the global numbers in `seen` that are not own to `foreign` (sorted, unique).
  void add_foreign(const std::vector<PetscInt>& seen) {
    for (const PetscInt g : seen)
      if (!own(g)) foreign.push_back(g);
    std::sort(foreign.begin(), foreign.end());
    foreign.erase(std::unique(foreign.begin(), foreign.end()), foreign.end());
  }
};

/// This rank's rows of a distributed AIJ matrix from their local form (rows: the rank's own;
/// columns: `numbering`), `local_columns` of its columns owned here. Collective.
[[nodiscard]] Mat distributed_matrix(MPI_Comm comm, const RowMatrix& R,
                                     const ExtNumbering& numbering, PetscInt local_columns);

}  // namespace signorini::petsc

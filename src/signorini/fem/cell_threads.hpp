#pragma once
// The OpenMP threads of the loops over a mesh's cells (the assembly, the cell checks, the
// sparsity pattern, the nodal stresses): each thread owns a share of the nodes and writes only
// at its own, so that any number of threads gives one thread's result to the bit
// (docs/performance.md, "The stiffness assembly in parallel").

#include <algorithm>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/core/types.hpp"

namespace signorini {

/// Threads for a loop over `cells` cells: one below 20,000 cells, where starting them costs
/// more than they save; else OpenMP's (omp_set_num_threads, OMP_NUM_THREADS, the MPI ranks'
/// shares of the cores: PetscEngine).
[[nodiscard]] inline int cell_loop_threads(Index cells) {
#ifdef _OPENMP
  if (cells >= 20000) return std::max(1, omp_get_max_threads());
#endif
  (void)cells;
  return 1;
}

/// The calling thread's number in the enclosing parallel region (0 outside one).
[[nodiscard]] inline int thread_number() {
#ifdef _OPENMP
  return omp_get_thread_num();
#else
  return 0;
#endif
}

/// The share of [0, count) that i falls in, of `threads` even shares.
[[nodiscard]] inline int share_of(Index i, Index count, int threads) {
  return static_cast<int>(std::min<Index>(threads - 1, i * threads / std::max<Index>(count, 1)));
}

}  // namespace signorini

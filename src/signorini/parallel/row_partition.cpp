#include "signorini/parallel/row_partition.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"

namespace signorini {

std::vector<Index> row_partition(Index n, int ranks, const std::vector<Index>& node_of_unknown,
                                 const SparseMatrix& N) {
  if (ranks < 1) throw InputError(fmt::format("row_partition: {} ranks", ranks));
  if (n < ranks)
    throw InputError(
        fmt::format("{} MPI ranks for {} free unknowns: fewer ranks, please", ranks, n));
  if (!node_of_unknown.empty() && static_cast<Index>(node_of_unknown.size()) != n)
    throw InputError("row_partition: a node number per free unknown expected");
  // joined[i]: dof i belongs with dof i - 1 (the same mesh node, or the same row of N).
  std::vector<bool> joined(static_cast<std::size_t>(n), false);
  for (Index i = 1; i < n; ++i)
    if (!node_of_unknown.empty() && node_of_unknown[static_cast<std::size_t>(i)] ==
                                        node_of_unknown[static_cast<std::size_t>(i) - 1])
      joined[static_cast<std::size_t>(i)] = true;
  if (N.nonZeros() > 0) {
    const SparseMatrix Nt = N.transpose();  // column j: the dofs of contact row j
    for (Index j = 0; j < Nt.cols(); ++j) {
      Index first = n, last = -1;
      for (SparseMatrix::InnerIterator it(Nt, j); it; ++it) {
        first = std::min<Index>(first, it.row());
        last = std::max<Index>(last, it.row());
      }
      for (Index i = first + 1; i <= last; ++i) joined[static_cast<std::size_t>(i)] = true;
    }
  }
  std::vector<Index> starts(static_cast<std::size_t>(ranks) + 1, n);
  starts[0] = 0;
  for (int r = 1; r < ranks; ++r) {
    Index s = std::max(starts[static_cast<std::size_t>(r) - 1] + 1, n * r / ranks);
    while (s < n && joined[static_cast<std::size_t>(s)]) ++s;
    starts[static_cast<std::size_t>(r)] = s;
  }
  for (int r = 0; r < ranks; ++r)
    if (starts[static_cast<std::size_t>(r)] >= starts[static_cast<std::size_t>(r) + 1])
      throw InputError(fmt::format(
          "{} MPI ranks for {} free unknowns: rank {} would own none; fewer ranks, please", ranks,
          n, r));
  return starts;
}

}  // namespace signorini

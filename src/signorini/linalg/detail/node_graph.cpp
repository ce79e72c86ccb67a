#include "signorini/linalg/detail/node_graph.hpp"

#include <algorithm>

namespace signorini::detail {

cholmod_sparse NodeGraph::view() {
  cholmod_sparse graph{};
  graph.nrow = graph.ncol = group_start.size();
  graph.nzmax = rows.size();
  graph.p = colptr.data();
  graph.i = rows.data();
  graph.stype = 1;
  graph.itype = CHOLMOD_LONG;
  graph.xtype = CHOLMOD_PATTERN;
  graph.dtype = CHOLMOD_DOUBLE;
  graph.sorted = 1;
  graph.packed = 1;
  return graph;
}

NodeGraph node_graph(const SparseMatrix& A, const std::vector<bool>& singled_out,
                     bool keep_singled_out) {
  const Index n = A.rows();
  const int* outer = A.outerIndexPtr();
  const int* inner = A.innerIndexPtr();
  auto single = [&](Index j) {
    return !singled_out.empty() && singled_out[static_cast<std::size_t>(j)];
  };
  NodeGraph g;
  g.group.assign(static_cast<std::size_t>(n), -1);
  // Groups: runs of adjacent columns with identical patterns, not crossing a singled-out unknown.
  for (Index j = 0; j < n; ++j) {
    if (single(j)) {
      if (!keep_singled_out) continue;
      g.group_start.push_back(j);
      g.group[static_cast<std::size_t>(j)] = g.size() - 1;
      continue;
    }
    const bool same = j > 0 && !single(j - 1) &&
                      outer[j + 1] - outer[j] == outer[j] - outer[j - 1] &&
                      std::equal(inner + outer[j], inner + outer[j + 1], inner + outer[j - 1]);
    if (!same) g.group_start.push_back(j);
    g.group[static_cast<std::size_t>(j)] = g.size() - 1;
  }
  const Index ng = g.size();
  // The quotient graph, upper triangle, pattern only: one column represents its group.
  g.colptr.assign(static_cast<std::size_t>(ng + 1), 0);
  g.rows.reserve(static_cast<std::size_t>(A.nonZeros() / 4 + ng));
  std::vector<Index> seen(static_cast<std::size_t>(ng), -1);
  for (Index v = 0; v < ng; ++v) {
    const Index j = g.group_start[static_cast<std::size_t>(v)];
    const auto begin = g.rows.size();
    for (int k = outer[j]; k < outer[j + 1]; ++k) {
      const Index h = g.group[static_cast<std::size_t>(inner[k])];
      if (h < 0 || h > v || seen[static_cast<std::size_t>(h)] == v) continue;
      seen[static_cast<std::size_t>(h)] = v;
      g.rows.push_back(h);
    }
    std::sort(g.rows.begin() + static_cast<std::ptrdiff_t>(begin), g.rows.end());
    g.colptr[static_cast<std::size_t>(v + 1)] = static_cast<SuiteSparse_long>(g.rows.size());
  }
  return g;
}

}  // namespace signorini::detail

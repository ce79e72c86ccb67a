#include "signorini/linalg/vertex_separator.hpp"

#include <algorithm>

#include "signorini/linalg/detail/node_graph.hpp"

namespace signorini {

namespace {

/// The vertex graph with both triangles (the node graph keeps the upper one), without the
/// diagonal: adjacency lists for breadth-first searches.
struct Adjacency {
  std::vector<Index> start, next;
  explicit Adjacency(const detail::NodeGraph& g) {
    const Index n = g.size();
    start.assign(static_cast<std::size_t>(n + 1), 0);
    for (Index v = 0; v < n; ++v)
      for (auto k = g.colptr[static_cast<std::size_t>(v)];
           k < g.colptr[static_cast<std::size_t>(v + 1)]; ++k) {
        const auto u = static_cast<Index>(g.rows[static_cast<std::size_t>(k)]);
        if (u == v) continue;
        ++start[static_cast<std::size_t>(u + 1)];
        ++start[static_cast<std::size_t>(v + 1)];
      }
    for (Index v = 0; v < n; ++v)
      start[static_cast<std::size_t>(v + 1)] += start[static_cast<std::size_t>(v)];
    next.resize(static_cast<std::size_t>(start.back()));
    std::vector<Index> fill(start.begin(), start.end() - 1);
    for (Index v = 0; v < n; ++v)
      for (auto k = g.colptr[static_cast<std::size_t>(v)];
           k < g.colptr[static_cast<std::size_t>(v + 1)]; ++k) {
        const auto u = static_cast<Index>(g.rows[static_cast<std::size_t>(k)]);
        if (u == v) continue;
        next[static_cast<std::size_t>(fill[static_cast<std::size_t>(u)]++)] = v;
        next[static_cast<std::size_t>(fill[static_cast<std::size_t>(v)]++)] = u;
      }
  }
  [[nodiscard]] Index degree(Index v) const {
    return start[static_cast<std::size_t>(v + 1)] - start[static_cast<std::size_t>(v)];
  }
};

/// Breadth-first levels from `root` (-1: not reached); returns the vertices in visiting order.
std::vector<Index> levels_from(const Adjacency& a, Index root, std::vector<Index>& level) {
  std::fill(level.begin(), level.end(), -1);
  std::vector<Index> queue{root};
  queue.reserve(level.size());
  level[static_cast<std::size_t>(root)] = 0;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Index v = queue[head];
    for (Index k = a.start[static_cast<std::size_t>(v)];
         k < a.start[static_cast<std::size_t>(v + 1)]; ++k) {
      const Index u = a.next[static_cast<std::size_t>(k)];
      if (level[static_cast<std::size_t>(u)] >= 0) continue;
      level[static_cast<std::size_t>(u)] = level[static_cast<std::size_t>(v)] + 1;
      queue.push_back(u);
    }
  }
  return queue;
}

}  // namespace

VertexSeparator vertex_separator(const SparseMatrix& A) {
  const Index n = A.rows();
  VertexSeparator out;
  out.part.assign(static_cast<std::size_t>(n), 0);
  const detail::NodeGraph nodes = detail::node_graph(A, {}, false);
  const Index nv = nodes.size();
  if (nv < 3) {
    out.part_size[0] = n;
    return out;
  }
  const Adjacency adj(nodes);
  // A pseudo-peripheral root (George and Liu): from a vertex, go to a vertex of least degree in
  // the last level while that makes the level structure deeper. On a strip of cells the root
  // ends in a corner and the levels run across the strip.
  std::vector<Index> level(static_cast<std::size_t>(nv), -1);
  Index root = 0;
  std::vector<Index> order = levels_from(adj, root, level);
  Index depth = level[static_cast<std::size_t>(order.back())];
  for (int sweep = 0; sweep < 8; ++sweep) {
    Index candidate = order.back();
    for (auto it = order.rbegin();
         it != order.rend() && level[static_cast<std::size_t>(*it)] == depth; ++it)
      if (adj.degree(*it) < adj.degree(candidate)) candidate = *it;
    std::vector<Index> level2(static_cast<std::size_t>(nv), -1);
    std::vector<Index> order2 = levels_from(adj, candidate, level2);
    const Index depth2 = level2[static_cast<std::size_t>(order2.back())];
    if (depth2 <= depth) break;
    root = candidate;
    level.swap(level2);
    order.swap(order2);
    depth = depth2;
  }
  // The separator is the level at which half the reached vertices have been visited; vertices
  // below it form part 0, above it part 1 (a level couples only to its two neighbours). Those of
  // the separator level without a neighbour in the next level join part 0.
  const Index median = level[static_cast<std::size_t>(order[order.size() / 2])];
  if (median == 0 || median == depth) {
    out.part_size[0] = n;  // no level structure to cut (a clique, or one level reached)
    return out;
  }
  std::vector<std::int8_t> vertex_part(static_cast<std::size_t>(nv), 1);  // unreached: part 1
  for (const Index v : order) {
    const Index l = level[static_cast<std::size_t>(v)];
    if (l < median) {
      vertex_part[static_cast<std::size_t>(v)] = 0;
    } else if (l == median) {
      bool touches_above = false;
      for (Index k = adj.start[static_cast<std::size_t>(v)];
           k < adj.start[static_cast<std::size_t>(v + 1)]; ++k)
        touches_above =
            touches_above ||
            level[static_cast<std::size_t>(adj.next[static_cast<std::size_t>(k)])] > median;
      vertex_part[static_cast<std::size_t>(v)] = touches_above ? 2 : 0;
    }
  }
  for (Index j = 0; j < n; ++j) {
    const std::int8_t p =
        vertex_part[static_cast<std::size_t>(nodes.group[static_cast<std::size_t>(j)])];
    out.part[static_cast<std::size_t>(j)] = p;
    if (p == 2)
      ++out.separator_size;
    else
      ++out.part_size[static_cast<std::size_t>(p)];
  }
  return out;
}

}  // namespace signorini

#include "signorini/mesh/cell_overlap.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// A cell's facet by its corners: the other corners in increasing order (the smallest is the
// bucket it is kept in), the cell, and which way the corner cycle turns seen from the smallest.
struct FacetSeen {
  std::array<Index, 3> others;
  Index cell;
  bool forward;
};

std::string node_list(const std::vector<Index>& nodes) {
  std::string out;
  for (std::size_t k = 0; k < nodes.size(); ++k)
    out += (k > 0 ? ", " : "") + std::to_string(nodes[k]);
  return out;
}

}  // namespace

void check_cells_do_not_overlap(const Mesh& mesh, const std::string& what,
                                const std::function<std::string(Index cell)>& cell_name) {
  const Index nc = mesh.num_cells();
  const auto nn = static_cast<std::size_t>(mesh.num_nodes());
  // Collapsed cells: a node named twice (its corners or its other nodes).
  std::vector<Index> sorted;
  for (Index c = 0; c < nc; ++c) {
    const auto nodes = mesh.cell(c);
    sorted.assign(nodes.begin(), nodes.end());
    std::sort(sorted.begin(), sorted.end());
    if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
      throw InputError(
          fmt::format("{}: {} names node {} twice (a collapsed cell): expected {} distinct nodes",
                      what, cell_name(c), *twice, nodes.size()));
  }
  // The cells around each corner node (32-bit cell numbers: a third of the memory of the
  // facets themselves), then around each node v the facets whose smallest corner is v, sorted
  // by their other corners: a facet's copies meet in its smallest corner's list.
  std::vector<std::uint32_t> start(nn + 1, 0);
  for (Index c = 0; c < nc; ++c) {
    const auto nodes = mesh.cell(c);
    for (int a = 0; a < corners_per_cell(mesh.cell_type(c)); ++a)
      ++start[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)]) + 1];
  }
  for (std::size_t v = 0; v < nn; ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> around(start[nn]);
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (Index c = 0; c < nc; ++c) {
      const auto nodes = mesh.cell(c);
      for (int a = 0; a < corners_per_cell(mesh.cell_type(c)); ++a)
        around[next[static_cast<std::size_t>(nodes[static_cast<std::size_t>(a)])]++] =
            static_cast<std::uint32_t>(c);
    }
  }
  const auto cell_nodes = [&](Index c) {
    const auto nodes = mesh.cell(c);
    std::vector<Index> v(nodes.begin(), nodes.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  std::vector<FacetSeen> bucket;
  std::array<Index, 4> corners{};
  for (std::size_t v = 0; v < nn; ++v) {
    bucket.clear();
    for (std::uint32_t p = start[v]; p < start[v + 1]; ++p) {
      const Index c = around[p];
      const CellType t = mesh.cell_type(c);
      const auto nodes = mesh.cell(c);
      const int k = corners_per_cell(facet_type(t));
      for (int f = 0; f < facets_per_cell(t); ++f) {
        const auto local = facet_local_nodes(t, f);
        for (int a = 0; a < k; ++a)
          corners[static_cast<std::size_t>(a)] =
              nodes[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])];
        const auto first = static_cast<int>(std::min_element(corners.begin(), corners.begin() + k) -
                                            corners.begin());
        if (corners[static_cast<std::size_t>(first)] != static_cast<Index>(v)) continue;
        // The cycle read from the smallest corner: "forward" where its next corner is smaller
        // than its previous one (for an edge: where it starts at its smaller end). The cell
        // across the facet reads it the other way round.
        const Index next = corners[static_cast<std::size_t>((first + 1) % k)];
        const Index previous = corners[static_cast<std::size_t>((first + k - 1) % k)];
        FacetSeen s{{-1, -1, -1}, c, k == 2 ? first == 0 : next < previous};
        int o = 0;
        for (int a = 0; a < k; ++a)
          if (a != first)
            s.others[static_cast<std::size_t>(o++)] = corners[static_cast<std::size_t>(a)];
        std::sort(s.others.begin(), s.others.begin() + (k - 1));
        bucket.push_back(s);
      }
    }
    std::sort(bucket.begin(), bucket.end(), [](const FacetSeen& x, const FacetSeen& y) {
      return x.others != y.others ? x.others < y.others : x.cell < y.cell;
    });
    for (auto it = bucket.begin(); it != bucket.end();) {
      auto end = it + 1;
      while (end != bucket.end() && end->others == it->others) ++end;
      if (end - it > 1) {
        std::vector<Index> facet{static_cast<Index>(v)};
        for (const Index w : it->others)
          if (w >= 0) facet.push_back(w);
        for (auto x = it; x != end; ++x)
          for (auto y = x + 1; y != end; ++y)
            if (cell_nodes(x->cell) == cell_nodes(y->cell))
              throw InputError(fmt::format(
                  "{}: {} and {} have the same nodes (a doubled cell, its stiffness counted "
                  "twice): expected each cell once",
                  what, cell_name(x->cell), cell_name(y->cell)));
        if (end - it > 2)
          throw InputError(fmt::format(
              "{}: the facet with corners {} bounds {} cells ({}, {}, {}): the cells overlap; "
              "expected at most two cells on a facet, one on each side",
              what, node_list(facet), end - it, cell_name(it->cell), cell_name((it + 1)->cell),
              cell_name((it + 2)->cell)));
        if (it->forward == (it + 1)->forward)
          throw InputError(fmt::format(
              "{}: {} and {} lie on the same side of their common facet (corners {}): the cells "
              "overlap; expected cells that meet face to face, each on its own side",
              what, cell_name(it->cell), cell_name((it + 1)->cell), node_list(facet)));
      }
      it = end;
    }
  }
}

}  // namespace signorini

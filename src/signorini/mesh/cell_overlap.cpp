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
// bucket it is kept in; kNone after them), the cell, and which way the corner cycle turns seen
// from the smallest. 32-bit numbers: meshes of up to four billion nodes and cells.
constexpr std::uint32_t kNone = 0xffffffffU;
struct FacetSeen {
  std::array<std::uint32_t, 3> others;
  std::uint32_t cell;
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
  // Collapsed cells: a node named twice (its corners or its other nodes). An insertion sort of
  // each cell's nodes in place (at most 27; no allocation per cell).
  std::array<Index, 32> sorted{};
  for (Index c = 0; c < nc; ++c) {
    const auto nodes = mesh.cell(c);
    const std::size_t k = std::min(nodes.size(), sorted.size());
    for (std::size_t a = 0; a < k; ++a) {
      std::size_t b = a;
      for (; b > 0 && sorted[b - 1] > nodes[a]; --b) sorted[b] = sorted[b - 1];
      sorted[b] = nodes[a];
    }
    for (std::size_t a = 1; a < k; ++a)
      if (sorted[a] == sorted[a - 1])
        throw InputError(
            fmt::format("{}: {} names node {} twice (a collapsed cell): expected {} distinct nodes",
                        what, cell_name(c), sorted[a], nodes.size()));
  }
  // Each cell type's facets as local corner numbers, looked up once (not per facet visit).
  struct TypeFacets {
    int count = 0, corners = 0;
    std::array<std::array<int, 4>, 6> local{};
  };
  std::array<TypeFacets, kCellTypeNames.size()> facets_of{};
  for (const CellType t : mesh.cell_types()) {
    TypeFacets& tf = facets_of[static_cast<std::size_t>(t)];
    tf.count = facets_per_cell(t);
    tf.corners = corners_per_cell(facet_type(t));
    for (int f = 0; f < tf.count; ++f) {
      const auto local = facet_local_nodes(t, f);
      for (int a = 0; a < tf.corners; ++a)
        tf.local[static_cast<std::size_t>(f)][static_cast<std::size_t>(a)] =
            local[static_cast<std::size_t>(a)];
    }
  }
  // Every facet once, in the cells' order (the connectivity read in sequence), placed in the
  // bucket of its smallest corner by a counting sort: 20 bytes a facet (165 MB for the two
  // million tetrahedra of a million-unknown mesh, freed before the assembly). A walk over the
  // cells around each node instead read the connectivity out of order and took 1.8 s there
  // (this, 1.0 s: a quarter of reading the file).
  const auto facet_of = [&](Index c, int f, FacetSeen& s) {
    const TypeFacets& tf = facets_of[static_cast<std::size_t>(mesh.cell_type(c))];
    const auto nodes = mesh.cell(c);
    const int k = tf.corners;
    std::array<Index, 4> corners{};
    const auto& local = tf.local[static_cast<std::size_t>(f)];
    for (int a = 0; a < k; ++a)
      corners[static_cast<std::size_t>(a)] =
          nodes[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])];
    int first = 0;
    for (int a = 1; a < k; ++a)
      if (corners[static_cast<std::size_t>(a)] < corners[static_cast<std::size_t>(first)])
        first = a;
    // The cycle read from the smallest corner: "forward" where its next corner is smaller than
    // its previous one (for an edge: where it starts at its smaller end). The cell across the
    // facet reads it the other way round.
    const Index next = corners[static_cast<std::size_t>((first + 1) % k)];
    const Index previous = corners[static_cast<std::size_t>((first + k - 1) % k)];
    s.cell = static_cast<std::uint32_t>(c);
    s.forward = k == 2 ? first == 0 : next < previous;
    s.others = {kNone, kNone, kNone};
    int o = 0;
    for (int a = 0; a < k; ++a)
      if (a != first)
        s.others[static_cast<std::size_t>(o++)] =
            static_cast<std::uint32_t>(corners[static_cast<std::size_t>(a)]);
    for (int a = 1; a < k - 1; ++a)  // (at most three: an insertion sort)
      for (int b = a; b > 0 && s.others[static_cast<std::size_t>(b - 1)] >
                                   s.others[static_cast<std::size_t>(b)];
           --b)
        std::swap(s.others[static_cast<std::size_t>(b - 1)], s.others[static_cast<std::size_t>(b)]);
    return corners[static_cast<std::size_t>(first)];
  };
  std::vector<std::uint32_t> start(nn + 1, 0);
  for (Index c = 0; c < nc; ++c) {  // (the counts need only each facet's smallest corner)
    const TypeFacets& tf = facets_of[static_cast<std::size_t>(mesh.cell_type(c))];
    const auto nodes = mesh.cell(c);
    for (int f = 0; f < tf.count; ++f) {
      const auto& local = tf.local[static_cast<std::size_t>(f)];
      Index smallest = nodes[static_cast<std::size_t>(local[0])];
      for (int a = 1; a < tf.corners; ++a)
        smallest =
            std::min(smallest, nodes[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])]);
      ++start[static_cast<std::size_t>(smallest) + 1];
    }
  }
  FacetSeen s{};
  for (std::size_t v = 0; v < nn; ++v) start[v + 1] += start[v];
  std::vector<FacetSeen> seen(start[nn]);
  {
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (Index c = 0; c < nc; ++c)
      for (int f = 0; f < facets_of[static_cast<std::size_t>(mesh.cell_type(c))].count; ++f) {
        const Index v = facet_of(c, f, s);
        seen[next[static_cast<std::size_t>(v)]++] = s;
      }
  }
  const auto cell_nodes = [&](Index c) {
    const auto nodes = mesh.cell(c);
    std::vector<Index> v(nodes.begin(), nodes.end());
    std::sort(v.begin(), v.end());
    return v;
  };
  for (std::size_t v = 0; v < nn; ++v) {
    const auto bucket_begin = seen.begin() + start[v], bucket_end = seen.begin() + start[v + 1];
    std::sort(bucket_begin, bucket_end, [](const FacetSeen& x, const FacetSeen& y) {
      return x.others != y.others ? x.others < y.others : x.cell < y.cell;
    });
    for (auto it = bucket_begin; it != bucket_end;) {
      auto end = it + 1;
      while (end != bucket_end && end->others == it->others) ++end;
      // Two cells on opposite sides: a conforming mesh's inner facet (nearly every group).
      const bool usual = end - it == 2 && it->forward != (it + 1)->forward;
      if (end - it > 1 && !usual) {
        std::vector<Index> facet{static_cast<Index>(v)};
        for (const std::uint32_t w : it->others)
          if (w != kNone) facet.push_back(static_cast<Index>(w));
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

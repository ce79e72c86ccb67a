#include "signorini/mesh/facet_matching.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

namespace signorini {

namespace {

// A facet by its sorted corners, -1 after them.
using FacetKey = std::array<Index, 4>;

struct FacetKeyHash {
  std::size_t operator()(const FacetKey& k) const {
    std::uint64_t h = 0;
    for (const Index v : k) h = (h ^ static_cast<std::uint64_t>(v)) * 0x9e3779b97f4a7c15ULL;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }
};

// The key of `n` corners; nullopt if one is not a node of the mesh (negative).
template <class Corner>
std::optional<FacetKey> facet_key(int n, Corner corner) {
  FacetKey k;
  k.fill(-1);
  if (n < 1 || n > 4) return std::nullopt;
  for (int a = 0; a < n; ++a) {
    k[static_cast<std::size_t>(a)] = corner(a);
    if (k[static_cast<std::size_t>(a)] < 0) return std::nullopt;
  }
  // At most 4 entries: an insertion sort (std::sort over a run of unknown length makes g++ 12
  // warn of bounds it cannot prove).
  for (std::size_t a = 1; a < static_cast<std::size_t>(n); ++a)
    for (std::size_t b = a; b > 0 && k[b - 1] > k[b]; --b) std::swap(k[b - 1], k[b]);
  return k;
}

}  // namespace

int boundary_element_corners(int dim, int nodes) {
  if (dim == 2) return nodes == 2 || nodes == 3 ? 2 : 0;
  if (dim == 3) {
    if (nodes == 3 || nodes == 6) return 3;
    if (nodes == 4 || nodes == 8 || nodes == 9) return 4;
  }
  return 0;
}

std::vector<std::optional<Facet>> match_facets(const Mesh& mesh,
                                               const std::vector<BoundaryElement>& elements) {
  // The elements' keys go into a table first (a boundary's worth), then every cell facet is
  // looked up in it: one pass over the cells, whatever the number of elements.
  std::vector<std::optional<FacetKey>> keys(elements.size());
  std::unordered_map<FacetKey, Facet, FacetKeyHash> facets;
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const BoundaryElement& e = elements[i];
    if (static_cast<int>(e.nodes.size()) < e.corners) continue;
    keys[i] = facet_key(e.corners, [&](int a) { return e.nodes[static_cast<std::size_t>(a)]; });
    if (keys[i]) facets.emplace(*keys[i], Facet{-1, 0});
  }
  // A cell facet can be an element only if all its corners are corners of elements: a flag per
  // node turns away the inner facets (all but a few of a 3D mesh's) before any hashing.
  std::vector<bool> on_element(static_cast<std::size_t>(mesh.num_nodes()), false);
  for (const auto& [key, facet] : facets)
    for (const Index v : key)
      if (v >= 0 && v < mesh.num_nodes()) on_element[static_cast<std::size_t>(v)] = true;
  if (!facets.empty())
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int f = 0; f < facets_per_cell(mesh.cell_type(c)); ++f) {
        const auto local = facet_local_nodes(mesh.cell_type(c), f);
        const auto cell = mesh.cell(c);
        const int corners = corners_per_cell(facet_type(mesh.cell_type(c)));
        bool candidate = true;
        for (int a = 0; a < corners && candidate; ++a)
          candidate = on_element[static_cast<std::size_t>(
              cell[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])])];
        if (!candidate) continue;
        const auto k = facet_key(corners, [&](int a) {
          return cell[static_cast<std::size_t>(local[static_cast<std::size_t>(a)])];
        });
        const auto it = facets.find(*k);
        if (it != facets.end() && it->second.cell < 0) it->second = Facet{c, f};
      }
  std::vector<std::optional<Facet>> out(elements.size());
  for (std::size_t i = 0; i < elements.size(); ++i) {
    const auto it = keys[i] ? facets.find(*keys[i]) : facets.end();
    if (it == facets.end() || it->second.cell < 0) continue;
    const BoundaryElement& e = elements[i];
    // An element with more than its corners (a second-order one) must have the facet's nodes;
    // one of the first order names the facet by its corners alone.
    if (static_cast<int>(e.nodes.size()) > e.corners) {
      std::vector<Index> fn = mesh.facet_nodes(it->second);
      std::vector<Index> v(e.nodes.begin(), e.nodes.end());
      std::sort(fn.begin(), fn.end());
      std::sort(v.begin(), v.end());
      if (fn != v) continue;
    }
    out[i] = it->second;
  }
  return out;
}

}  // namespace signorini

#include "signorini/mesh/cell_type.hpp"

#include <array>
#include <stdexcept>

namespace signorini {

namespace {
// Quad4: nodes counterclockwise 0:(-1,-1) 1:(1,-1) 2:(1,1) 3:(-1,1); facets bottom, right, top,
// left.
constexpr std::array<std::array<int, 2>, 4> kQuad4Facets{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
constexpr std::array<std::array<int, 2>, 3> kTri3Facets{{{0, 1}, {1, 2}, {2, 0}}};
// Hex8 and Tet4 faces are ordered counterclockwise seen from outside.
constexpr std::array<std::array<int, 4>, 6> kHex8Facets{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
constexpr std::array<std::array<int, 3>, 4> kTet4Facets{
    {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
}  // namespace

std::span<const int> facet_local_nodes(CellType t, int facet) {
  if (facet < 0 || facet >= facets_per_cell(t))
    throw std::out_of_range("facet number out of range");
  const auto f = static_cast<std::size_t>(facet);
  switch (t) {
    case CellType::Quad4:
      return kQuad4Facets[f];
    case CellType::Tri3:
      return kTri3Facets[f];
    case CellType::Hex8:
      return kHex8Facets[f];
    case CellType::Tet4:
      return kTet4Facets[f];
  }
  throw std::logic_error("unknown cell type");
}

}  // namespace signorini

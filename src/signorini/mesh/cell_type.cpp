#include "signorini/mesh/cell_type.hpp"

#include <array>
#include <stdexcept>

namespace signorini {

namespace {
// Quadrilaterals: corners counterclockwise 0:(-1,-1) 1:(1,-1) 2:(1,1) 3:(-1,1), mid-edge nodes
// 4..7 on edges 0-1, 1-2, 2-3, 3-0, centre 8 (Quad9); facets bottom, right, top, left.
constexpr std::array<std::array<int, 2>, 4> kQuad4Facets{{{0, 1}, {1, 2}, {2, 3}, {3, 0}}};
constexpr std::array<std::array<int, 3>, 4> kQuad2Facets{
    {{0, 1, 4}, {1, 2, 5}, {2, 3, 6}, {3, 0, 7}}};
// Triangles: corners 0:(0,0) 1:(1,0) 2:(0,1), mid-edge nodes 3..5 on edges 0-1, 1-2, 2-0.
constexpr std::array<std::array<int, 2>, 3> kTri3Facets{{{0, 1}, {1, 2}, {2, 0}}};
constexpr std::array<std::array<int, 3>, 3> kTri6Facets{{{0, 1, 3}, {1, 2, 4}, {2, 0, 5}}};
constexpr std::array<std::array<int, 1>, 2> kLineFacets{{{0}, {1}}};
// 3D faces: corners counterclockwise seen from outside (the outward normal by the right-hand
// rule), then, on quadratic cells, the face's mid-edge nodes in the order of its edges and its
// centre (the Tri6 and Quad9 orders). Hexahedra: z = -1, z = 1, y = -1, x = 1, y = 1, x = -1.
constexpr std::array<std::array<int, 4>, 6> kHex8Facets{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
constexpr std::array<std::array<int, 9>, 6> kHex27Facets{{{0, 3, 2, 1, 9, 13, 11, 8, 20},
                                                          {4, 5, 6, 7, 16, 18, 19, 17, 25},
                                                          {0, 1, 5, 4, 8, 12, 16, 10, 21},
                                                          {1, 2, 6, 5, 11, 14, 18, 12, 23},
                                                          {2, 3, 7, 6, 13, 15, 19, 14, 24},
                                                          {3, 0, 4, 7, 9, 10, 17, 15, 22}}};
constexpr std::array<std::array<int, 3>, 4> kTet4Facets{
    {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}}};
constexpr std::array<std::array<int, 6>, 4> kTet10Facets{
    {{0, 2, 1, 6, 5, 4}, {0, 1, 3, 4, 9, 7}, {1, 2, 3, 5, 8, 9}, {0, 3, 2, 7, 8, 6}}};
}  // namespace

CellType facet_type(CellType t) {
  switch (t) {
    case CellType::Tri3:
    case CellType::Quad4:
      return CellType::Line2;
    case CellType::Tri6:
    case CellType::Quad8:
    case CellType::Quad9:
      return CellType::Line3;
    case CellType::Tet4:
      return CellType::Tri3;
    case CellType::Tet10:
      return CellType::Tri6;
    case CellType::Hex8:
      return CellType::Quad4;
    case CellType::Hex27:
      return CellType::Quad9;
    case CellType::Line2:
    case CellType::Line3:
      break;
  }
  throw std::logic_error("facet_type: a line has no facet cell type");
}

std::span<const int> facet_local_nodes(CellType t, int facet) {
  if (facet < 0 || facet >= facets_per_cell(t))
    throw std::out_of_range("facet number out of range");
  const auto f = static_cast<std::size_t>(facet);
  switch (t) {
    case CellType::Line2:
    case CellType::Line3:
      return kLineFacets[f];
    case CellType::Tri3:
      return kTri3Facets[f];
    case CellType::Tri6:
      return kTri6Facets[f];
    case CellType::Quad4:
      return kQuad4Facets[f];
    case CellType::Quad8:
    case CellType::Quad9:
      return kQuad2Facets[f];
    case CellType::Tet4:
      return kTet4Facets[f];
    case CellType::Tet10:
      return kTet10Facets[f];
    case CellType::Hex8:
      return kHex8Facets[f];
    case CellType::Hex27:
      return kHex27Facets[f];
  }
  throw std::logic_error("unknown cell type");
}

}  // namespace signorini

// libFuzzer target: a mesh from a user's arrays (mesh_from_arrays), the path of signorini.Mesh in
// Python and of C++ callers. The bytes are read as a small mesh: a dimension, points (coordinates
// from single bytes, so that duplicates, collinear and coincident points are common), blocks of
// cells of any type with node numbers, and a boundary part. Besides crashes and sanitizer
// reports, it checks that every error is an InputError with a one-line message, and that an
// accepted mesh has no collapsed or doubled cell and positive orientation. Built and run by
// tests/fuzz/run.sh, not by the normal build.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/mesh/cell_orientation.hpp"
#include "signorini/mesh/mesh_arrays.hpp"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "mesh_arrays_fuzzer: %s: %s\n", what, detail.c_str());
  std::abort();
}

// The bytes one at a time, 0 once they run out.
struct Bytes {
  const std::uint8_t* data;
  std::size_t size, at = 0;
  int next() { return at < size ? data[at++] : 0; }
  [[nodiscard]] bool done() const { return at >= size; }
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace signorini;
  Bytes in{data, size};
  MeshArrays a;
  const int rows = 2 + in.next() % 2;  // 2D or 3D points (3 rows may carry 2D cells)
  const int n = 1 + in.next() % 24;
  a.points.resize(rows, n);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < rows; ++k) a.points(k, i) = static_cast<double>(in.next() % 8) - 2.0;
  static constexpr CellType kTypes[] = {CellType::Tri3,  CellType::Tri6,  CellType::Quad4,
                                        CellType::Quad8, CellType::Quad9, CellType::Tet4,
                                        CellType::Tet10, CellType::Hex8,  CellType::Hex27};
  const int blocks = 1 + in.next() % 3;
  for (int b = 0; b < blocks && !in.done(); ++b) {
    CellBlock block;
    block.type = kTypes[in.next() % 9];
    const int cells = 1 + in.next() % 6;
    for (int c = 0; c < cells * nodes_per_cell(block.type); ++c)
      block.nodes.push_back(in.next() % (n + 1) - (in.next() % 64 == 0 ? 1 : 0));
    block.region = in.next() % 2 ? "r" : "";
    a.blocks.push_back(std::move(block));
  }
  if (in.next() % 2) {
    BoundaryFacets f{"side", 2 + in.next() % 3, {}};
    for (int k = 0; k < f.nodes_per_facet * (1 + in.next() % 3); ++k)
      f.nodes.push_back(in.next() % (n + 1));
    a.boundaries.push_back(std::move(f));
  }
  try {
    const Mesh mesh = mesh_from_arrays(a);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell(c);
      for (std::size_t i = 0; i < nodes.size(); ++i)
        for (std::size_t j = i + 1; j < nodes.size(); ++j)
          if (nodes[i] == nodes[j]) broken("a collapsed cell accepted", std::to_string(c));
      if (mesh.dim() == 2 &&
          !(signed_corner_area2(mesh.cell_type(c), nodes.data(), mesh.coordinates()) > 0.0))
        broken("a 2D cell not counterclockwise", std::to_string(c));
      if (mesh.dim() == 3 &&
          !(min_corner_det(mesh.cell_type(c), nodes.data(), mesh.coordinates()) > 0.0))
        broken("a 3D cell not positively oriented", std::to_string(c));
    }
  } catch (const InputError& e) {
    if (std::strchr(e.what(), '\n') != nullptr) broken("multi-line error", e.what());
  } catch (const std::exception& e) {
    broken("an exception that is not an InputError", e.what());
  }
  return 0;
}

// libFuzzer target: the Gmsh reader (parse_gmsh_mesh) on arbitrary bytes, ASCII and binary,
// formats 4.1 and 2.2. Besides crashes and sanitizer reports, it checks what the reader promises:
//   - every error is an InputError with a one-line message (no other exception);
//   - a mesh it returns is sound: node numbers in range, cells of one dimension, no cell that
//     names a node twice, every boundary facet a facet of its cell.
// Built and run by tests/fuzz/run.sh, not by the normal build.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/mesh/gmsh_reader.hpp"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "gmsh_reader_fuzzer: %s: %s\n", what, detail.c_str());
  std::abort();
}

void check_mesh(const signorini::Mesh& mesh) {
  using signorini::Index;
  if (mesh.num_cells() == 0) broken("a mesh without cells", "");
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (signorini::cell_dimension(mesh.cell_type(c)) != mesh.dim())
      broken("a cell of another dimension", std::to_string(c));
    const auto nodes = mesh.cell(c);
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      if (nodes[a] < 0 || nodes[a] >= mesh.num_nodes()) broken("node out of range", "");
      for (std::size_t b = a + 1; b < nodes.size(); ++b)
        if (nodes[a] == nodes[b]) broken("a collapsed cell accepted", std::to_string(c));
    }
  }
  for (const std::string& name : mesh.boundary_part_names())
    for (const signorini::Facet& f : mesh.boundary_part(name).facets) {
      if (f.cell < 0 || f.cell >= mesh.num_cells()) broken("facet of no cell", name);
      if (f.local < 0 || f.local >= signorini::facets_per_cell(mesh.cell_type(f.cell)))
        broken("facet number out of range", name);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    check_mesh(signorini::parse_gmsh_mesh(text, "fuzz.msh"));
  } catch (const signorini::InputError& e) {
    if (std::strchr(e.what(), '\n') != nullptr) broken("multi-line error", e.what());
    if (std::strncmp(e.what(), "fuzz.msh", 8) != 0) broken("error without the file", e.what());
  } catch (const std::exception& e) {
    broken("an exception that is not an InputError", e.what());
  }
  return 0;
}

#pragma once
// A vertex separator of a stiffness matrix's graph: two parts that no entry of the matrix couples,
// and the unknowns between them. The two-part Schur complement (schur_complement.hpp) factorises
// the parts on two threads at once.

#include <array>
#include <cstdint>
#include <vector>

#include "signorini/core/types.hpp"

namespace signorini {

struct VertexSeparator {
  /// Per unknown: 0 or 1 (the part), 2 (the separator).
  std::vector<std::int8_t> part;
  Index separator_size = 0;  // unknowns with part 2
  std::array<Index, 2> part_size{0, 0};
};

/// Splits the unknowns of A (symmetric pattern, both triangles stored) in two parts of about equal
/// size and a separator: the middle level of a breadth-first level structure from a
/// pseudo-peripheral vertex of the graph of the mesh nodes (George and Liu's automatic nested
/// dissection, one level), so that a node's components stay together. On the paper's strip it
/// finds the shortest cut, one column of nodes, as METIS's vertex separator does, in 0.02 s
/// instead of 0.16 s at 960x320 (docs/performance.md); a poor cut on another geometry costs speed,
/// not accuracy, and the Schur complement falls back to one part when the cut is too large.
/// All parts 0 when A has no level structure to cut.
VertexSeparator vertex_separator(const SparseMatrix& A);

}  // namespace signorini

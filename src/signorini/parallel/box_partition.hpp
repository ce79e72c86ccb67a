#pragma once
// The partition of a generated box among the ranks of a distributed run (docs/distributed.md,
// "A box made in parts"): a grid of px x py x pz blocks of cubes, one per rank, chosen to cut the
// fewest cube faces, so that each rank makes its own part of the mesh and no rank ever holds the
// whole. A rank owns the lattice points of its block, the points on a block's upper faces
// belonging to the next block (the last block along an axis keeps the box's far side).

#include <array>

#include "signorini/core/types.hpp"
#include "signorini/mesh/box_mesh.hpp"

namespace signorini {

class BoxPartition {
 public:
  /// The blocks of `box` for `ranks` ranks; possible() is false where no grid gives every rank
  /// at least one cube along each axis (a tiny box on many ranks).
  BoxPartition(const BoxMeshOptions& box, int ranks);

  [[nodiscard]] bool possible() const { return possible_; }
  /// The blocks along x, y and z (their product is the number of ranks).
  [[nodiscard]] const std::array<int, 3>& grid() const { return grid_; }
  /// Rank r's cubes along axis a: first_cube(r)[a] <= i < end_cube(r)[a].
  [[nodiscard]] std::array<Index, 3> first_cube(int rank) const;
  [[nodiscard]] std::array<Index, 3> end_cube(int rank) const;
  /// The cubes of rank r's part of the mesh: two layers of cubes around its block (every cube
  /// that touches a node of a cube that touches one of its points), clipped to the box.
  [[nodiscard]] std::array<Index, 3> first_part_cube(int rank) const;
  [[nodiscard]] std::array<Index, 3> end_part_cube(int rank) const;
  /// The lattice points rank r owns along axis a: first_point(r)[a] <= I < end_point(r)[a].
  [[nodiscard]] std::array<Index, 3> first_point(int rank) const;
  [[nodiscard]] std::array<Index, 3> end_point(int rank) const;
  /// The rank that owns lattice point (I, J, K) of the whole box.
  [[nodiscard]] int owner(const std::array<Index, 3>& point) const;
  /// Lattice point of the whole box's node number v.
  [[nodiscard]] std::array<Index, 3> point(Index v) const;

 private:
  std::array<Index, 3> cubes_{};   // nx, ny, nz
  std::array<Index, 3> points_{};  // lattice points along each axis
  Index order_ = 1;                // lattice steps per cube
  std::array<int, 3> grid_{1, 1, 1};
  bool possible_ = false;
  // Block t along axis a starts at cube floor(t n_a / q_a).
  [[nodiscard]] Index cube_start(std::size_t axis, int block) const;
  [[nodiscard]] std::array<int, 3> block(int rank) const;
};

}  // namespace signorini

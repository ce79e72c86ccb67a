#include "signorini/parallel/box_partition.hpp"

#include <algorithm>
#include <limits>

namespace signorini {

BoxPartition::BoxPartition(const BoxMeshOptions& box, int ranks) {
  cubes_ = {box.nx, box.ny, box.nz};
  order_ = cell_order(box.cell);
  for (std::size_t a = 0; a < 3; ++a) points_[a] = order_ * cubes_[a] + 1;
  // The grid whose interfaces cut the fewest cube faces: (px - 1) ny nz + ... over the
  // factorisations of the ranks that give every block a cube along each axis.
  double best = std::numeric_limits<double>::infinity();
  for (int px = 1; px <= ranks; ++px) {
    if (ranks % px != 0) continue;
    for (int py = 1; py <= ranks / px; ++py) {
      if ((ranks / px) % py != 0) continue;
      const int pz = ranks / px / py;
      if (px > cubes_[0] || py > cubes_[1] || pz > cubes_[2]) continue;
      const auto x = static_cast<double>(cubes_[0]), y = static_cast<double>(cubes_[1]),
                 z = static_cast<double>(cubes_[2]);
      const double cut = (px - 1) * y * z + (py - 1) * x * z + (pz - 1) * x * y;
      if (cut < best) {
        best = cut;
        grid_ = {px, py, pz};
        possible_ = true;
      }
    }
  }
}

Index BoxPartition::cube_start(std::size_t axis, int block) const {
  return block * cubes_[axis] / grid_[axis];
}

std::array<int, 3> BoxPartition::block(int rank) const {
  return {rank % grid_[0], (rank / grid_[0]) % grid_[1], rank / (grid_[0] * grid_[1])};
}

std::array<Index, 3> BoxPartition::first_cube(int rank) const {
  const std::array<int, 3> b = block(rank);
  return {cube_start(0, b[0]), cube_start(1, b[1]), cube_start(2, b[2])};
}

std::array<Index, 3> BoxPartition::end_cube(int rank) const {
  const std::array<int, 3> b = block(rank);
  return {cube_start(0, b[0] + 1), cube_start(1, b[1] + 1), cube_start(2, b[2] + 1)};
}

std::array<Index, 3> BoxPartition::first_part_cube(int rank) const {
  std::array<Index, 3> f = first_cube(rank);
  for (Index& i : f) i = std::max<Index>(0, i - 2);
  return f;
}

std::array<Index, 3> BoxPartition::end_part_cube(int rank) const {
  std::array<Index, 3> e = end_cube(rank);
  for (std::size_t a = 0; a < 3; ++a) e[a] = std::min(cubes_[a], e[a] + 1);
  return e;
}

std::array<Index, 3> BoxPartition::first_point(int rank) const {
  std::array<Index, 3> f = first_cube(rank);
  for (Index& i : f) i *= order_;
  return f;
}

std::array<Index, 3> BoxPartition::end_point(int rank) const {
  std::array<Index, 3> e = end_cube(rank);
  for (std::size_t a = 0; a < 3; ++a) e[a] = e[a] == cubes_[a] ? points_[a] : order_ * e[a];
  return e;
}

int BoxPartition::owner(const std::array<Index, 3>& point) const {
  std::array<int, 3> b{};
  for (std::size_t a = 0; a < 3; ++a) {
    // The last block whose first point is at or below the point's.
    const Index cube = std::min(point[a] / order_, cubes_[a] - 1);
    int t = static_cast<int>(cube * grid_[a] / cubes_[a]);  // a first guess, then corrected
    while (t + 1 < grid_[a] && order_ * cube_start(a, t + 1) <= point[a]) ++t;
    while (t > 0 && order_ * cube_start(a, t) > point[a]) --t;
    b[a] = t;
  }
  return b[0] + grid_[0] * (b[1] + grid_[1] * b[2]);
}

std::array<Index, 3> BoxPartition::point(Index v) const {
  return {v % points_[0], (v / points_[0]) % points_[1], v / (points_[0] * points_[1])};
}

}  // namespace signorini

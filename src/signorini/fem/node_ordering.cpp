#include "signorini/fem/node_ordering.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>

namespace signorini {

namespace {

// The 21 low bits of v spread to every third bit (bit i to bit 3 i).
std::uint64_t spread_by_three(std::uint64_t v) {
  v &= 0x1fffffULL;
  v = (v | (v << 32)) & 0x1f00000000ffffULL;
  v = (v | (v << 16)) & 0x1f0000ff0000ffULL;
  v = (v | (v << 8)) & 0x100f00f00f00f00fULL;
  v = (v | (v << 4)) & 0x10c30c30c30c30c3ULL;
  v = (v | (v << 2)) & 0x1249249249249249ULL;
  return v;
}

}  // namespace

std::vector<Index> z_order(const Mesh& mesh) {
  const Index n = mesh.num_nodes();
  std::vector<Index> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), Index{0});
  if (n == 0) return order;
  Point lo = mesh.point(0), hi = lo;
  for (Index i = 1; i < n; ++i) {
    lo = lo.cwiseMin(mesh.point(i));
    hi = hi.cwiseMax(mesh.point(i));
  }
  constexpr double kCells = 2097151.0;  // 2^21 - 1
  std::vector<std::uint64_t> key(static_cast<std::size_t>(n));
  for (Index i = 0; i < n; ++i) {
    const Point x = mesh.point(i);
    std::uint64_t k = 0;
    for (int d = 0; d < 3; ++d) {
      const double extent = hi(d) - lo(d);
      const double t = extent > 0.0 ? (x(d) - lo(d)) / extent : 0.0;
      k |= spread_by_three(static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * kCells)) << d;
    }
    key[static_cast<std::size_t>(i)] = k;
  }
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) {
    return key[static_cast<std::size_t>(a)] < key[static_cast<std::size_t>(b)];
  });
  return order;
}

}  // namespace signorini

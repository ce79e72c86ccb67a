// The nodal stresses (fem/nodal_stress.hpp) on several threads: each thread sums at its own
// nodes, so any number of threads gives one thread's stresses to the bit.

#include "signorini/fem/nodal_stress.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <utility>

#include "fem/threaded_boxes.hpp"

namespace signorini {
namespace {

TEST(NodalStress, AnyNumberOfThreadsGivesTheSameStressesToTheBit) {
  // 24,576 tetrahedra and 21,952 hexahedra: above the 20,000 cells where the threads start.
  for (const auto& [cell, n] :
       {std::pair{CellType::Tet4, Index{16}}, std::pair{CellType::Hex8, Index{28}}}) {
    const Mesh mesh = testing::moved_box(cell, n, n, n, true);
    ASSERT_GE(mesh.num_cells(), 20000);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> value(-1e-3, 1e-3);
    Vector u(3 * mesh.num_nodes());
    for (Index i = 0; i < u.size(); ++i) u(i) = value(random);
    const ElasticityOptions options;
    const NodalStress one = testing::on_threads(1, [&] { return nodal_stress(mesh, options, u); });
    EXPECT_GT(one.von_mises.maxCoeff(), 0.0);
    for (const int threads : {2, 3}) {
      const NodalStress many =
          testing::on_threads(threads, [&] { return nodal_stress(mesh, options, u); });
      ASSERT_EQ(many.sigma.size(), one.sigma.size());
      EXPECT_EQ(std::memcmp(many.sigma.data(), one.sigma.data(),
                            sizeof(double) * static_cast<std::size_t>(one.sigma.size())),
                0)
          << threads;
      EXPECT_EQ(std::memcmp(many.von_mises.data(), one.von_mises.data(),
                            sizeof(double) * static_cast<std::size_t>(one.von_mises.size())),
                0)
          << threads;
    }
  }
}

}  // namespace
}  // namespace signorini

// The numbering of the unknowns (fem/dof_map.hpp): a full displacement expanded from all the
// free values, or from a rank's part of them (a distributed run's part of the mesh,
// ContactProblem::solution_unknowns), with a prescribed value and a node with its own axes.

#include "signorini/fem/dof_map.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "signorini/core/error.hpp"

namespace signorini {
namespace {

// Four 2D nodes: node 0 clamped in x, node 1 prescribed u_y = 0.25, node 3 with axes turned by
// 30 degrees and held along its first axis.
DofMap four_nodes() {
  DofMap dofs(4, 2);
  dofs.clamp(0, 0);
  dofs.prescribe(1, 1, 0.25);
  const double c = std::cos(M_PI / 6.0), s = std::sin(M_PI / 6.0);
  Eigen::Matrix2d Q;
  Q << c, -s, s, c;
  dofs.set_frame(3, Q);
  dofs.clamp(3, 0);
  dofs.finalize();
  return dofs;
}

TEST(DofMap, ExpandsAPartOfTheFreeValuesAsTheWhole) {
  const DofMap dofs = four_nodes();
  ASSERT_EQ(dofs.num_free(), 5);
  const Vector free_values = Vector::LinSpaced(5, 1.0, 5.0);
  const Vector scales = Vector::Constant(dofs.num_dofs(), 2.0);
  const Vector whole = dofs.expand(free_values, scales);
  EXPECT_DOUBLE_EQ(whole(3), 0.5);  // node 1's prescribed u_y, scaled
  // The same values, held at other places (here in reverse order) and found by a lookup.
  std::vector<Index> held = {4, 3, 2, 1, 0};
  Vector values(5);
  for (Index k = 0; k < 5; ++k) values(k) = free_values(held[static_cast<std::size_t>(k)]);
  const auto place = [&](Index f) {
    return static_cast<Index>(std::find(held.begin(), held.end(), f) - held.begin());
  };
  EXPECT_EQ(dofs.expand(values, scales, place), whole);
  // A free dof without a value is an error, not a zero.
  const auto missing = [&](Index f) { return f == 2 ? Index{-1} : place(f); };
  EXPECT_THROW((void)dofs.expand(values, scales, missing), InputError);
}

}  // namespace
}  // namespace signorini

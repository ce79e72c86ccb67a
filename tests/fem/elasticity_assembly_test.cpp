// The stiffness assembly (fem/elasticity_assembly.hpp): require_valid_cells finds an inverted
// cell without assembling, with the assembly's own message; the assembly in parallel gives the
// one-thread matrix to the bit, and the one-thread message for the first bad cell.

#include "signorini/fem/elasticity_assembly.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <numeric>
#include <stdexcept>
#include <tuple>

#include "fem/threaded_boxes.hpp"
#include "signorini/core/error.hpp"
#include "signorini/problem/model.hpp"

namespace signorini {
namespace {

// Two unit squares side by side; the second numbered clockwise when `inverted`.
Mesh two_squares(bool inverted) {
  Eigen::MatrixXd x(2, 6);
  x << 0, 1, 2, 0, 1, 2,  //
      0, 0, 0, 1, 1, 1;
  std::vector<Index> cells = {0, 1, 4, 3, 1, 2, 5, 4};
  if (inverted) std::swap(cells[5], cells[7]);
  return Mesh({CellType::Quad4, CellType::Quad4}, x, cells);
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(RequireValidCells, FindsTheInvertedCellAsTheAssemblyDoes) {
  ElasticityOptions options;
  EXPECT_NO_THROW(require_valid_cells(two_squares(false), options));
  const Mesh bad = two_squares(true);
  const DofMap dofs = make_dof_map(bad, {});
  const std::string checked = message_of([&] { require_valid_cells(bad, options); });
  const std::string assembled = message_of([&] { (void)assemble_stiffness(bad, dofs, options); });
  EXPECT_NE(checked.find("mesh cell 1 (quad4, nodes 1 4 5 2): inverted or degenerate quad4"),
            std::string::npos)
      << checked;
  EXPECT_EQ(checked, assembled);
}

SparseMatrix assembled_on(int threads, const Mesh& mesh, const DofMap& dofs,
                          const std::vector<bool>* columns_of = nullptr) {
  return testing::on_threads(
      threads, [&] { return assemble_stiffness(mesh, dofs, ElasticityOptions{}, columns_of); });
}

void expect_same_bits(const SparseMatrix& a, const SparseMatrix& b) {
  ASSERT_EQ(a.rows(), b.rows());
  ASSERT_EQ(a.cols(), b.cols());
  ASSERT_EQ(a.nonZeros(), b.nonZeros());
  const auto n = static_cast<std::size_t>(a.nonZeros());
  EXPECT_TRUE(std::equal(a.outerIndexPtr(), a.outerIndexPtr() + a.cols() + 1, b.outerIndexPtr()));
  EXPECT_TRUE(std::equal(a.innerIndexPtr(), a.innerIndexPtr() + n, b.innerIndexPtr()));
  EXPECT_EQ(std::memcmp(a.valuePtr(), b.valuePtr(), n * sizeof(double)), 0);
}

// Above 20,000 cells the assembly runs on the machine's threads, each filling the columns of its
// share of the nodes: every thread count gives the one-thread matrix to the bit, for cells that
// share their element matrix (a structured box) and for cells that are all different, whole or
// with only some nodes' columns (a distributed run's part).
TEST(StiffnessAssembly, AnyNumberOfThreadsGivesTheSameMatrixToTheBit) {
  for (const auto& [cell, nx, jitter] :
       {std::tuple{CellType::Tet4, Index{16}, true}, std::tuple{CellType::Hex8, Index{28}, false},
        std::tuple{CellType::Hex8, Index{28}, true}}) {
    SCOPED_TRACE(std::string(enum_to_string(kCellTypeNames, cell)) + (jitter ? " moved" : ""));
    const Mesh mesh = testing::moved_box(cell, nx, nx, nx, jitter);
    ASSERT_GE(mesh.num_cells(), 20000);
    const DofMap dofs = testing::clamped_in_z_order(mesh);
    const SparseMatrix one = assembled_on(1, mesh, dofs);
    EXPECT_GT(one.nonZeros(), 0);
    for (const int threads : {2, 3}) expect_same_bits(one, assembled_on(threads, mesh, dofs));
    // The same numbering given whole, as a part of a distributed run gets it (DofMap::part: the
    // nodes' places are their first free numbers, the clamped nodes after all).
    std::vector<Index> all(static_cast<std::size_t>(mesh.num_nodes()));
    std::iota(all.begin(), all.end(), Index{0});
    const DofMap given = dofs.part(all);
    for (const int threads : {1, 2, 3}) expect_same_bits(one, assembled_on(threads, mesh, given));
    // The columns of the nodes of the first half of the numbering (a rank's range), held alone:
    // column k of the part is unknown k's (lo = 0 here).
    std::vector<bool> half(static_cast<std::size_t>(mesh.num_nodes()));
    Index held = 0;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      const Index first = dofs.free_index(v, 0);
      half[static_cast<std::size_t>(v)] = first >= 0 && first < dofs.num_free() / 2;
      for (int k = 0; k < 3; ++k)
        if (half[static_cast<std::size_t>(v)] && dofs.free_index(v, k) >= 0) ++held;
    }
    const SparseMatrix part = assembled_on(1, mesh, dofs, &half);
    ASSERT_EQ(part.rows(), dofs.num_free());
    ASSERT_EQ(part.cols(), held);
    expect_same_bits(part, assembled_on(2, mesh, dofs, &half));
    // The part's columns are the whole matrix's.
    for (Index col = 0; col < held; col += 97)
      EXPECT_EQ((part.col(col) - one.col(col)).norm(), 0.0);
  }
}

TEST(StiffnessAssembly, TheColumnsOfSomeNodesAreHeldAlone) {
  const Mesh mesh = testing::moved_box(CellType::Hex8, 6, 5, 4, true);
  const DofMap dofs = testing::clamped_in_z_order(mesh);
  const SparseMatrix whole = assembled_on(1, mesh, dofs);
  // The nodes whose free dofs are [lo, hi), a middle range: an n x (hi - lo) matrix whose column
  // k is the whole matrix's column lo + k.
  // (Nodes whose first free dof lies in the middle third: their dofs are [lo, hi).)
  const Index third = dofs.num_free() / 3;
  std::vector<bool> middle(static_cast<std::size_t>(mesh.num_nodes()), false);
  Index lo = dofs.num_free(), hi = 0;
  for (Index v = 0; v < mesh.num_nodes(); ++v) {
    Index first = -1, last = -1;
    for (int k = 0; k < 3; ++k)
      if (const Index f = dofs.free_index(v, k); f >= 0) {
        if (first < 0) first = f;
        last = f;
      }
    if (first >= third && first < 2 * third) {
      middle[static_cast<std::size_t>(v)] = true;
      lo = std::min(lo, first);
      hi = std::max(hi, last + 1);
    }
  }
  ASSERT_LT(lo, hi);
  const SparseMatrix part = assembled_on(1, mesh, dofs, &middle);
  ASSERT_EQ(part.rows(), dofs.num_free());
  ASSERT_EQ(part.cols(), hi - lo);
  EXPECT_EQ(Matrix(part), Matrix(whole.middleCols(lo, hi - lo)));
  // Nodes whose free dofs leave a gap are refused (a rank's unknowns are one range).
  std::vector<bool> gap(static_cast<std::size_t>(mesh.num_nodes()), false);
  Index flagged = 0;
  for (Index v = 0; v < mesh.num_nodes() && flagged < 2; ++v)
    if (const Index f = dofs.free_index(v, 0); f == 0 || f == hi) {
      gap[static_cast<std::size_t>(v)] = true;
      ++flagged;
    }
  ASSERT_EQ(flagged, 2);
  EXPECT_THROW((void)assembled_on(1, mesh, dofs, &gap), std::logic_error);
}

// Two inverted cells, far apart in the mesh (and so in different threads' shares): every thread
// count names the first, as one thread does, in the assembly and in the cell checks.
TEST(StiffnessAssembly, InParallelTheFirstBadCellIsNamed) {
  const Mesh good = testing::moved_box(CellType::Hex8, 28, 28, 28, false);
  std::vector<Index> cells = testing::connectivity_of(good);
  for (const Index c : {Index{20000}, Index{300}})  // (swap two nodes of each: inverted)
    std::swap(cells[static_cast<std::size_t>(8 * c + 1)],
              cells[static_cast<std::size_t>(8 * c + 3)]);
  const Mesh bad(CellType::Hex8, good.coordinates(), cells);
  const DofMap dofs = testing::clamped_in_z_order(bad);
  const std::string one = message_of([&] { (void)assembled_on(1, bad, dofs); });
  EXPECT_NE(one.find("mesh cell 300 "), std::string::npos) << one;
  for (const int threads : {2, 4})
    EXPECT_EQ(message_of([&] { (void)assembled_on(threads, bad, dofs); }), one) << threads;
  // The cell checks before the assembly, in parallel too, say the same.
  for (const int threads : {1, 2, 4})
    EXPECT_EQ(message_of([&] {
                testing::on_threads(threads, [&] {
                  require_valid_cells(bad, ElasticityOptions{});
                  return 0;
                });
              }),
              one)
        << threads;
}

}  // namespace
}  // namespace signorini

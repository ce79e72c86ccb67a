// The stiffness assembly (fem/elasticity_assembly.hpp): require_valid_cells finds an inverted
// cell without assembling, with the assembly's own message; the assembly in parallel gives the
// one-thread matrix to the bit, and the one-thread message for the first bad cell.

#include "signorini/fem/elasticity_assembly.hpp"

#include <gtest/gtest.h>

#include <cstring>
#include <numeric>
#include <random>
#include <tuple>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/core/error.hpp"
#include "signorini/fem/node_ordering.hpp"
#include "signorini/mesh/box_mesh.hpp"
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

std::vector<Index> connectivity_of(const Mesh& mesh) {
  std::vector<Index> cells;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const Index a : mesh.cell(c)) cells.push_back(a);
  return cells;
}

// A box of cells, its inner nodes moved by up to a tenth of a cell (`jitter`: no two cells
// alike, as on a mesh from a generator), clamped at x = 0.
Mesh box(CellType cell, Index nx, Index ny, Index nz, bool jitter) {
  BoxMeshOptions o;
  o.nx = nx;
  o.ny = ny;
  o.nz = nz;
  o.cell = cell;
  Mesh mesh = make_box_mesh(o);
  if (!jitter) return mesh;
  const CellType type = mesh.cell_type(0);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> shift(-0.1, 0.1);
  Eigen::MatrixXd x = mesh.coordinates();
  for (Index v = 0; v < x.cols(); ++v) {
    const bool inner = (x.col(v).array() > 1e-9).all() && (x.col(v).array() < 1.0 - 1e-9).all();
    if (!inner) continue;
    x(0, v) += shift(random) / static_cast<double>(nx);
    x(1, v) += shift(random) / static_cast<double>(ny);
    x(2, v) += shift(random) / static_cast<double>(nz);
  }
  return Mesh(type, x, connectivity_of(mesh));
}

// The numbering of `mesh` in Z-order (as for a mesh read from a file) with the nodes at x = 0
// clamped.
DofMap clamped_in_z_order(const Mesh& mesh) {
  DofMap dofs(mesh.num_nodes(), mesh.dim());
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    if (mesh.node(v)(0) < 1e-12)
      for (int k = 0; k < mesh.dim(); ++k) dofs.clamp(v, k);
  dofs.finalize(z_order(mesh));
  return dofs;
}

SparseMatrix assembled_on(int threads, const Mesh& mesh, const DofMap& dofs,
                          const std::vector<bool>* columns_of = nullptr) {
#ifdef _OPENMP
  const int saved = omp_get_max_threads();
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  SparseMatrix A;
  try {
    A = assemble_stiffness(mesh, dofs, ElasticityOptions{}, columns_of);
  } catch (...) {
#ifdef _OPENMP
    omp_set_num_threads(saved);
#endif
    throw;
  }
#ifdef _OPENMP
  omp_set_num_threads(saved);
#endif
  return A;
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
    const Mesh mesh = box(cell, nx, nx, nx, jitter);
    ASSERT_GE(mesh.num_cells(), 20000);
    const DofMap dofs = clamped_in_z_order(mesh);
    const SparseMatrix one = assembled_on(1, mesh, dofs);
    EXPECT_GT(one.nonZeros(), 0);
    for (const int threads : {2, 3}) expect_same_bits(one, assembled_on(threads, mesh, dofs));
    // The same numbering given whole, as a part of a distributed run gets it (DofMap::part: the
    // nodes' places are their first free numbers, the clamped nodes after all).
    std::vector<Index> all(static_cast<std::size_t>(mesh.num_nodes()));
    std::iota(all.begin(), all.end(), Index{0});
    const DofMap given = dofs.part(all);
    for (const int threads : {1, 2, 3}) expect_same_bits(one, assembled_on(threads, mesh, given));
    std::vector<bool> half(static_cast<std::size_t>(mesh.num_nodes()));
    for (Index v = 0; v < mesh.num_nodes(); ++v)
      half[static_cast<std::size_t>(v)] = mesh.node(v)(1) < 0.5;
    const SparseMatrix part = assembled_on(1, mesh, dofs, &half);
    expect_same_bits(part, assembled_on(2, mesh, dofs, &half));
    // The part's columns are the whole matrix's.
    for (Index v = 0; v < mesh.num_nodes(); v += 97)
      for (int k = 0; k < 3; ++k)
        if (const Index col = dofs.free_index(v, k);
            col >= 0 && half[static_cast<std::size_t>(v)]) {
          EXPECT_EQ((part.col(col) - one.col(col)).norm(), 0.0) << v;
        }
  }
}

// Two inverted cells, far apart in the mesh (and so in different threads' shares): every thread
// count names the first, as one thread does, in the assembly and in the cell checks.
TEST(StiffnessAssembly, InParallelTheFirstBadCellIsNamed) {
  const Mesh good = box(CellType::Hex8, 28, 28, 28, false);
  std::vector<Index> cells = connectivity_of(good);
  for (const Index c : {Index{20000}, Index{300}})  // (swap two nodes of each: inverted)
    std::swap(cells[static_cast<std::size_t>(8 * c + 1)],
              cells[static_cast<std::size_t>(8 * c + 3)]);
  const Mesh bad(CellType::Hex8, good.coordinates(), cells);
  const DofMap dofs = clamped_in_z_order(bad);
  const std::string one = message_of([&] { (void)assembled_on(1, bad, dofs); });
  EXPECT_NE(one.find("mesh cell 300 "), std::string::npos) << one;
  for (const int threads : {2, 4})
    EXPECT_EQ(message_of([&] { (void)assembled_on(threads, bad, dofs); }), one) << threads;
  // The cell checks before the assembly, in parallel too, say the same.
  for (const int threads : {1, 2, 4}) {
#ifdef _OPENMP
    const int saved = omp_get_max_threads();
    omp_set_num_threads(threads);
#endif
    EXPECT_EQ(message_of([&] { require_valid_cells(bad, ElasticityOptions{}); }), one) << threads;
#ifdef _OPENMP
    omp_set_num_threads(saved);
#endif
  }
}

}  // namespace
}  // namespace signorini

#include "signorini/fem/elasticity_assembly.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

#include "signorini/core/error.hpp"
#include "signorini/fem/cell_threads.hpp"
#include "signorini/fem/elasticity_matrices.hpp"
#include "signorini/fem/isoparametric_element.hpp"
#include "signorini/fem/sparsity_pattern.hpp"

namespace signorini {

namespace {

// "mesh cell 12 (quad4, nodes 3 4 9 8)": how errors name a cell.
std::string cell_name(const Mesh& mesh, Index c) {
  std::string s = "mesh cell " + std::to_string(c) + " (";
  if (mesh.cell_source_tag(c) >= 0)
    s += "element " + std::to_string(mesh.cell_source_tag(c)) + " of the mesh file, ";
  s += std::string(enum_to_string(kCellTypeNames, mesh.cell_type(c))) + ", nodes";
  for (const Index n : mesh.cell(c)) s += " " + std::to_string(n);
  return s + ")";
}

}  // namespace

const IsotropicMaterial& material_of_region(const ElasticityOptions& options, int region) {
  const auto r = static_cast<std::size_t>(region);
  if (r < options.region_materials.size() && options.region_materials[r])
    return *options.region_materials[r];
  return options.material;
}

void require_supported_cells(const Mesh& mesh) {
  if (mesh.dim() != 2 && mesh.dim() != 3)
    throw InputError("a mesh of dimension " + std::to_string(mesh.dim()) +
                     ": expected a 2D or a 3D mesh");
  for (const CellType t : mesh.cell_types()) {
    require_finite_element(t);
    if (cell_dimension(t) != mesh.dim())
      throw InputError(std::string("a ") + std::string(enum_to_string(kCellTypeNames, t)) +
                       " cell in a " + std::to_string(mesh.dim()) +
                       "D mesh: expected cells of the mesh's dimension");
  }
}

namespace {

// The first bad cell's message where threads each meet their own failures: the lowest cell's,
// the one a single thread would have met first.
class FirstBadCell {
 public:
  void note(const Mesh& mesh, Index c, const char* what) {
#pragma omp critical(signorini_first_bad_cell)
    if (c < cell_) {
      cell_ = c;
      message_ = cell_name(mesh, c) + ": " + what;
    }
  }
  void rethrow() const {
    if (!message_.empty()) throw InputError(message_);
  }

 private:
  Index cell_ = std::numeric_limits<Index>::max();
  std::string message_;
};

template <int Dim>
SparseMatrix assemble(const Mesh& mesh, const DofMap& dofs, const ElasticityOptions& options,
                      const std::vector<bool>* columns_of) {
  const std::vector<ElasticityMatrixOf<Dim>> D = region_elasticity_matrices<Dim>(mesh, options);
  SparsityPattern pattern(mesh, dofs, columns_of);
  SparseMatrix A = pattern.take_zero_matrix();
  double* values = A.valuePtr();
  // In parallel by columns: thread t fills the columns of the nodes whose places in the
  // numbering (DofMap::node_place) fall in its t-th share, from every cell that touches one of
  // them, so no two threads write one entry, and each entry sums its cells' terms in the cells'
  // order as one thread would: the same matrix to the bit whatever the number of threads. A cell
  // across shares is integrated by each of their threads (few: the places follow the
  // numbering's order through space).
  const int threads = cell_loop_threads(mesh.num_cells());
  const Index nodes = mesh.num_nodes();
  // The shares split the range of places of the nodes with a filled column evenly (a part of a
  // distributed run numbers its nodes by their free numbers in the whole problem, and the nodes
  // without a free dof come after every other: DofMap::node_place); -1: no filled column.
  std::vector<int> thread_of;
  if (threads > 1) {
    thread_of.assign(static_cast<std::size_t>(nodes), -1);
    Index low = std::numeric_limits<Index>::max(), high = -1;
    for (Index m = 0; m < nodes; ++m) {
      const bool column = columns_of == nullptr || (*columns_of)[static_cast<std::size_t>(m)];
      bool free = false;
      for (int k = 0; k < Dim; ++k) free = free || dofs.free_index(m, k) >= 0;
      if (!column || !free) continue;
      thread_of[static_cast<std::size_t>(m)] = 0;  // (a share below)
      low = std::min(low, dofs.node_place(m));
      high = std::max(high, dofs.node_place(m));
    }
    for (Index m = 0; m < nodes; ++m)
      if (int& t = thread_of[static_cast<std::size_t>(m)]; t >= 0)
        t = share_of(dofs.node_place(m) - low, high - low + 1, threads);
  }
  // Whether thread t fills node m's columns (one thread fills them all).
  const auto mine = [&](Index m, int t) {
    return threads == 1 || thread_of[static_cast<std::size_t>(m)] == t;
  };
  // Cells of the type of the previous one that are its translates (all of them on a structured
  // mesh) share its element matrix: compare the node coordinates relative to the first node.
  // Decided here, in the cells' order, once for all threads: source[c] is the cell whose element
  // matrix cell c takes (-1: a cell with no filled column), so that every thread computes each
  // element matrix from the same cell, and gets the same bits, as one thread would.
  // (Four bytes a cell: the cells of a matrix of at most 2^31 entries are numbered in an int.)
  if (mesh.num_cells() > std::numeric_limits<int>::max())
    throw InputError("mesh too large: more than 2^31 cells");
  std::vector<int> source(static_cast<std::size_t>(mesh.num_cells()), -1);
  {
    int last = -1;
    CellCoordinatesOf<Dim> previous = CellCoordinatesOf<Dim>::Zero(Dim, 0);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      bool touches = false;  // only the cells that touch a kept node
      for (const Index a : mesh.cell(c))
        touches = touches || columns_of == nullptr || (*columns_of)[static_cast<std::size_t>(a)];
      if (!touches) continue;
      const CellCoordinatesOf<Dim> X = cell_coordinates<Dim>(mesh, c);
      const CellCoordinatesOf<Dim> relative = X.colwise() - X.col(0);
      bool same = last >= 0 && mesh.cell_type(c) == mesh.cell_type(last) &&
                  mesh.cell_region(c) == mesh.cell_region(last);
      if (same) {
        double size = 0.0, change = 0.0;
        for (Index a = 0; a < relative.cols(); ++a) {
          size = std::max(size, relative.col(a).cwiseAbs().maxCoeff());
          change = std::max(change, (relative.col(a) - previous.col(a)).cwiseAbs().maxCoeff());
        }
        same = change <= 1e-13 * size;
      }
      if (!same) {
        last = static_cast<int>(c);
        previous = relative;
      }
      source[static_cast<std::size_t>(c)] = last;
    }
  }
  FirstBadCell failure;  // (each thread stops at its first)
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    const int t = thread_number();
    CellRules rules(options.gauss_points);  // (fills itself in: one per thread)
    ElementMatrixOf<Dim> K;
    ElementMatrixOf<Dim> rotated;
    Index computed = -1;  // K is the element matrix of this cell
    std::array<Index, Dim * Dim> block{};
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const Index from = source[static_cast<std::size_t>(c)];
      if (from < 0) continue;
      const auto nodes_of = mesh.cell(c);
      if (threads > 1) {  // only the cells with a column of this thread's
        bool touches = false;
        for (const Index a : nodes_of) touches = touches || mine(a, t);
        if (!touches) continue;
      }
      if (from != computed) {
        const CellType type = mesh.cell_type(from);
        try {
          K = element_stiffness<Dim>(type, cell_coordinates<Dim>(mesh, from),
                                     D[static_cast<std::size_t>(mesh.cell_region(from))],
                                     rules(type));
        } catch (const InputError& e) {
          failure.note(mesh, from, e.what());
          break;
        }
        computed = from;
      }
      const auto n = static_cast<int>(nodes_of.size());
      // Nodes with local axes (DofMap::set_frame, 2D): R^T K R, R the block diagonal of their
      // axes, on a copy (K may serve the next cell too).
      const ElementMatrixOf<Dim>* Kc = &K;
      if constexpr (Dim == 2) {
        if (dofs.has_frames()) {
          for (int a = 0; a < n; ++a) {
            const Index node = nodes_of[static_cast<std::size_t>(a)];
            if (!dofs.has_frame(node)) continue;
            if (Kc == &K) {
              rotated = K;
              Kc = &rotated;
            }
            const Eigen::Matrix2d Q = dofs.frame(node);
            rotated.middleRows(2 * a, 2) = (Q.transpose() * rotated.middleRows(2 * a, 2)).eval();
            rotated.middleCols(2 * a, 2) = (rotated.middleCols(2 * a, 2) * Q).eval();
          }
        }
      }
      for (int b = 0; b < n; ++b) {
        const Index node_b = nodes_of[static_cast<std::size_t>(b)];
        if (!mine(node_b, t)) continue;
        for (int a = 0; a < n; ++a) {
          pattern.block_positions(nodes_of[static_cast<std::size_t>(a)], node_b, block.data());
          for (int ka = 0; ka < Dim; ++ka)
            for (int kb = 0; kb < Dim; ++kb) {
              const Index pos = block[static_cast<std::size_t>(ka * Dim + kb)];
              if (pos >= 0)
                values[pos] += (*Kc)(Dim * a + ka, Dim * b + kb);  // clamped: eliminated
            }
        }
      }
    }
  }
  failure.rethrow();
  return A;
}

template <int Dim>
Vector internal_forces_of(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                          const std::function<bool(Index)>& needed) {
  const std::vector<ElasticityMatrixOf<Dim>> D = region_elasticity_matrices<Dim>(mesh, options);
  CellRules rules(options.gauss_points);
  Vector f = Vector::Zero(u.size());
  ElementVectorOf<Dim> ue;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (needed && !needed(c)) continue;
    const CellType type = mesh.cell_type(c);
    const auto nodes = mesh.cell(c);
    const auto n = static_cast<Index>(nodes.size());
    ue.resize(Dim * n);
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < Dim; ++k)
        ue(Dim * a + k) = u(nodes[static_cast<std::size_t>(a)] * Dim + k);
    const ElementVectorOf<Dim> fe =
        element_stiffness<Dim>(type, cell_coordinates<Dim>(mesh, c),
                               D[static_cast<std::size_t>(mesh.cell_region(c))], rules(type)) *
        ue;
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < Dim; ++k)
        f(nodes[static_cast<std::size_t>(a)] * Dim + k) += fe(Dim * a + k);
  }
  return f;
}

}  // namespace

namespace {

template <int Dim>
void check_cells(const Mesh& mesh, const ElasticityOptions& options) {
  // In parallel over the cells; the message is the first bad cell's, as one thread finds it.
  const int threads = cell_loop_threads(mesh.num_cells());
  FirstBadCell failure;
#pragma omp parallel num_threads(threads) if (threads > 1)
  {
    CellRules rules(options.gauss_points);  // (fills itself in: one per thread)
#pragma omp for schedule(static)
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const CellType type = mesh.cell_type(c);
      const CellCoordinatesOf<Dim> X = cell_coordinates<Dim>(mesh, c);
      try {
        check_cell_geometry<Dim>(type, X);
        for (const QuadraturePoint& q : rules(type))
          if (const double det_j = cell_jacobian<Dim>(type, X, q.xi).determinant(); !(det_j > 0.0))
            throw InputError("inverted or degenerate " +
                             std::string(enum_to_string(kCellTypeNames, type)) +
                             " (det J = " + std::to_string(det_j) + " at a quadrature point)");
      } catch (const InputError& e) {
        failure.note(mesh, c, e.what());
      }
    }
  }
  failure.rethrow();
}

}  // namespace

void require_valid_cells(const Mesh& mesh, const ElasticityOptions& options) {
  require_supported_cells(mesh);
  if (mesh.dim() == 2)
    check_cells<2>(mesh, options);
  else
    check_cells<3>(mesh, options);
}

namespace {

// The free dofs [lo, hi) of the flagged nodes, which must be consecutive.
std::pair<Index, Index> flagged_dofs(const DofMap& dofs, const std::vector<bool>& flags) {
  Index lo = dofs.num_free(), hi = 0, count = 0;
  for (Index v = 0; v < dofs.num_nodes(); ++v) {
    if (!flags[static_cast<std::size_t>(v)]) continue;
    for (int k = 0; k < dofs.dim(); ++k)
      if (const Index f = dofs.free_index(v, k); f >= 0) {
        lo = std::min(lo, f);
        hi = std::max(hi, f + 1);
        ++count;
      }
  }
  if (count == 0) return {0, 0};
  if (hi - lo != count)
    throw std::logic_error("assemble_stiffness: the flagged nodes' free dofs are not consecutive");
  return {lo, hi};
}

// A whose columns outside [lo, hi) are empty as the n x (hi - lo) matrix of the others, in
// place: the column pointers moved down and their array shortened, the entries untouched.
void keep_columns(SparseMatrix& A, Index lo, Index hi) {
  A.makeCompressed();
  int* outer = A.outerIndexPtr();
  if (outer[lo] != 0 || outer[hi] != A.nonZeros())
    throw std::logic_error("assemble_stiffness: entries outside the flagged nodes' columns");
  std::copy(outer + lo, outer + hi + 1, outer);
  A.conservativeResize(A.rows(), hi - lo);  // (keeps the entries; the pointers' array shrinks)
}

}  // namespace

SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options,
                                const std::vector<bool>* columns_of) {
  require_supported_cells(mesh);
  if (dofs.dim() != mesh.dim())
    throw std::logic_error("assemble_stiffness: the dof map has another dimension than the mesh");
  if (columns_of != nullptr && static_cast<Index>(columns_of->size()) != mesh.num_nodes())
    throw InputError("assemble_stiffness: one flag per node expected");
  SparseMatrix A = mesh.dim() == 2 ? assemble<2>(mesh, dofs, options, columns_of)
                                   : assemble<3>(mesh, dofs, options, columns_of);
  if (columns_of != nullptr) {
    // Only the flagged nodes' columns are held: no array of all n columns (its pointers, 4
    // bytes per unknown on every rank of a distributed run; docs/distributed.md).
    const auto [lo, hi] = flagged_dofs(dofs, *columns_of);
    keep_columns(A, lo, hi);
  }
  return A;
}

Vector internal_forces(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                       const std::function<bool(Index)>& needed) {
  require_supported_cells(mesh);
  return mesh.dim() == 2 ? internal_forces_of<2>(mesh, options, u, needed)
                         : internal_forces_of<3>(mesh, options, u, needed);
}

}  // namespace signorini

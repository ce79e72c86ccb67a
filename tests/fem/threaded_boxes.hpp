#pragma once
// Test meshes and helpers for the code that runs on several threads (the assembly, the nodal
// stresses): boxes whose cells all differ, as a generator's, numbered in Z-order, and a call
// made on a given number of OpenMP threads.

#include <random>
#include <vector>
#ifdef _OPENMP
#include <omp.h>
#endif

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/node_ordering.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini::testing {

inline std::vector<Index> connectivity_of(const Mesh& mesh) {
  std::vector<Index> cells;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (const Index a : mesh.cell(c)) cells.push_back(a);
  return cells;
}

// A unit box of cells, its inner nodes moved by up to a tenth of a cell where `jitter` (no two
// cells alike, as on a mesh from a generator).
inline Mesh moved_box(CellType cell, Index nx, Index ny, Index nz, bool jitter) {
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
inline DofMap clamped_in_z_order(const Mesh& mesh) {
  DofMap dofs(mesh.num_nodes(), mesh.dim());
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    if (mesh.node(v)(0) < 1e-12)
      for (int k = 0; k < mesh.dim(); ++k) dofs.clamp(v, k);
  dofs.finalize(z_order(mesh));
  return dofs;
}

// f() with `threads` OpenMP threads (the setting restored after, also on an exception).
template <class F>
auto on_threads(int threads, const F& f) {
#ifdef _OPENMP
  struct Restore {
    int saved = omp_get_max_threads();
    ~Restore() { omp_set_num_threads(saved); }
  } restore;
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  return f();
}

}  // namespace signorini::testing

#include "signorini/problem/rectangle_hierarchy.hpp"

#include <array>
#include <optional>
#include <utility>

#include "signorini/problem/model.hpp"

namespace signorini {

namespace {

// Coarse neighbours of fine index i along one axis with their linear interpolation weights.
int coarse_neighbours(Index i, std::array<std::pair<Index, double>, 2>& out) {
  if (i % 2 == 0) {
    out[0] = {i / 2, 1.0};
    return 1;
  }
  out[0] = {(i - 1) / 2, 0.5};
  out[1] = {(i + 1) / 2, 0.5};
  return 2;
}

}  // namespace

std::vector<SparseMatrix> make_rectangle_prolongations(
    const RectangleMeshOptions& mesh, const std::vector<ClampSpec>& clamps, const DofMap& fine_dofs,
    Index min_coarse_unknowns, const std::vector<DisplacementSpec>& displacements) {
  std::vector<SparseMatrix> out;
  RectangleMeshOptions fine = mesh;
  // The current level's numbering: the fine one in place (no copy of the largest map).
  const DofMap* current = &fine_dofs;
  std::optional<DofMap> coarser;  // each coarse level's, once there is one
  while (fine.nx % 2 == 0 && fine.ny % 2 == 0 && current->num_free() > min_coarse_unknowns) {
    const DofMap& fdofs = *current;
    RectangleMeshOptions coarse = fine;
    coarse.nx = fine.nx / 2;
    coarse.ny = fine.ny / 2;
    DofMap cdofs = make_dof_map(make_rectangle_mesh(coarse), clamps, displacements);
    const int dim = fdofs.dim();
    std::vector<Eigen::Triplet<double, int>> entries;
    entries.reserve(static_cast<std::size_t>(fdofs.num_free()) * 9 / 4 + 16);
    std::array<std::pair<Index, double>, 2> wx{}, wy{};
    for (Index j = 0; j <= fine.ny; ++j) {
      const int ny = coarse_neighbours(j, wy);
      for (Index i = 0; i <= fine.nx; ++i) {
        const int nx = coarse_neighbours(i, wx);
        const Index fnode = j * (fine.nx + 1) + i;
        for (int k = 0; k < dim; ++k) {
          const Index f = fdofs.free_index(fnode, k);
          if (f < 0) continue;
          for (int b = 0; b < ny; ++b)
            for (int a = 0; a < nx; ++a) {
              const Index cnode = wy[static_cast<std::size_t>(b)].first * (coarse.nx + 1) +
                                  wx[static_cast<std::size_t>(a)].first;
              const Index c = cdofs.free_index(cnode, k);
              if (c >= 0)
                entries.emplace_back(static_cast<int>(f), static_cast<int>(c),
                                     wx[static_cast<std::size_t>(a)].second *
                                         wy[static_cast<std::size_t>(b)].second);
            }
        }
      }
    }
    SparseMatrix P(fdofs.num_free(), cdofs.num_free());
    P.setFromTriplets(entries.begin(), entries.end());
    out.push_back(std::move(P));
    fine = coarse;
    coarser = std::move(cdofs);  // fdofs (the old *coarser) is not used after this
    current = &*coarser;
  }
  return out;
}

}  // namespace signorini

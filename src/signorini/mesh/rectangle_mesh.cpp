#include "signorini/mesh/rectangle_mesh.hpp"

#include <cmath>

#include "signorini/core/error.hpp"

namespace signorini {

Mesh make_rectangle_mesh(const RectangleMeshOptions& o) {
  if (o.nx < 1 || o.ny < 1)
    throw InputError("rectangle mesh: nx and ny must be >= 1 (got " + std::to_string(o.nx) + " x " +
                     std::to_string(o.ny) + ")");
  if (!(o.length > 0.0) || !(o.height > 0.0) || !std::isfinite(o.length) ||
      !std::isfinite(o.height))
    throw InputError("rectangle mesh: length and height must be positive and finite");
  const Index nxp = o.nx + 1;
  const Index nyp = o.ny + 1;
  Eigen::MatrixXd xy(2, nxp * nyp);
  for (Index j = 0; j < nyp; ++j)
    for (Index i = 0; i < nxp; ++i) {
      // Multiply before dividing so that the far edges land exactly on x0 + length, y0 + height.
      xy(0, j * nxp + i) = o.x0 + o.length * static_cast<double>(i) / static_cast<double>(o.nx);
      xy(1, j * nxp + i) = o.y0 + o.height * static_cast<double>(j) / static_cast<double>(o.ny);
    }
  std::vector<Index> cells;
  cells.reserve(static_cast<std::size_t>(4 * o.nx * o.ny));
  for (Index j = 0; j < o.ny; ++j)
    for (Index i = 0; i < o.nx; ++i) {
      const Index n0 = j * nxp + i;
      cells.insert(cells.end(), {n0, n0 + 1, n0 + 1 + nxp, n0 + nxp});
    }
  Mesh mesh(CellType::Quad4, std::move(xy), std::move(cells));

  std::vector<Facet> bottom, top, left, right;
  for (Index i = 0; i < o.nx; ++i) {
    bottom.push_back({i, 0});
    top.push_back({(o.ny - 1) * o.nx + i, 2});
  }
  for (Index j = 0; j < o.ny; ++j) {
    left.push_back({j * o.nx, 3});
    right.push_back({j * o.nx + o.nx - 1, 1});
  }
  mesh.set_boundary_part("bottom", std::move(bottom));
  mesh.set_boundary_part("top", std::move(top));
  mesh.set_boundary_part("left", std::move(left));
  mesh.set_boundary_part("right", std::move(right));
  return mesh;
}

}  // namespace signorini

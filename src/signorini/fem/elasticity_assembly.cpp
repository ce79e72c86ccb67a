#include "signorini/fem/elasticity_assembly.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "signorini/core/error.hpp"
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

std::vector<Eigen::Matrix3d> region_elasticity_matrices(const Mesh& mesh,
                                                        const ElasticityOptions& options) {
  std::vector<Eigen::Matrix3d> D;
  for (std::size_t r = 0; r < mesh.region_names().size(); ++r)
    D.push_back(plane_elasticity_matrix(material_of_region(options, static_cast<int>(r)),
                                        options.plane_model));
  return D;
}

void require_supported_cells(const Mesh& mesh) {
  if (mesh.dim() != 2)
    throw InputError("finite elements for " + std::to_string(mesh.dim()) +
                     "D meshes are not implemented yet (2D only)");
  for (const CellType t : mesh.cell_types()) require_finite_element(t);
}

SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options) {
  require_supported_cells(mesh);
  const std::vector<Eigen::Matrix3d> D = region_elasticity_matrices(mesh, options);
  const SparsityPattern pattern(mesh, dofs);
  SparseMatrix A = pattern.zero_matrix();
  double* values = A.valuePtr();
  // Cells of the type of the previous one that are its translates (all of them on a structured
  // mesh) share its element matrix: compare the node coordinates relative to the first node.
  CellType previous_type = mesh.num_cells() > 0 ? mesh.cell_type(0) : CellType::Quad4;
  int previous_region = mesh.num_cells() > 0 ? mesh.cell_region(0) : 0;
  CellCoordinates previous = CellCoordinates::Zero(2, 0);
  CellRules rules(options.gauss_points);
  ElementMatrix K;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType type = mesh.cell_type(c);
    const CellCoordinates X = cell_coordinates(mesh, c);
    const CellCoordinates relative = X.colwise() - X.col(0);
    const int region = mesh.cell_region(c);
    bool same = c > 0 && type == previous_type && region == previous_region;
    if (same) {
      double size = 0.0, change = 0.0;
      for (Index a = 0; a < relative.cols(); ++a) {
        size = std::max(size, relative.col(a).cwiseAbs().maxCoeff());
        change = std::max(change, (relative.col(a) - previous.col(a)).cwiseAbs().maxCoeff());
      }
      same = change <= 1e-13 * size;
    }
    if (!same) {
      try {
        K = element_stiffness(type, X, D[static_cast<std::size_t>(region)], rules(type));
      } catch (const InputError& e) {
        throw InputError(cell_name(mesh, c) + ": " + e.what());
      }
      previous = relative;
      previous_type = type;
      previous_region = region;
    }
    const auto nodes = mesh.cell(c);
    const auto n = static_cast<int>(nodes.size());
    // Nodes with local axes (DofMap::set_frame): R^T K R, R the block diagonal of their axes, on
    // a copy (K may serve the next cell too).
    const ElementMatrix* Kc = &K;
    ElementMatrix rotated;
    if (dofs.has_frames()) {
      for (int a = 0; a < n; ++a) {
        const Index node = nodes[static_cast<std::size_t>(a)];
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
    std::array<Index, 4> block{};
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        pattern.block_positions(nodes[static_cast<std::size_t>(a)],
                                nodes[static_cast<std::size_t>(b)], block.data());
        for (int ka = 0; ka < 2; ++ka)
          for (int kb = 0; kb < 2; ++kb) {
            const Index pos = block[static_cast<std::size_t>(ka * 2 + kb)];
            if (pos >= 0) values[pos] += (*Kc)(2 * a + ka, 2 * b + kb);  // clamped: eliminated
          }
      }
  }
  return A;
}

Vector internal_forces(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                       const std::function<bool(Index)>& needed) {
  require_supported_cells(mesh);
  const std::vector<Eigen::Matrix3d> D = region_elasticity_matrices(mesh, options);
  CellRules rules(options.gauss_points);
  Vector f = Vector::Zero(u.size());
  ElementVector ue;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (needed && !needed(c)) continue;
    const CellType type = mesh.cell_type(c);
    const auto nodes = mesh.cell(c);
    const auto n = static_cast<Index>(nodes.size());
    ue.resize(2 * n);
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < 2; ++k) ue(2 * a + k) = u(nodes[static_cast<std::size_t>(a)] * 2 + k);
    const ElementVector fe =
        element_stiffness(type, cell_coordinates(mesh, c),
                          D[static_cast<std::size_t>(mesh.cell_region(c))], rules(type)) *
        ue;
    for (Index a = 0; a < n; ++a)
      for (int k = 0; k < 2; ++k) f(nodes[static_cast<std::size_t>(a)] * 2 + k) += fe(2 * a + k);
  }
  return f;
}

}  // namespace signorini

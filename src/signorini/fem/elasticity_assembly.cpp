#include "signorini/fem/elasticity_assembly.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "signorini/core/error.hpp"
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

template <int Dim>
SparseMatrix assemble(const Mesh& mesh, const DofMap& dofs, const ElasticityOptions& options,
                      const std::vector<bool>* columns_of) {
  const std::vector<ElasticityMatrixOf<Dim>> D = region_elasticity_matrices<Dim>(mesh, options);
  SparsityPattern pattern(mesh, dofs, columns_of);
  SparseMatrix A = pattern.take_zero_matrix();
  double* values = A.valuePtr();
  // Cells of the type of the previous one that are its translates (all of them on a structured
  // mesh) share its element matrix: compare the node coordinates relative to the first node.
  CellType previous_type = mesh.num_cells() > 0 ? mesh.cell_type(0) : CellType::Quad4;
  int previous_region = mesh.num_cells() > 0 ? mesh.cell_region(0) : 0;
  CellCoordinatesOf<Dim> previous = CellCoordinatesOf<Dim>::Zero(Dim, 0);
  CellRules rules(options.gauss_points);
  ElementMatrixOf<Dim> K;
  bool have_previous = false;  // K is the element matrix of `previous`
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (columns_of != nullptr) {  // only the cells that touch a kept node
      bool touches = false;
      for (const Index a : mesh.cell(c))
        touches = touches || (*columns_of)[static_cast<std::size_t>(a)];
      if (!touches) continue;
    }
    const CellType type = mesh.cell_type(c);
    const CellCoordinatesOf<Dim> X = cell_coordinates<Dim>(mesh, c);
    const CellCoordinatesOf<Dim> relative = X.colwise() - X.col(0);
    const int region = mesh.cell_region(c);
    bool same = have_previous && type == previous_type && region == previous_region;
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
        K = element_stiffness<Dim>(type, X, D[static_cast<std::size_t>(region)], rules(type));
      } catch (const InputError& e) {
        throw InputError(cell_name(mesh, c) + ": " + e.what());
      }
      previous = relative;
      previous_type = type;
      previous_region = region;
      have_previous = true;
    }
    const auto nodes = mesh.cell(c);
    const auto n = static_cast<int>(nodes.size());
    // Nodes with local axes (DofMap::set_frame, 2D): R^T K R, R the block diagonal of their
    // axes, on a copy (K may serve the next cell too).
    const ElementMatrixOf<Dim>* Kc = &K;
    ElementMatrixOf<Dim> rotated;
    if constexpr (Dim == 2) {
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
    }
    std::array<Index, Dim * Dim> block{};
    for (int b = 0; b < n; ++b)
      for (int a = 0; a < n; ++a) {
        pattern.block_positions(nodes[static_cast<std::size_t>(a)],
                                nodes[static_cast<std::size_t>(b)], block.data());
        for (int ka = 0; ka < Dim; ++ka)
          for (int kb = 0; kb < Dim; ++kb) {
            const Index pos = block[static_cast<std::size_t>(ka * Dim + kb)];
            if (pos >= 0) values[pos] += (*Kc)(Dim * a + ka, Dim * b + kb);  // clamped: eliminated
          }
      }
  }
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
  CellRules rules(options.gauss_points);
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
      throw InputError(cell_name(mesh, c) + ": " + e.what());
    }
  }
}

}  // namespace

void require_valid_cells(const Mesh& mesh, const ElasticityOptions& options) {
  require_supported_cells(mesh);
  if (mesh.dim() == 2)
    check_cells<2>(mesh, options);
  else
    check_cells<3>(mesh, options);
}

SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options,
                                const std::vector<bool>* columns_of) {
  require_supported_cells(mesh);
  if (dofs.dim() != mesh.dim())
    throw std::logic_error("assemble_stiffness: the dof map has another dimension than the mesh");
  if (columns_of != nullptr && static_cast<Index>(columns_of->size()) != mesh.num_nodes())
    throw InputError("assemble_stiffness: one flag per node expected");
  return mesh.dim() == 2 ? assemble<2>(mesh, dofs, options, columns_of)
                         : assemble<3>(mesh, dofs, options, columns_of);
}

Vector internal_forces(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                       const std::function<bool(Index)>& needed) {
  require_supported_cells(mesh);
  return mesh.dim() == 2 ? internal_forces_of<2>(mesh, options, u, needed)
                         : internal_forces_of<3>(mesh, options, u, needed);
}

}  // namespace signorini

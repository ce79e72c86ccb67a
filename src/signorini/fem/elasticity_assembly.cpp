#include "signorini/fem/elasticity_assembly.hpp"

#include <Eigen/LU>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "signorini/core/error.hpp"
#include "signorini/fem/q1_element.hpp"
#include "signorini/fem/quadrature.hpp"
#include "signorini/fem/sparsity_pattern.hpp"

namespace signorini {

namespace {

void require_quad4(const Mesh& mesh) {
  if (mesh.cell_type() != CellType::Quad4)
    throw InputError("finite elements for cell type '" +
                     std::string(enum_to_string(kCellTypeNames, mesh.cell_type())) +
                     "' are not implemented yet (only quad4)");
}

Q1Coordinates cell_coordinates(const Mesh& mesh, Index c) {
  Q1Coordinates X;
  const auto nodes = mesh.cell(c);
  for (int a = 0; a < 4; ++a) X.col(a) = mesh.node(nodes[static_cast<std::size_t>(a)]);
  return X;
}

std::string position_text(const Point& x, int dim) {
  std::ostringstream s;
  s << "(" << x(0) << ", " << x(1);
  if (dim == 3) s << ", " << x(2);
  s << ")";
  return s.str();
}

Eigen::Vector3d checked(const VectorField& field, const Point& x, int dim,
                        const std::string& what) {
  const Eigen::Vector3d v = field(x);
  if (!v.head(dim).allFinite())
    throw InputError(what + " is not finite at x = " + position_text(x, dim) +
                     ": expected finite values everywhere it is used");
  return v;
}

}  // namespace

SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options) {
  require_quad4(mesh);
  const Eigen::Matrix3d D = plane_elasticity_matrix(options.material, options.plane_model);
  const SparsityPattern pattern(mesh, dofs);
  SparseMatrix A = pattern.zero_matrix();
  double* values = A.valuePtr();
  // Cells that are translates of the previous one (all of them on a structured mesh) share its
  // element matrix: compare the node coordinates relative to the first node.
  Q1Coordinates previous = Q1Coordinates::Constant(std::numeric_limits<double>::quiet_NaN());
  Q1Stiffness K;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Q1Coordinates X = cell_coordinates(mesh, c);
    const Q1Coordinates relative = X.colwise() - X.col(0);
    const double size = relative.cwiseAbs().maxCoeff();
    if (!((relative - previous).cwiseAbs().maxCoeff() <= 1e-13 * size)) {
      try {
        K = q1_stiffness(X, D, options.gauss_points);
      } catch (const InputError& e) {
        throw InputError("mesh cell " + std::to_string(c) + ": " + e.what());
      }
      previous = relative;
    }
    const auto nodes = mesh.cell(c);
    std::array<Index, 4> block{};
    for (int b = 0; b < 4; ++b)
      for (int a = 0; a < 4; ++a) {
        pattern.block_positions(nodes[static_cast<std::size_t>(a)],
                                nodes[static_cast<std::size_t>(b)], block.data());
        for (int ka = 0; ka < 2; ++ka)
          for (int kb = 0; kb < 2; ++kb) {
            const Index pos = block[static_cast<std::size_t>(ka * 2 + kb)];
            if (pos >= 0) values[pos] += K(2 * a + ka, 2 * b + kb);  // clamped: eliminated
          }
      }
  }
  return A;
}

void add_traction_load(const Mesh& mesh, const DofMap& dofs, const BoundaryPart& part,
                       const VectorField& p, int gauss_points, Vector& b, const std::string& what) {
  require_quad4(mesh);
  const auto rule = gauss_legendre(gauss_points);
  for (const Facet& f : part.facets) {
    const auto fn = mesh.facet_nodes(f);
    const Eigen::Vector2d xa = mesh.node(fn[0]);
    const Eigen::Vector2d xb = mesh.node(fn[1]);
    const double half_length = 0.5 * (xb - xa).norm();
    for (const auto& q : rule) {
      const double na = 0.5 * (1.0 - q.x);
      const double nb = 0.5 * (1.0 + q.x);
      Point x = Point::Zero();
      x.head<2>() = na * xa + nb * xb;
      const Eigen::Vector3d pv = checked(p, x, 2, what);
      for (int k = 0; k < 2; ++k) {
        const Index ia = dofs.free_index(fn[0], k);
        const Index ib = dofs.free_index(fn[1], k);
        if (ia >= 0) b(ia) += na * pv(k) * half_length * q.w;
        if (ib >= 0) b(ib) += nb * pv(k) * half_length * q.w;
      }
    }
  }
}

void add_body_force_load(const Mesh& mesh, const DofMap& dofs, const VectorField& f,
                         int gauss_points, Vector& b, const std::string& what) {
  require_quad4(mesh);
  const auto rule = gauss_legendre(gauss_points);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const Q1Coordinates X = cell_coordinates(mesh, c);
    const auto nodes = mesh.cell(c);
    for (const auto& qx : rule)
      for (const auto& qy : rule) {
        const Eigen::Vector4d N = q1_shape(qx.x, qy.x);
        const Eigen::Matrix2d J = q1_shape_gradients(qx.x, qy.x) * X.transpose();
        const double det_j = J.determinant();
        if (!(det_j > 0.0))
          throw InputError("mesh cell " + std::to_string(c) +
                           ": inverted or degenerate quadrilateral");
        Point x = Point::Zero();
        x.head<2>() = X * N;
        const Eigen::Vector3d fv = checked(f, x, 2, what);
        for (int a = 0; a < 4; ++a)
          for (int k = 0; k < 2; ++k) {
            const Index i = dofs.free_index(nodes[static_cast<std::size_t>(a)], k);
            if (i >= 0) b(i) += N(a) * fv(k) * det_j * qx.w * qy.w;
          }
      }
  }
}

double elastic_energy(const SparseMatrix& A, const Vector& b, const Vector& v) {
  return 0.5 * v.dot(A * v) - b.dot(v);
}

}  // namespace signorini

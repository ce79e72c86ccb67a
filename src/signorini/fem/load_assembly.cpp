#include "signorini/fem/load_assembly.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <sstream>

#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/face_geometry.hpp"
#include "signorini/fem/isoparametric_element.hpp"
#include "signorini/fem/quadrature.hpp"

namespace signorini {

namespace {

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

bool CoordinateBox::unbounded() const {
  for (std::size_t k = 0; k < 3; ++k)
    if (std::isfinite(lower[k]) || std::isfinite(upper[k])) return false;
  return true;
}

std::array<double, 2> CoordinateBox::clip(const Point& a, const Point& b) const {
  double t0 = 0.0, t1 = 1.0;
  for (std::size_t k = 0; k < 3; ++k) {
    const auto i = static_cast<Eigen::Index>(k);
    const double d = b(i) - a(i);
    if (d == 0.0) {
      if (a(i) < lower[k] || a(i) > upper[k]) return {1.0, 0.0};  // parallel and outside
      continue;
    }
    double s0 = (lower[k] - a(i)) / d;  // where the segment crosses the two planes
    double s1 = (upper[k] - a(i)) / d;
    if (s0 > s1) std::swap(s0, s1);
    t0 = std::max(t0, s0);
    t1 = std::min(t1, s1);
  }
  return {t0, t1};
}

namespace {

// int_part t . v dGamma into f in 3D, t = traction(x, outward unit normal at x): each face by the
// rule of its type (fem/reference_element.hpp; Quad4 faces with gauss_points per direction),
// the surface element |dx/ds1 x dx/ds2| and the normal along it, outward because the faces'
// corners run counterclockwise seen from outside (mesh/cell_type.hpp).
template <class Traction>
void integrate_over_faces(const Mesh& mesh, const BoundaryPart& part, const Traction& traction,
                          int gauss_points, Vector& f) {
  CellRules rules(gauss_points);
  ShapeValues N;
  for (const Facet& facet : part.facets) {
    const CellType type = facet_type(mesh.cell_type(facet.cell));
    const auto fn = mesh.facet_nodes(facet);
    for (const QuadraturePoint& q : rules(type)) {
      const FacePoint p = face_point(mesh, type, fn, q.xi, N);
      const double da = p.area.norm();
      if (!(da > 0.0)) continue;  // a degenerate face carries nothing
      const Eigen::Vector3d pv = traction(p.x, Eigen::Vector3d(p.area / da));
      for (std::size_t a = 0; a < fn.size(); ++a)
        for (int k = 0; k < 3; ++k) f(fn[a] * 3 + k) += N(static_cast<Index>(a)) * pv(k) * da * q.w;
    }
  }
}

// int_{part ∩ box} t . v dGamma into f, t = traction(x, outward unit normal at x).
template <class Traction>
void integrate_over_facets(const Mesh& mesh, const BoundaryPart& part, const Traction& traction,
                           int gauss_points, Vector& f, const std::string& what,
                           const CoordinateBox& box) {
  require_supported_cells(mesh);
  const int dim = mesh.dim();
  const bool whole = box.unbounded();
  if (dim == 3) {
    if (!whole)
      throw InputError(what +
                       ": a coordinate box on a 3D boundary part is not supported yet; make the "
                       "loaded part a boundary part of its own");
    integrate_over_faces(mesh, part, traction, gauss_points, f);
    return;
  }
  ShapeValues N;
  ShapeGradients dN;
  for (const Facet& facet : part.facets) {
    const CellType type = facet_type(mesh.cell_type(facet.cell));
    const auto fn = mesh.facet_nodes(facet);
    const auto n = static_cast<int>(fn.size());
    const Point xa = mesh.point(fn[0]);
    const Point xb = mesh.point(fn[1]);
    // The part of the facet inside the box, reference coordinate s in [s0, s1] (all of it
    // without a box). Clipping is done on the chord, which is the facet for straight ones.
    double s0 = -1.0, s1 = 1.0;
    if (!whole) {
      if (type == CellType::Line3) {
        const Point mid = mesh.point(fn[2]);
        if ((mid - 0.5 * (xa + xb)).norm() > 1e-10 * (xb - xa).norm())
          throw InputError(what +
                           ": a box on a boundary part with curved quadratic edges is not "
                           "supported; make the loaded part a boundary part of its own");
      }
      const auto [c0, c1] = box.clip(xa, xb);
      if (!(c1 > c0)) continue;  // misses the box, or touches it at one point only
      s0 = 2.0 * c0 - 1.0;
      s1 = 2.0 * c1 - 1.0;
    }
    for (const auto& q : gauss_legendre(gauss_points)) {
      // The Gauss point of [s0, s1]; on the whole facet exactly the paper's consistent rule.
      const Eigen::Vector3d s(whole ? q.x : s0 + 0.5 * (s1 - s0) * (q.x + 1.0), 0.0, 0.0);
      shape_functions(type, s, N);
      shape_gradients(type, s, dN);
      Point x = Point::Zero();
      Point dx = Point::Zero();  // dx/ds
      for (int a = 0; a < n; ++a) {
        x += N(a) * mesh.point(fn[static_cast<std::size_t>(a)]);
        dx += dN(0, a) * mesh.point(fn[static_cast<std::size_t>(a)]);
      }
      // The outward normal: facets run with the body on their left (mesh.hpp).
      const Eigen::Vector3d normal = Eigen::Vector3d(dx(1), -dx(0), 0.0) / dx.norm();
      const Eigen::Vector3d pv = traction(x, normal);
      const double weight = 0.5 * (s1 - s0) * dx.norm() * q.w;
      for (int a = 0; a < n; ++a)
        for (int k = 0; k < dim; ++k)
          f(fn[static_cast<std::size_t>(a)] * dim + k) += N(a) * pv(k) * weight;
    }
  }
}

}  // namespace

void add_traction_forces(const Mesh& mesh, const BoundaryPart& part, const VectorField& p,
                         int gauss_points, Vector& f, const std::string& what,
                         const CoordinateBox& box) {
  const int dim = mesh.dim();
  integrate_over_facets(
      mesh, part, [&](const Point& x, const Eigen::Vector3d&) { return checked(p, x, dim, what); },
      gauss_points, f, what, box);
}

void add_pressure_forces(const Mesh& mesh, const BoundaryPart& part, const ScalarField& p,
                         int gauss_points, Vector& f, const std::string& what) {
  integrate_over_facets(
      mesh, part,
      [&](const Point& x, const Eigen::Vector3d& normal) -> Eigen::Vector3d {
        const double value = p(x);
        if (!std::isfinite(value))
          throw InputError(what + " is not finite at x = " + position_text(x, mesh.dim()) +
                           ": expected finite values everywhere it is used");
        return -value * normal;  // a pressure pushes into the body: t = -p n
      },
      gauss_points, f, what, CoordinateBox{});
}

namespace {

template <int Dim>
void add_body_forces_of(const Mesh& mesh, const VectorField& force, int gauss_points, Vector& f,
                        const std::string& what) {
  CellRules rules(gauss_points);
  ShapeValues N;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const CellType type = mesh.cell_type(c);
    const CellCoordinatesOf<Dim> X = cell_coordinates<Dim>(mesh, c);
    const auto nodes = mesh.cell(c);
    for (const QuadraturePoint& q : rules(type)) {
      shape_functions(type, q.xi, N);
      const double det_j = cell_jacobian<Dim>(type, X, q.xi).determinant();
      if (!(det_j > 0.0))
        throw InputError("mesh cell " + std::to_string(c) + ": inverted or degenerate " +
                         std::string(enum_to_string(kCellTypeNames, type)) +
                         " (det J = " + std::to_string(det_j) + " at a quadrature point)");
      Point x = Point::Zero();
      x.head<Dim>() = X * N;
      const Eigen::Vector3d fv = checked(force, x, Dim, what);
      for (Index a = 0; a < N.size(); ++a)
        for (int k = 0; k < Dim; ++k)
          f(nodes[static_cast<std::size_t>(a)] * Dim + k) += N(a) * fv(k) * det_j * q.w;
    }
  }
}

}  // namespace

void add_body_forces(const Mesh& mesh, const VectorField& force, int gauss_points, Vector& f,
                     const std::string& what) {
  require_supported_cells(mesh);
  if (mesh.dim() == 2)
    add_body_forces_of<2>(mesh, force, gauss_points, f, what);
  else
    add_body_forces_of<3>(mesh, force, gauss_points, f, what);
}

void add_traction_load(const Mesh& mesh, const DofMap& dofs, const BoundaryPart& part,
                       const VectorField& p, int gauss_points, Vector& b, const std::string& what) {
  Vector f = Vector::Zero(dofs.num_dofs());
  add_traction_forces(mesh, part, p, gauss_points, f, what);
  b += dofs.restrict_to_free(f);
}

void add_body_force_load(const Mesh& mesh, const DofMap& dofs, const VectorField& force,
                         int gauss_points, Vector& b, const std::string& what) {
  Vector f = Vector::Zero(dofs.num_dofs());
  add_body_forces(mesh, force, gauss_points, f, what);
  b += dofs.restrict_to_free(f);
}

Index nearest_node(const Mesh& mesh, const Point& x, const std::vector<Index>& candidates) {
  Index best = -1;
  double best_distance = std::numeric_limits<double>::infinity();
  const auto consider = [&](Index n) {
    const double d = (mesh.point(n) - x).squaredNorm();
    if (d < best_distance) {
      best_distance = d;
      best = n;
    }
  };
  if (candidates.empty())
    for (Index n = 0; n < mesh.num_nodes(); ++n) consider(n);
  else
    for (const Index n : candidates) consider(n);
  return best;
}

}  // namespace signorini

#pragma once
// The load vector of the discrete problem (14): tractions on boundary parts (optionally on the
// part of a boundary inside a box of coordinates), body forces and point loads, assembled into
// the full node-major vector (node * dim + component) so that the loads on clamped dofs are kept
// for the resultants (problem/resultants.hpp); the free part is the b of (14).

#include <array>
#include <limits>
#include <string>

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

/// A box of coordinates, each axis an interval [lower, upper] (unbounded by default): a traction
/// acts on the part of its boundary inside the box.
struct CoordinateBox {
  std::array<double, 3> lower{-std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity(),
                              -std::numeric_limits<double>::infinity()};
  std::array<double, 3> upper{std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::infinity(),
                              std::numeric_limits<double>::infinity()};
  /// True if no axis is bounded.
  [[nodiscard]] bool unbounded() const;
  /// The parameters [t0, t1] of the part of the segment a + t (b - a), t in [0, 1], inside the
  /// box; t0 > t1 where the segment misses it (Liang-Barsky clipping).
  [[nodiscard]] std::array<double, 2> clip(const Point& a, const Point& b) const;
};

/// Adds int_{part ∩ box} p . v dGamma to the full vector f (num_nodes * dim entries) by Gauss
/// quadrature with `gauss_points` on the part of each facet inside the box (method.md
/// "Conventions": consistent, not lumped). The box cuts facets where its faces cross them, so a
/// load on part of an edge is integrated exactly for polynomial p (degree <= 2 gauss_points - 2),
/// wherever the mesh nodes lie. Quadratic (curved) edges are integrated along the curve; a box
/// on them is allowed only where they are straight. Throws InputError if p is not finite
/// somewhere (naming `what`).
void add_traction_forces(const Mesh& mesh, const BoundaryPart& part, const VectorField& p,
                         int gauss_points, Vector& f, const std::string& what = "traction",
                         const CoordinateBox& box = {});

/// Adds the load of a pressure p(x) normal to a boundary part, int -p n . v dGamma with n the
/// outward unit normal at each Gauss point (along the curve on quadratic edges), to the full
/// vector f. p > 0 pushes into the body. Throws InputError if p is not finite somewhere.
void add_pressure_forces(const Mesh& mesh, const BoundaryPart& part, const ScalarField& p,
                         int gauss_points, Vector& f, const std::string& what = "pressure");
/// Adds int_Omega f . v dOmega to the full vector (each cell type's rule, cell_quadrature(); Q1
/// cells with `gauss_points` per direction).
void add_body_forces(const Mesh& mesh, const VectorField& force, int gauss_points, Vector& f,
                     const std::string& what = "body force");

/// The traction load on the free dofs only (b of (14)): add_traction_forces, restricted.
void add_traction_load(const Mesh& mesh, const DofMap& dofs, const BoundaryPart& part,
                       const VectorField& p, int gauss_points, Vector& b,
                       const std::string& what = "traction");

/// The body-force load on the free dofs only: add_body_forces, restricted.
void add_body_force_load(const Mesh& mesh, const DofMap& dofs, const VectorField& f,
                         int gauss_points, Vector& b, const std::string& what = "body force");

/// The mesh node nearest to x (the first of equals), among `candidates` if it is not empty.
[[nodiscard]] Index nearest_node(const Mesh& mesh, const Point& x,
                                 const std::vector<Index>& candidates = {});

}  // namespace signorini

#pragma once
// Global assembly of the discrete problem (14): the stiffness A and the load vector b, directly
// in the numbering of the free dofs (Dirichlet conditions by elimination).

#include <string>

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/material.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

struct ElasticityOptions {
  IsotropicMaterial material;
  PlaneModel plane_model = PlaneModel::PlaneStrain;
  int gauss_points = 2;  ///< per direction in cells (the paper's 2x2 rule)
};

/// Reduced stiffness A (num_free x num_free, SPD when clamping holds the body, both triangles
/// stored). Throws InputError on an inverted or degenerate cell, naming it.
SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options);

/// Adds the consistent load of a traction p on a boundary part, int_{part} p . v dGamma, by
/// Gauss quadrature with `gauss_points` per facet (method.md "Conventions": consistent, not
/// lumped). Throws InputError if p is not finite somewhere (naming `what` and the position).
void add_traction_load(const Mesh& mesh, const DofMap& dofs, const BoundaryPart& part,
                       const VectorField& p, int gauss_points, Vector& b,
                       const std::string& what = "traction");

/// Adds the body-force load int_Omega f . v dOmega (cell Gauss rule of `gauss_points`^dim).
void add_body_force_load(const Mesh& mesh, const DofMap& dofs, const VectorField& f,
                         int gauss_points, Vector& b, const std::string& what = "body force");

/// Energy J(v) = 1/2 <A v, v> - <b, v> (method.md section 1).
double elastic_energy(const SparseMatrix& A, const Vector& b, const Vector& v);

}  // namespace signorini

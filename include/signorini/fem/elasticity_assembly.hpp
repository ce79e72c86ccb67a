#pragma once
// Global assembly of the discrete problem (14): the stiffness A and the load vector b, directly
// in the numbering of the free dofs (Dirichlet conditions by elimination).

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "signorini/fem/dof_map.hpp"
#include "signorini/fem/material.hpp"
#include "signorini/fem/vector_field.hpp"
#include "signorini/mesh/mesh.hpp"

namespace signorini {

struct ElasticityOptions {
  IsotropicMaterial material;  ///< of every cell whose region has none of its own below
  /// Materials per mesh region (Mesh::cell_region): entry r, where set, is region r's. Empty:
  /// `material` everywhere.
  std::vector<std::optional<IsotropicMaterial>> region_materials;
  PlaneModel plane_model = PlaneModel::PlaneStrain;
  /// Gauss points per direction in Q1 quadrilaterals and hexahedra (the paper's 2x2 rule); the
  /// other cell types have their own rules (fem/reference_element.hpp). plane_model is for 2D
  /// meshes; 3D ones use the full Hooke's law.
  int gauss_points = 2;
};

/// The material of the cells of region r.
const IsotropicMaterial& material_of_region(const ElasticityOptions& options, int region);
/// Throws InputError unless the mesh is 2D or 3D and every cell type has a finite element of the
/// mesh's dimension (tri3, tri6, quad4, quad8, quad9; tet4, tet10, hex8, hex27).
void require_supported_cells(const Mesh& mesh);

/// Reduced stiffness A (num_free x num_free, SPD when clamping holds the body, both triangles
/// stored). Throws InputError on an inverted or degenerate cell, naming it.
/// `columns_of` (optional, one flag per node): only the columns of these nodes, from the cells
/// that touch them (a distributed run's part: by symmetry the rows of its unknowns;
/// docs/distributed.md). Their free dofs must be consecutive, [lo, hi): the result is then
/// num_free x (hi - lo), its column k that of dof lo + k (ContactProblem::column_of).
SparseMatrix assemble_stiffness(const Mesh& mesh, const DofMap& dofs,
                                const ElasticityOptions& options,
                                const std::vector<bool>* columns_of = nullptr);

/// Throws InputError, naming the cell as assemble_stiffness does, on the first cell that is
/// inverted or degenerate: det J <= 0 at one of its nodes or at a point of the stiffness's
/// quadrature rule. The same checks as the assembly's, without the element matrices: for rank 0
/// of a distributed run, which assembles none of the cells but must find a bad one for all
/// (docs/distributed.md).
void require_valid_cells(const Mesh& mesh, const ElasticityOptions& options);

/// K u for the full node-major vector u (num_nodes * dim), cell by cell, at the nodes of the
/// cells for which `needed(cell)` holds (all cells if it is empty); zero elsewhere. With u the
/// solution, (K u)_i - f_i at a clamped dof i is the reaction of the clamp there.
Vector internal_forces(const Mesh& mesh, const ElasticityOptions& options, const Vector& u,
                       const std::function<bool(Index)>& needed = {});

}  // namespace signorini

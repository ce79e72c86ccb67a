#pragma once
// The elasticity matrix D of each region of a mesh, in the dimension of the mesh: the plane one
// (plane strain or stress) in 2D, the full 6x6 one in 3D (material.hpp).
#include <vector>

#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/isoparametric_element.hpp"

namespace signorini {

/// D of each region (index: Mesh::cell_region), for a mesh of dimension Dim.
template <int Dim>
std::vector<ElasticityMatrixOf<Dim>> region_elasticity_matrices(const Mesh& mesh,
                                                                const ElasticityOptions& options) {
  std::vector<ElasticityMatrixOf<Dim>> D;
  for (std::size_t r = 0; r < mesh.region_names().size(); ++r) {
    const IsotropicMaterial& m = material_of_region(options, static_cast<int>(r));
    if constexpr (Dim == 2)
      D.push_back(plane_elasticity_matrix(m, options.plane_model));
    else
      D.push_back(elasticity_matrix_3d(m));
  }
  return D;
}

}  // namespace signorini

#include "signorini/problem/model_hierarchy.hpp"

#include <fmt/format.h>

#include "signorini/core/error.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/iterative/galerkin_product.hpp"
#include "signorini/iterative/smoothed_aggregation.hpp"
#include "signorini/linalg/iterative_options.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model.hpp"
#include "signorini/problem/rectangle_hierarchy.hpp"

namespace signorini {

MultigridHierarchy make_model_hierarchy(const ProblemSpec& spec, const Mesh& mesh,
                                        const DofMap& dofs, const SparseMatrix& A) {
  const MultigridCoarsening asked = spec.solver.linear.coarsening;
  const bool q1_rectangle =
      spec.mesh_type == MeshType::Rectangle && spec.mesh.cell == CellType::Quad4;
  if (!q1_rectangle && asked == MultigridCoarsening::Geometric)
    throw InputError(fmt::format(
        "solver.linear.coarsening = \"geometric\" halves rectangles of quad4 cells, not {}; "
        "use \"auto\" or \"aggregation\"",
        spec.mesh_type == MeshType::Gmsh    ? std::string("a mesh from a file")
        : spec.mesh_type == MeshType::Given ? std::string("a given mesh")
        : spec.mesh_type == MeshType::Box
            ? std::string("a box of 3D cells")
            : std::string(enum_to_string(kCellTypeNames, spec.mesh.cell))));
  if (asked == MultigridCoarsening::Aggregation || !q1_rectangle)
    return smoothed_aggregation_hierarchy(A, rigid_body_modes(mesh, dofs), free_dof_nodes(dofs));

  MultigridHierarchy h;
  h.prolongations =
      make_rectangle_prolongations(spec.mesh, spec.clamps, dofs, 400, spec.displacements);
  if (!h.prolongations.empty()) h.kind = HierarchyKind::Geometric;
  const Index coarsest = h.prolongations.empty() ? dofs.num_free() : h.prolongations.back().cols();
  const Index dense_limit = multigrid_options(spec.solver.linear).max_dense_coarse;
  const int halvings = static_cast<int>(h.prolongations.size());
  if (coarsest <= dense_limit) return h;
  if (asked == MultigridCoarsening::Geometric)
    // A coarsest level smoothed rather than solved leaves CG with thousands of iterations
    // (7,281 against 328 at 810x270): refused rather than run.
    throw InputError(fmt::format(
        "solver.linear.coarsening = \"geometric\": the {}x{} mesh halves only down to {}x{} "
        "({} unknowns; the coarsest level must have at most {}, so nx and ny must stay even "
        "until then); use \"auto\" or \"aggregation\"",
        spec.mesh.nx, spec.mesh.ny, spec.mesh.nx >> halvings, spec.mesh.ny >> halvings, coarsest,
        dense_limit));

  // "auto" with a coarsest geometric level too large to factorise densely (an odd nx or ny on
  // the way down): aggregation continues from it. Its near-null space is the rigid-body modes of
  // the coarse rectangle, which bilinear interpolation carries exactly to the fine mesh, and its
  // matrix the Galerkin product of the geometric levels, formed here for that reason.
  RectangleMeshOptions coarse = spec.mesh;
  coarse.nx >>= halvings;
  coarse.ny >>= halvings;
  const Mesh coarse_mesh = make_rectangle_mesh(coarse);
  const DofMap coarse_dofs = make_dof_map(coarse_mesh, spec.clamps, spec.displacements);
  const SparseMatrix* current = &A;
  for (const SparseMatrix& P : h.prolongations) {
    h.coarse_operators.push_back(galerkin_product(*current, P));
    current = &h.coarse_operators.back();
  }
  MultigridHierarchy rest = smoothed_aggregation_hierarchy(
      *current, rigid_body_modes(coarse_mesh, coarse_dofs), free_dof_nodes(coarse_dofs));
  if (rest.prolongations.empty()) return h;  // (cannot happen above max_dense_coarse)
  for (auto& P : rest.prolongations) h.prolongations.push_back(std::move(P));
  for (auto& C : rest.coarse_operators) h.coarse_operators.push_back(std::move(C));
  h.kind = halvings == 0 ? HierarchyKind::Aggregation : HierarchyKind::GeometricThenAggregation;
  return h;
}

}  // namespace signorini

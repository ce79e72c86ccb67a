#include "signorini/problem/model.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/core/error.hpp"
#include "signorini/fem/contact_boundary.hpp"
#include "signorini/fem/free_rigid_motions.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/problem/model_hierarchy.hpp"

namespace signorini {

DofMap make_dof_map(const Mesh& mesh, const std::vector<ClampSpec>& clamps) {
  DofMap dofs(mesh.num_nodes(), mesh.dim());
  for (const ClampSpec& c : clamps) {
    const auto nodes = mesh.boundary_part_nodes(c.boundary);  // throws on unknown names
    for (const Index node : nodes)
      for (int k = 0; k < mesh.dim(); ++k)
        if (c.components[static_cast<std::size_t>(k)]) dofs.clamp(node, k);
  }
  dofs.finalize();
  return dofs;
}

void require_no_free_rigid_motion(const Mesh& mesh, const DofMap& dofs) {
  const std::vector<RigidMotion> free = free_rigid_motions(mesh, dofs);
  if (free.empty()) return;
  std::string list;
  Index piece = -1;
  const bool several_pieces = count_mesh_pieces(mesh) > 1;
  for (const RigidMotion& m : free) {
    if (!list.empty()) list += ", ";
    if (m.piece != piece && several_pieces) {
      const auto x = mesh.node(m.piece_node);
      list +=
          fmt::format("the mesh piece with node {} at ({:g}, {:g}): ", m.piece_node, x(0), x(1));
      piece = m.piece;
    }
    list += m.description();
  }
  throw InputError(fmt::format(
      "the clamps leave {} free ({}): the stiffness is singular, and frictionless contact "
      "cannot hold a body by itself (the foundation only pushes, never along its surface); "
      "clamp more components ([[clamp]] components = [\"x\", \"y\"]) or another boundary part",
      free.size() == 1 ? "a rigid motion" : fmt::format("{} rigid motions", free.size()), list));
}

namespace {

std::vector<ClampedPart> clamped_parts(const Mesh& mesh, const std::vector<ClampSpec>& clamps) {
  std::vector<ClampedPart> parts;
  std::vector<bool> taken(static_cast<std::size_t>(mesh.num_nodes() * mesh.dim()), false);
  for (const ClampSpec& c : clamps) {
    ClampedPart part{c.boundary, {}};
    for (const Index node : mesh.boundary_part_nodes(c.boundary))
      for (int k = 0; k < mesh.dim(); ++k) {
        const Index dof = node * mesh.dim() + k;
        if (!c.components[static_cast<std::size_t>(k)] || taken[static_cast<std::size_t>(dof)])
          continue;
        taken[static_cast<std::size_t>(dof)] = true;
        part.dofs.push_back(dof);
      }
    parts.push_back(std::move(part));
  }
  return parts;
}

}  // namespace

Model build_model(const ProblemSpec& spec) {
  validate(spec.elasticity.material);
  validate(spec.solver);
  if (spec.clamps.empty())
    throw InputError(
        "no clamped boundary: the stiffness would be singular (add a [[clamp]] section)");
  // A part of the boundary is either loaded (Gamma_N) or in possible contact (Gamma_K), not both
  // (method.md section 1): a load there would act where the foundation pushes, unaccounted.
  for (std::size_t i = 0; i < spec.tractions.size(); ++i)
    if (spec.tractions[i].boundary == spec.contact.boundary)
      throw InputError(fmt::format(
          "traction[{}].boundary = '{}' is the contact boundary (contact.boundary): a boundary "
          "part is either loaded or in contact with the foundation; load another part",
          i, spec.tractions[i].boundary));
  TimingTable timings;
  ScopedTimer mesh_timer(timings, "mesh");
  Mesh mesh = spec.mesh_type == MeshType::Gmsh ? read_mesh_file(spec.mesh_file)
                                               : make_rectangle_mesh(spec.mesh);
  // Materials per region, by the regions' names.
  ElasticityOptions elasticity = spec.elasticity;
  for (const RegionMaterialSpec& m : spec.region_materials) {
    const auto& names = mesh.region_names();
    const auto it = std::find(names.begin(), names.end(), m.region);
    if (m.region.empty() || it == names.end()) {
      std::string known;
      for (const std::string& n : names)
        if (!n.empty()) known += (known.empty() ? "" : ", ") + n;
      throw InputError("region.name = '" + m.region + "': the mesh has no such region (it has: " +
                       (known.empty() ? std::string("none") : known) + ")");
    }
    const auto r = static_cast<std::size_t>(it - names.begin());
    if (elasticity.region_materials.size() <= r) elasticity.region_materials.resize(r + 1);
    elasticity.region_materials[r] = m.material;
  }
  DofMap dofs = make_dof_map(mesh, spec.clamps);
  mesh_timer.stop();
  if (dofs.num_free() == 0) throw InputError("every dof is clamped: nothing to solve");
  require_no_free_rigid_motion(mesh, dofs);

  ContactProblem problem;
  {
    ScopedTimer t(timings, "assembly");
    problem.A = assemble_stiffness(mesh, dofs, elasticity);
  }
  Vector loads = Vector::Zero(dofs.num_dofs());
  std::vector<PlacedPointLoad> placed;
  {
    ScopedTimer t(timings, "loads");
    for (const TractionSpec& tr : spec.tractions)
      add_traction_forces(mesh, mesh.boundary_part(tr.boundary), tr.p, spec.boundary_gauss_points,
                          loads, "traction on '" + tr.boundary + "'", tr.region);
    if (spec.body_force)
      add_body_forces(mesh, spec.body_force, spec.elasticity.gauss_points, loads);
    for (std::size_t i = 0; i < spec.point_loads.size(); ++i) {
      const PointLoadSpec& pl = spec.point_loads[i];
      if (!pl.at.allFinite() || !pl.force.allFinite())
        throw InputError(fmt::format("point_load[{}]: expected finite 'at' and 'force'", i));
      const std::vector<Index> candidates =
          pl.boundary.empty() ? std::vector<Index>{} : mesh.boundary_part_nodes(pl.boundary);
      PlacedPointLoad p;
      p.requested = pl.at;
      p.node = nearest_node(mesh, pl.at, candidates);
      p.at = mesh.point(p.node);
      p.distance = (p.at - pl.at).norm();
      p.force = pl.force;
      for (int k = 0; k < mesh.dim(); ++k) loads(p.node * mesh.dim() + k) += pl.force(k);
      placed.push_back(p);
    }
    problem.b = dofs.restrict_to_free(loads);
  }
  {
    ScopedTimer t(timings, "contact set");
    problem.contact = make_contact_set(mesh, mesh.boundary_part(spec.contact.boundary), dofs, [&] {
      RigidObstacle o = spec.contact.obstacle;
      if (o.shape == ObstacleShape::Gap) o.gap = spec.contact.gap;
      return o;
    }());
  }
  MultigridHierarchy multigrid;
  const LinearSolverOptions& linear = spec.solver.linear;
  if (linear.type == LinearSolverType::ConjugateGradient &&
      linear.preconditioner == PreconditionerType::Multigrid) {
    ScopedTimer t(timings, "multigrid hierarchy");
    multigrid = make_model_hierarchy(spec, mesh, dofs, problem.A);
  }
  std::vector<ClampedPart> clamps = clamped_parts(mesh, spec.clamps);
  return Model{std::move(mesh),    std::move(dofs),      std::move(problem), std::move(multigrid),
               std::move(timings), elasticity,           std::move(loads),   std::move(clamps),
               std::move(placed),  spec.contact.boundary};
}

}  // namespace signorini

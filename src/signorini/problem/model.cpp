#include "signorini/problem/model.hpp"

#include "signorini/contact/contact_set.hpp"
#include "signorini/core/error.hpp"
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

Model build_model(const ProblemSpec& spec) {
  validate(spec.elasticity.material);
  validate(spec.solver);
  if (spec.clamps.empty())
    throw InputError(
        "no clamped boundary: the stiffness would be singular (add a [[clamp]] section)");
  TimingTable timings;
  ScopedTimer mesh_timer(timings, "mesh");
  Mesh mesh = make_rectangle_mesh(spec.mesh);
  DofMap dofs = make_dof_map(mesh, spec.clamps);
  mesh_timer.stop();
  if (dofs.num_free() == 0) throw InputError("every dof is clamped: nothing to solve");

  ContactProblem problem;
  {
    ScopedTimer t(timings, "assembly");
    problem.A = assemble_stiffness(mesh, dofs, spec.elasticity);
  }
  {
    ScopedTimer t(timings, "loads");
    problem.b = Vector::Zero(dofs.num_free());
    for (const TractionSpec& tr : spec.tractions)
      add_traction_load(mesh, dofs, mesh.boundary_part(tr.boundary), tr.p,
                        spec.boundary_gauss_points, problem.b, "traction on '" + tr.boundary + "'");
    if (spec.body_force)
      add_body_force_load(mesh, dofs, spec.body_force, spec.elasticity.gauss_points, problem.b);
  }
  {
    ScopedTimer t(timings, "contact set");
    problem.contact =
        make_contact_set(mesh, mesh.boundary_part(spec.contact.boundary), dofs, spec.contact.gap);
  }
  const LinearSolverOptions& linear = spec.solver.linear;
  if (linear.type == LinearSolverType::ConjugateGradient &&
      linear.preconditioner == PreconditionerType::Multigrid) {
    ScopedTimer t(timings, "multigrid hierarchy");
    problem.multigrid = make_model_hierarchy(spec, mesh, dofs, problem.A);
  }
  return Model{std::move(mesh), std::move(dofs), std::move(problem), std::move(timings)};
}

}  // namespace signorini

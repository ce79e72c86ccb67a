#include "signorini/problem/model.hpp"

#include <fmt/format.h>

#include <Eigen/LU>
#include <algorithm>

#include "signorini/contact/distributed_engine.hpp"
#include "signorini/contact/method_table.hpp"
#include "signorini/core/error.hpp"
#include "signorini/core/peak_memory.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/free_rigid_motions.hpp"
#include "signorini/fem/load_assembly.hpp"
#include "signorini/fem/node_ordering.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/interface/contact_tangents.hpp"
#include "signorini/iterative/contact_prolongation.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/mesh/rectangle_mesh.hpp"
#include "signorini/parallel/node_partition.hpp"
#include "signorini/parallel/row_partition.hpp"
#include "signorini/problem/box_model_in_parts.hpp"
#include "signorini/problem/distributed_model.hpp"
#include "signorini/problem/model_hierarchy.hpp"
#include "signorini/problem/model_in_parts.hpp"
#include "signorini/problem/solver_plan.hpp"

namespace signorini {

namespace {

// Calls hold(node, k, value) for each Cartesian component that displacement entry `d` (number
// i) prescribes, and hold_normal(node, normal, value) for each node of a `normal` entry whose
// outward normal is not along a coordinate axis (it needs local axes). Where the normal is along
// axis k (a side parallel to it), u . n is that component, with the normal's sign.
template <class Hold, class HoldNormal>
void for_each_prescribed(const Mesh& mesh, const DisplacementSpec& d, std::size_t i,
                         const Hold& hold, const HoldNormal& hold_normal) {
  if (d.normal) {
    if (mesh.dim() != 2)  // local axes per node (DofMap::set_frame) are 2D so far
      throw InputError(fmt::format(
          "displacement[{}].normal: a normal displacement is supported on 2D meshes only so far; "
          "give the components x, y, z",
          i));
    const BoundaryNodes b = boundary_nodes(mesh, mesh.boundary_part(d.boundary),
                                           fmt::format("displacement[{}].boundary", i));
    for (std::size_t j = 0; j < b.nodes.size(); ++j) {
      const Index node = b.nodes[j];
      const Eigen::Vector2d n = b.normals.col(static_cast<Index>(j));
      const double value = d.normal(mesh.point(node));
      const int k = std::abs(n(0)) >= std::abs(n(1)) ? 0 : 1;
      if (std::abs(std::abs(n(k)) - 1.0) <= 1e-12)
        hold(node, k, n(k) > 0.0 ? value : -value);
      else
        hold_normal(node, n, value);
    }
    return;
  }
  const auto nodes = mesh.boundary_part_nodes(d.boundary);  // throws on unknown names
  for (const Index node : nodes)
    for (int k = 0; k < mesh.dim(); ++k)
      if (d.values[static_cast<std::size_t>(k)])
        hold(node, k, d.values[static_cast<std::size_t>(k)](mesh.point(node)));
}

// The dof numbering, and for each full dof the entry that holds it (-1: free): clamp c as c,
// displacement entry i as clamps.size() + i. Clamps come first and win; among the displacements
// the first entry wins. A node held along its normal in local axes belongs to that entry with
// both of its Cartesian dofs (its reaction is along the normal, in x and y).
}  // namespace

DofMap number_dofs(const Mesh& mesh, const std::vector<ClampSpec>& clamps,
                   const std::vector<DisplacementSpec>& displacements, std::vector<int>& owner,
                   const std::vector<Index>& node_order) {
  DofMap dofs(mesh.num_nodes(), mesh.dim());
  owner.assign(static_cast<std::size_t>(dofs.num_dofs()), -1);
  const auto owner_of = [&](Index node, int k) -> int& {
    return owner[static_cast<std::size_t>(node * mesh.dim() + k)];
  };
  for (std::size_t c = 0; c < clamps.size(); ++c) {
    std::vector<Index> nodes;
    if (!clamps[c].boundary.empty())
      nodes = mesh.boundary_part_nodes(clamps[c].boundary);  // throws on unknown names
    if (clamps[c].at) {  // a pinned node: the nearest one (of the part, where one is named)
      if (!clamps[c].at->allFinite())
        throw InputError(fmt::format("clamp[{}].at: expected finite coordinates", c));
      nodes = {nearest_node(mesh, *clamps[c].at, nodes)};
    }
    for (const Index node : nodes)
      for (int k = 0; k < mesh.dim(); ++k) {
        if (!clamps[c].components[static_cast<std::size_t>(k)]) continue;
        dofs.clamp(node, k);
        if (owner_of(node, k) < 0) owner_of(node, k) = static_cast<int>(c);
      }
  }
  for (std::size_t i = 0; i < displacements.size(); ++i) {
    const int entry = static_cast<int>(clamps.size() + i);
    for_each_prescribed(
        mesh, displacements[i], i,
        [&](Index node, int k, double value) {
          if (owner_of(node, k) >= 0) return;
          owner_of(node, k) = entry;
          dofs.prescribe(node, k, value);
        },
        [&](Index node, const Eigen::Vector2d& n, double value) {
          if (dofs.has_frame(node)) {
            // A corner of two parts held along their normals: u . n1 = v1 and u . n = value fix
            // u; its component along the node's second axis is held too. (Nearly) parallel
            // normals: the first entry wins.
            const Eigen::Matrix2d Q = dofs.frame(node);
            const Eigen::Vector2d n1 = Q.col(0);
            if (dofs.is_clamped(node, 1) || std::abs(n1(0) * n(1) - n1(1) * n(0)) < 1e-6) return;
            Eigen::Matrix2d M;
            M.row(0) = n1.transpose();
            M.row(1) = n.transpose();
            const Eigen::Vector2d u = M.inverse() * Eigen::Vector2d(dofs.value(node, 0), value);
            dofs.prescribe(node, 1, Q.col(1).dot(u));
            return;
          }
          const bool held_x = owner_of(node, 0) >= 0, held_y = owner_of(node, 1) >= 0;
          if (held_x && held_y) return;
          if (held_x || held_y) {
            // One component held (a roller where the part meets a symmetry line): it keeps its
            // value c, and u . n = value gives the other, (value - n_k c) / n_other.
            const int k = held_x ? 0 : 1, other = 1 - k;
            if (std::abs(n(other)) < 1e-6) return;  // the normal is along the held axis
            owner_of(node, other) = entry;
            dofs.prescribe(node, other, (value - n(k) * dofs.value(node, k)) / n(other));
            return;
          }
          // u . n alone on an inclined or curved part: the node's axes become (n, t), its first
          // component is held.
          owner_of(node, 0) = owner_of(node, 1) = entry;
          Eigen::Matrix2d Q;
          Q << n(0), -n(1), n(1), n(0);  // columns: the normal, the tangent n turned a quarter
          dofs.set_frame(node, Q);
          dofs.prescribe(node, 0, value);
        });
  }
  dofs.finalize(node_order);
  return dofs;
}

// The dofs of each [[clamp]], then of each [[displacement]] entry, from number_dofs's owners:
// each dof counts for the entry that holds it, so that the reactions add up to the total.
std::vector<ClampedPart> clamped_parts(const std::vector<ClampSpec>& clamps,
                                       const std::vector<DisplacementSpec>& displacements,
                                       const std::vector<int>& owner) {
  std::vector<ClampedPart> parts;
  for (const ClampSpec& c : clamps) parts.push_back({c.name(), {}});
  for (const DisplacementSpec& d : displacements) parts.push_back({d.boundary, {}});
  for (std::size_t dof = 0; dof < owner.size(); ++dof)
    if (owner[dof] >= 0)
      parts[static_cast<std::size_t>(owner[dof])].dofs.push_back(static_cast<Index>(dof));
  return parts;
}

DofMap make_dof_map(const Mesh& mesh, const std::vector<ClampSpec>& clamps,
                    const std::vector<DisplacementSpec>& displacements,
                    const std::vector<Index>& node_order) {
  std::vector<int> owner;
  return number_dofs(mesh, clamps, displacements, owner, node_order);
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

std::string ClampSpec::name() const {
  if (!at) return boundary;
  if ((*at)(2) == 0.0) return fmt::format("at ({:g}, {:g})", (*at)(0), (*at)(1));
  return fmt::format("at ({:g}, {:g}, {:g})", (*at)(0), (*at)(1), (*at)(2));
}

namespace {

// Each part is either loaded (Gamma_N) or in possible contact (Gamma_K), not both (method.md
// section 1): a load there would act where the foundation pushes, unaccounted.
void require_loads_off_contact(const ProblemSpec& spec) {
  const auto check = [&](const char* section, std::size_t i, const std::string& boundary) {
    for (const ContactSpec& c : spec.contacts)
      if (boundary == c.boundary)
        throw InputError(fmt::format(
            "{}[{}].boundary = '{}' is a contact boundary (contact.boundary): a boundary part is "
            "either loaded or in contact with the foundation; load another part",
            section, i, boundary));
  };
  for (std::size_t i = 0; i < spec.tractions.size(); ++i)
    check("traction", i, spec.tractions[i].boundary);
  for (std::size_t i = 0; i < spec.pressures.size(); ++i)
    check("pressure", i, spec.pressures[i].boundary);
}

}  // namespace

namespace {

// The friction law of the contact set (contact_friction_law), and the tangential rows added to
// N; null when no boundary has friction.
std::shared_ptr<const FrictionLaw> make_friction(const ProblemSpec& spec, const Mesh& mesh,
                                                 const DofMap& dofs,
                                                 const std::vector<Index>& starts,
                                                 ContactSet& contact,
                                                 const DistributedEngine* engine) {
  std::shared_ptr<const FrictionLaw> law = contact_friction_law(
      spec, mesh.dim(), starts,
      [&](Index j) { return mesh.point(contact.nodes[static_cast<std::size_t>(j)]); }, engine);
  if (law) add_tangential_rows(contact, tangential_operator(contact, dofs));
  return law;
}

}  // namespace

void add_surface_and_body_loads(
    const ProblemSpec& spec, const Mesh& mesh,
    const std::function<Vector&(const std::vector<double>&, std::string)>& into) {
  for (std::size_t i = 0; i < spec.tractions.size(); ++i) {
    const TractionSpec& tr = spec.tractions[i];
    add_traction_forces(mesh, mesh.boundary_part(tr.boundary), tr.p, spec.boundary_gauss_points,
                        into(tr.factors, fmt::format("traction[{}]", i)),
                        "traction on '" + tr.boundary + "'", tr.region);
  }
  for (std::size_t i = 0; i < spec.pressures.size(); ++i)
    add_pressure_forces(mesh, mesh.boundary_part(spec.pressures[i].boundary), spec.pressures[i].p,
                        spec.boundary_gauss_points,
                        into(spec.pressures[i].factors, fmt::format("pressure[{}]", i)),
                        fmt::format("pressure[{}].p", i));
  if (spec.body_force)
    add_body_forces(mesh, spec.body_force, spec.elasticity.gauss_points,
                    into(spec.body_force_factors, "body_force"));
}

std::vector<FrictionKind> friction_kinds(const ProblemSpec& spec) {
  std::vector<FrictionKind> kinds;
  for (const ContactSpec& c : spec.contacts)
    if (c.friction != FrictionModel::None)
      kinds.push_back(c.friction == FrictionModel::Tresca ? FrictionKind::Tresca
                                                          : FrictionKind::Coulomb);
  return kinds;
}

std::shared_ptr<const FrictionLaw> contact_friction_law(const ProblemSpec& spec, int dim,
                                                        const std::vector<Index>& starts,
                                                        const std::function<Point(Index j)>& point,
                                                        const DistributedEngine* engine) {
  std::vector<FrictionKind> kinds = friction_kinds(spec);
  if (kinds.empty()) return nullptr;
  const Index size = starts.back();
  Vector s = Vector::Zero(size), mu = Vector::Zero(size);
  for (std::size_t part = 0; part < spec.contacts.size(); ++part) {
    const ContactSpec& c = spec.contacts[part];
    const std::string where =
        spec.contacts.size() == 1 ? "contact" : fmt::format("contact[{}]", part);
    for (Index j = starts[part]; j < starts[part + 1]; ++j) {
      if (c.friction == FrictionModel::Coulomb) mu(j) = c.mu;
      if (c.friction != FrictionModel::Tresca) continue;
      const Point x = point(j);
      s(j) = c.slip_bound(x);
      if (!(s(j) >= 0.0) || !std::isfinite(s(j)))
        throw InputError(fmt::format(
            "{}.slip_bound = \"{}\" is {} at ({:g}, {:g}, {:g}): expected a finite value >= 0",
            where, c.slip_bound_text, s(j), x(0), x(1), x(2)));
    }
  }
  auto law =
      std::make_shared<const FrictionLaw>(dim, std::move(s), std::move(mu), std::move(kinds));
  // Where the options' path takes this law (semismooth Newton's friction solver runs in one
  // process): the table's refusal, before the solve (method_table.hpp).
  validate_path(spec.solver, engine, law_kind(*law), law->name());
  return law;
}

Vector free_loads(const Mesh& mesh, const DofMap& dofs, const ElasticityOptions& elasticity,
                  const Vector& f, const Vector& u_d) {
  if (!dofs.has_prescribed_values()) return f;
  const Vector own = u_d.size() != 0 ? Vector() : dofs.prescribed_values();
  const Vector& values = u_d.size() != 0 ? u_d : own;
  // K u_D formed only in the cells that touch a nonzero prescribed value.
  const auto touches = [&](Index cell) {
    for (const Index node : mesh.cell(cell))
      for (int k = 0; k < mesh.dim(); ++k)
        if (values(node * mesh.dim() + k) != 0.0) return true;
    return false;
  };
  return f - internal_forces(mesh, elasticity, values, touches);
}

void require_implied_dimension(const ProblemSpec& spec, int dim) {
  if (const ImpliedDimension& d = spec.implied_dimension; d.dimension != 0 && d.dimension != dim)
    throw InputError(fmt::format(
        "{} gives {} ({}D problems only), but the mesh{} is {}D: expected {}", d.key, d.given,
        d.dimension, spec.mesh_type == MeshType::Gmsh ? " '" + spec.mesh_file + "'" : "", dim,
        d.instead));
}

std::vector<int> load_group_of_dofs(const std::vector<LoadGroup>& groups, Index num_dofs) {
  std::vector<int> group_of_dof;  // the last entry that holds a dof wins (prescribed_scales)
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (const Index d : groups[g].prescribed_dofs) {
      if (group_of_dof.empty()) group_of_dof.assign(static_cast<std::size_t>(num_dofs), -1);
      group_of_dof[static_cast<std::size_t>(d)] = static_cast<int>(g);
    }
  return group_of_dof;
}

bool uses_multigrid(const ContactSolverOptions& options) {
  return options.linear.type == LinearSolverType::ConjugateGradient &&
         options.linear.preconditioner == PreconditionerType::Multigrid;
}

SolverPlan plan_model_solver(const ProblemSpec& spec, const ProblemSize& size,
                             const DistributedEngine* distributed) {
  SolverPlan plan = plan_solver(spec.solver, size);
  // On the distributed path the plan's choice names how the Newton systems are solved there
  // (docs/distributed.md: a direct choice becomes MUMPS, the multigrid GAMG), not the path.
  if (distributed != nullptr)
    plan.reason =
        fmt::format("distributed on {} MPI ranks; the Newton systems as the serial plan chose: {}",
                    distributed->size(), plan.reason);
  return plan;
}

ElasticityOptions region_elasticity(const ProblemSpec& spec,
                                    const std::vector<std::string>& names) {
  // Materials per region, by the regions' names.
  ElasticityOptions elasticity = spec.elasticity;
  for (const RegionMaterialSpec& m : spec.region_materials) {
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
  return elasticity;
}

namespace {

Model build_whole_model(const ProblemSpec& spec, RootAnnouncements* parts,
                        DistributedEngine* engine);

}  // namespace

// Every builder below gives the problem its engine (ContactProblem::engine), where it makes it.
Model build_model(const ProblemSpec& spec, DistributedEngine* engine_or_null) {
  validate(spec.elasticity.material);
  validate(spec.solver);
  validate_path(spec.solver, engine_or_null);
  if (spec.clamps.empty() && spec.displacements.empty())
    throw InputError(
        "no clamped boundary: the stiffness would be singular (add a [[clamp]] or "
        "[[displacement]] section)");
  if (spec.contacts.empty()) throw InputError("no contact boundary (add a [contact] section)");
  require_loads_off_contact(spec);
  // The distributed path (docs/distributed.md) is the options' choice alone: the size-based plan
  // never changes it. On more than one rank, rank 0 alone reads the mesh and sends each other
  // rank its part (problem/distributed_model.hpp).
  if (distributed_path(engine_or_null, spec.solver)) {
    DistributedEngine& engine = *engine_or_null;  // (distributed_path: not null)
    if (engine.size() > 1) {
      // A box is made in parts, each rank its own (problem/box_model_in_parts.hpp).
      if (box_in_parts(spec, engine.size())) return build_box_model_in_parts(spec, engine);
      if (engine.rank() != 0) return receive_model_part(spec, engine);
      RootAnnouncements parts(engine);
      try {
        return build_whole_model(spec, &parts, engine_or_null);
      } catch (const std::exception& e) {
        parts.failed(e.what());
        throw;
      }
    }
  }
  return build_whole_model(spec, nullptr, engine_or_null);
}

namespace {

// Model::contact_gap_shift and its groups, from the whole mesh's numbering.
std::pair<Eigen::MatrixXd, std::vector<int>> contact_gap_shift(
    const ContactSet& c, const DofMap& dofs, const std::vector<LoadGroup>& groups) {
  if (!dofs.has_prescribed_values()) return {};
  const int dim = dofs.dim();
  const std::vector<int> group_of_dof = load_group_of_dofs(groups, dofs.num_dofs());
  Eigen::MatrixXd shift(dim, c.size());
  std::vector<int> group(static_cast<std::size_t>(dim * c.size()), -1);
  for (Index j = 0; j < c.size(); ++j) {
    const Index node = c.nodes[static_cast<std::size_t>(j)];
    for (int k = 0; k < dim; ++k) {
      Eigen::VectorXd axis = Eigen::VectorXd::Unit(dim, k);
      if (dofs.has_frame(node)) axis = dofs.frame(node).col(k);
      shift(k, j) = c.normals.col(j).dot(axis) * dofs.value(node, k);
      if (!group_of_dof.empty())
        group[static_cast<std::size_t>(j * dim + k)] =
            group_of_dof[static_cast<std::size_t>(node * dim + k)];
    }
  }
  return {std::move(shift), std::move(group)};
}

// The model of a serial run, or rank 0's of a distributed one (`parts`: then whole but for the
// stiffness, and the others' parts sent).
Model build_whole_model(const ProblemSpec& spec, RootAnnouncements* parts,
                        DistributedEngine* engine_or_null) {
  TimingTable timings;
  ScopedTimer mesh_timer(timings, "mesh");
  if (spec.mesh_type == MeshType::Given && !spec.given_mesh)
    throw InputError("mesh type \"given\" without a mesh (ProblemSpec::given_mesh)");
  Mesh mesh = spec.mesh_type == MeshType::Gmsh    ? read_mesh_file(spec.mesh_file)
              : spec.mesh_type == MeshType::Given ? Mesh(*spec.given_mesh)
              : spec.mesh_type == MeshType::Box   ? make_box_mesh(spec.box)
                                                  : make_rectangle_mesh(spec.mesh);
  // A problem file on a Gmsh mesh gives points and vectors with as many components as it
  // chooses; now that the mesh is read, they must match it.
  require_implied_dimension(spec, mesh.dim());
  const ElasticityOptions elasticity = region_elasticity(spec, mesh.region_names());
  std::vector<int> owner;
  // A mesh from a file (or a program) comes in its generator's order; its unknowns are numbered
  // along the Z-order curve instead, so that each product with the stiffness finds a row's
  // columns near each other in memory (fem/node_ordering.hpp). The generated meshes are numbered
  // row by row already. The mesh's own node numbers, and so the result files, stay as they are.
  DofMap dofs = number_dofs(mesh, spec.clamps, spec.displacements, owner,
                            is_structured(spec.mesh_type) ? std::vector<Index>{} : z_order(mesh));
  mesh_timer.stop();
  if (dofs.num_free() == 0) throw InputError("every dof is clamped: nothing to solve");
  require_no_free_rigid_motion(mesh, dofs);
  if (parts != nullptr) parts->ok();

  const bool distributed = distributed_path(engine_or_null, spec.solver);
  ContactProblem problem;
  problem.engine = engine_or_null;
  if (distributed) {
    DistributedEngine& engine = *engine_or_null;
    // The nodes partitioned by the engine's graph partitioner (parallel/node_partition.hpp),
    // and the unknowns numbered again rank by rank; the even split of the numbering where the
    // partitioner leaves a rank without unknowns (or on one rank). Rank 0 makes each rank's
    // rows of the graph in turn and sends them (never the whole graph at once).
    if (engine.size() > 1) {
      ScopedTimer t(timings, "partition");
      NodePartition p;
      {
        const NodeGraph own = send_node_graph_rows(NodeGraphRows(mesh, dofs), engine);
        const std::vector<int> rank_of = engine.partition(own, spec.solver.petsc_options);
        p = partition_order(own, dofs, rank_of, engine.size());
      }
      parts->owe();
      if (!p.row_starts.empty()) {
        dofs = number_dofs(mesh, spec.clamps, spec.displacements, owner, p.node_order);
        problem.row_starts = p.row_starts;
      }
    }
    problem.node_of_unknown = free_dof_nodes(dofs);
    if (problem.row_starts.empty())
      problem.row_starts = row_partition(dofs.num_free(), engine.size(), problem.node_of_unknown,
                                         SparseMatrix(0, dofs.num_free()));
    problem.rank = engine.rank();
  }
  if (parts != nullptr && model_parts_support(spec, /*numbered_whole=*/true)) {
    // Rank 0 of several, where the model can be made in parts (problem/model_in_parts.hpp):
    // it checks the cells for all (an inverted one stops every rank with its one message),
    // sends each rank its part of the mesh and that part's numbering, lets the whole go, and
    // builds its own model from its part, as the others do.
    DistributedEngine& engine = *engine_or_null;
    {
      ScopedTimer t(timings, "assembly");
      require_valid_cells(mesh, elasticity);
    }
    const std::map<std::string, std::vector<Index>> orders = contact_orders(spec, mesh);
    parts->ok();
    std::vector<char> own;
    {
      ScopedTimer t(timings, "mesh");
      own = send_mesh_parts(mesh, dofs, owner, problem, orders, engine);
    }
    {
      const Mesh whole_mesh = std::move(mesh);
      const DofMap whole_dofs = std::move(dofs);
      const ContactProblem whole_problem = std::move(problem);
      owner = {};
    }
    return model_from_mesh_part(spec, std::move(own), engine, std::move(timings));
  }
  if (parts != nullptr) {
    // Rank 0 of several assembles no cell here (each rank its own, from its part), but finds an
    // inverted cell for all of them: then every rank stops with its one message.
    ScopedTimer t(timings, "assembly");
    require_valid_cells(mesh, elasticity);
  } else {
    ScopedTimer t(timings, "assembly");
    if (distributed) {
      const DistributedEngine& engine = *engine_or_null;
      // A distributed run (docs/distributed.md): each rank assembles only the columns of the
      // unknowns it owns (by symmetry its rows), from the cells that touch its nodes; the
      // partition keeps each node's unknowns on one rank.
      const auto rank = static_cast<std::size_t>(engine.rank());
      std::vector<bool> owned(static_cast<std::size_t>(mesh.num_nodes()), false);
      for (Index i = problem.row_starts[rank]; i < problem.row_starts[rank + 1]; ++i)
        owned[static_cast<std::size_t>(problem.node_of_unknown[static_cast<std::size_t>(i)])] =
            true;
      problem.A = assemble_stiffness(mesh, dofs, elasticity, &owned);
    } else {
      problem.A = assemble_stiffness(mesh, dofs, elasticity);
    }
  }
  Vector loads = Vector::Zero(dofs.num_dofs());
  Vector whole_b;                     // rank 0 of several: b, and each group's,
  std::vector<Vector> whole_group_b;  // for the others' rows
  std::vector<PlacedPointLoad> placed;
  std::vector<LoadGroup> groups;
  {
    ScopedTimer t(timings, "loads");
    // Where an entry's loads go: a group of its own when it has load factors of its own, so
    // that each step of a loading history can scale it alone (Model::free_loads).
    const auto into = [&](const std::vector<double>& factors, std::string entry) -> Vector& {
      if (factors.empty()) return loads;
      groups.push_back({std::move(entry), factors, Vector::Zero(dofs.num_dofs()), {}, {}});
      return groups.back().loads;
    };
    add_surface_and_body_loads(spec, mesh, into);
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
      Vector& target = into(pl.factors, fmt::format("point_load[{}]", i));
      for (int k = 0; k < mesh.dim(); ++k) target(p.node * mesh.dim() + k) += pl.force(k);
      placed.push_back(p);
    }
    for (std::size_t i = 0; i < spec.displacements.size(); ++i) {
      if (spec.displacements[i].factors.empty()) continue;
      LoadGroup g{fmt::format("displacement[{}]", i), spec.displacements[i].factors, {}, {}, {}};
      for (std::size_t d = 0; d < owner.size(); ++d)
        if (owner[d] == static_cast<int>(spec.clamps.size() + i))
          g.prescribed_dofs.push_back(static_cast<Index>(d));
      groups.push_back(std::move(g));
    }
    // The free loads b = f - K u_D: nonzero prescribed displacements u_D load the free dofs (K
    // u_D formed only in the cells that touch a prescribed value), and the full solution is u_D
    // plus the free part (DofMap::expand). b is linear in f and u_D: each group's part is kept
    // for the steps of a loading history.
    const auto free_part = [&](const Vector& f, const Vector& u_d) -> Vector {
      return dofs.restrict_to_free(free_loads(mesh, dofs, elasticity, f, u_d));
    };
    for (LoadGroup& g : groups) {
      Vector scales = Vector::Zero(dofs.num_dofs());
      for (const Index d : g.prescribed_dofs) scales(d) = 1.0;
      const Vector u_d = dofs.prescribed_values(scales);
      Vector b =
          free_part(g.loads.size() != 0 ? g.loads : Vector(Vector::Zero(dofs.num_dofs())), u_d);
      g.b = problem.held_rows(b);
      if (parts != nullptr) whole_group_b.push_back(std::move(b));
      if (g.loads.size() != 0) loads += g.loads;
    }
    // (A distributed run keeps its own rows of b: ContactProblem.)
    Vector b = free_part(loads, dofs.prescribed_values());
    problem.b = problem.held_rows(b);
    if (parts != nullptr) whole_b = std::move(b);
  }
  std::vector<std::string> contact_boundaries;
  std::vector<Index> contact_starts{0};
  {
    ScopedTimer t(timings, "contact set");
    for (const ContactSpec& c : spec.contacts) {
      RigidObstacle o = c.obstacle;
      if (o.shape == ObstacleShape::Gap) o.gap = c.gap;
      append_contact_set(problem.contact, make_contact_set(mesh, mesh.boundary_part(c.boundary),
                                                           dofs, o, c.surface_normal));
      contact_boundaries.push_back(c.boundary);
      contact_starts.push_back(problem.contact.size());
    }
  }
  // Friction: the tangential rows in N and the law per node (friction_law.hpp).
  std::shared_ptr<const FrictionLaw> friction =
      make_friction(spec, mesh, dofs, contact_starts, problem.contact, engine_or_null);
  // The solver path from the problem's size (solver_plan.hpp), before the hierarchy that it may
  // call for.
  const ProblemSize size{mesh.dim(),
                         mesh.num_nodes(),
                         dofs.num_free(),
                         problem.contact.size(),
                         physical_memory_bytes(),
                         friction != nullptr};
  problem.law = friction;  // (the problem owns its law: contact_law.hpp)
  const SolverPlan plan = plan_model_solver(spec, size, distributed ? engine_or_null : nullptr);
  MultigridHierarchy multigrid;
  const bool multigrid_cg = uses_multigrid(plan.options);
  if (distributed) {
    // PETSc's algebraic multigrid builds its own levels, from the rigid-body modes.
    // (Each rank its own rows: 6 numbers per unknown in 3D; on several ranks from its part.)
    if (multigrid_cg && parts == nullptr)
      problem.near_null_space =
          rigid_body_modes(mesh, dofs, problem.first_row(), problem.end_row());
  } else if (multigrid_cg) {
    ScopedTimer t(timings, "multigrid hierarchy");
    // (The plan changes neither the coarsening nor the smoother, which the hierarchy reads from
    // the spec.)
    multigrid = make_model_hierarchy(spec, mesh, dofs, problem.A);
    // (Of the tentative prolongation, the rows of the contact nodes' unknowns.)
    keep_contact_rows(multigrid, problem.contact.N, free_dof_nodes(dofs));
  }
  std::vector<ClampedPart> clamps = clamped_parts(spec.clamps, spec.displacements, owner);
  auto gap_shifts = contact_gap_shift(problem.contact, dofs, groups);
  const auto whole_model = [&] {
    return Model{.mesh = std::move(mesh),
                 .dofs = std::move(dofs),
                 .problem = std::move(problem),
                 .multigrid = std::move(multigrid),
                 .solver = plan.options,
                 .solver_reason = plan.reason,
                 .timings = std::move(timings),
                 .elasticity = elasticity,
                 .loads = std::move(loads),
                 .clamped_parts = std::move(clamps),
                 .point_loads = std::move(placed),
                 .contact_boundaries = std::move(contact_boundaries),
                 .contact_starts = std::move(contact_starts),
                 .load_groups = std::move(groups),
                 .contact_gap_shift = std::move(gap_shifts.first),
                 .contact_gap_shift_group = std::move(gap_shifts.second),
                 .global_nodes = {},
                 .whole = {},
                 .node_ranks = {}};
  };
  if (parts == nullptr) return whole_model();
  // Rank 0 of several: the others' parts sent, its own model is its part too, as theirs are;
  // the whole model goes before rank 0 builds its part.
  const DistributedEngine& engine = *engine_or_null;
  std::vector<char> everyone, own;
  TimingTable so_far;
  std::vector<PlacedPointLoad> point_loads;
  {
    const Model whole = whole_model();
    parts->ok();
    own = send_model_parts(whole, friction.get(), whole_b, whole_group_b, size, engine, everyone);
    so_far = whole.timings;
    point_loads = whole.point_loads;
  }
  whole_b = {};
  whole_group_b = {};
  owner = {};
  // (A failure from here is rank 0's alone, as on the other ranks: receive_model_part.)
  try {
    Model part = model_from_part(spec, std::move(own), std::move(everyone), *engine_or_null,
                                 std::move(so_far));
    part.point_loads = std::move(point_loads);
    return part;
  } catch (const InputError& e) {
    throw std::runtime_error(fmt::format("building this rank's part of the model: {}", e.what()));
  }
}

}  // namespace

namespace {

// Group g's factor in the state (factor, step) (model.hpp).
double group_factor(const LoadGroup& g, double factor, int step) {
  if (step <= 0) return factor;
  if (static_cast<std::size_t>(step) > g.factors.size())
    throw InputError(fmt::format("{}.factors: no load factor for step {} (it has {})", g.entry,
                                 step, g.factors.size()));
  return g.factors[static_cast<std::size_t>(step - 1)];
}

}  // namespace

Vector Model::prescribed_scales(double factor, int step) const {
  Vector s = Vector::Constant(dofs.num_dofs(), factor);
  for (const LoadGroup& g : load_groups) {
    const double t = group_factor(g, factor, step);
    for (const Index d : g.prescribed_dofs) s(d) = t;
  }
  return s;
}

// Each is linear in the loads and u_D: the whole at `factor`, and each group's part moved from
// `factor` to its own.
Vector Model::applied_loads(double factor, int step) const {
  Vector f = factor * loads;
  for (const LoadGroup& g : load_groups)
    if (g.loads.size() != 0) f += (group_factor(g, factor, step) - factor) * g.loads;
  return f;
}

Vector Model::free_loads(double factor, int step) const {
  Vector b = factor * problem.b;
  for (const LoadGroup& g : load_groups) b += (group_factor(g, factor, step) - factor) * g.b;
  return b;
}

Vector Model::contact_gaps(double factor, int step) const {
  const ContactSet& c = problem.contact;
  if (contact_gap_shift.size() == 0) return c.gaps;
  // The gaps are g - nu . u_D at the node (interface/contact_boundary.cpp): at scaled u_D they grow
  // by nu . (u_D - u_D scaled), a sum over the node's components (contact_gap_shift).
  Vector gaps = c.gaps;
  const auto dim = contact_gap_shift.rows();
  for (Index j = 0; j < c.size(); ++j)
    for (Index k = 0; k < dim; ++k) {
      const int g = contact_gap_shift_group[static_cast<std::size_t>(j * dim + k)];
      const double s =
          g < 0 ? factor : group_factor(load_groups[static_cast<std::size_t>(g)], factor, step);
      gaps(j) += contact_gap_shift(k, j) * (1.0 - s);
    }
  return gaps;
}

Index Model::local_node(Index node) const {
  if (global_nodes.empty()) return node;
  const auto it = std::lower_bound(global_nodes.begin(), global_nodes.end(), node);
  return it != global_nodes.end() && *it == node ? static_cast<Index>(it - global_nodes.begin())
                                                 : -1;
}

int Model::node_rank(Index node, const std::vector<Index>& starts) const {
  for (int k = 0; k < dofs.dim(); ++k)
    if (const Index f = dofs.free_index(node, k); f >= 0)
      return static_cast<int>(std::upper_bound(starts.begin(), starts.end(), f) - starts.begin()) -
             1;
  return 0;
}

int Model::cell_rank(Index cell, const std::vector<Index>& starts) const {
  for (const Index node : mesh.cell(cell))
    for (int k = 0; k < dofs.dim(); ++k)
      if (dofs.free_index(node, k) >= 0) return node_rank(node, starts);
  return 0;
}

int Model::node_rank(Index node) const {
  if (!node_ranks.empty()) return node_ranks[static_cast<std::size_t>(node)];
  return problem.partitioned() ? node_rank(node, problem.row_starts) : 0;
}

int Model::cell_rank(Index cell) const {
  if (!node_ranks.empty()) return node_ranks[static_cast<std::size_t>(mesh.cell(cell)[0])];
  return problem.partitioned() ? cell_rank(cell, problem.row_starts) : 0;
}

Vector Model::full_displacement(const Vector& u, double factor, int step) const {
  // (A rank's part of a distributed run's mesh holds its part of the solution:
  // ContactProblem::solution_unknowns.)
  if (problem.part_solution())
    return dofs.expand(u, prescribed_scales(factor, step),
                       [this](Index f) { return problem.solution_index(f); });
  return dofs.expand(u, prescribed_scales(factor, step));
}

const std::string& Model::contact_boundary_of(Index j) const {
  const auto it = std::upper_bound(contact_starts.begin(), contact_starts.end(), j);
  return contact_boundaries.at(static_cast<std::size_t>(it - contact_starts.begin() - 1));
}

}  // namespace signorini

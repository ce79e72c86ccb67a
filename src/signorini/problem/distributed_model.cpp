#include "signorini/problem/distributed_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <stdexcept>

#include "signorini/core/error.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/parallel/byte_message.hpp"
#include "signorini/problem/model_in_parts.hpp"
#include "signorini/problem/model_part.hpp"

namespace signorini {

namespace {

// The announcement's bytes: empty when rank 0 went on, else its message.
void expect_root_went_on(const DistributedEngine& engine) {
  std::vector<char> bytes;
  engine.broadcast(bytes);
  if (!bytes.empty()) throw InputError(std::string(bytes.begin(), bytes.end()));
}

}  // namespace

void RootAnnouncements::ok() {
  std::vector<char> none;
  engine_.broadcast(none);
  owed_ = false;
}

void RootAnnouncements::failed(const std::string& message) {
  if (!owed_) return;
  owed_ = false;
  const std::string text = message.empty() ? std::string("rank 0 failed") : message;
  std::vector<char> bytes(text.begin(), text.end());
  engine_.broadcast(bytes);
}

NodeGraph send_node_graph_rows(const NodeGraphRows& rows, const DistributedEngine& engine) {
  const int ranks = engine.size();
  for (int r = 1; r < ranks; ++r) {
    ByteWriter out;
    pack(out, rows.rows(r, ranks, /*with_nodes=*/false));  // (the partitioner needs no nodes)
    engine.send_from_root(r, out.bytes());
  }
  return rows.rows(0, ranks);
}

namespace {

// The full dofs of `nodes` (increasing whole-mesh numbers) in a vector of the whole mesh's full
// dofs; empty stays empty.
Vector nodes_rows(const Vector& full, const std::vector<Index>& nodes, int dim) {
  if (full.size() == 0) return {};
  Vector out(static_cast<Index>(nodes.size()) * dim);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    out.segment(static_cast<Index>(i) * dim, dim) = full.segment(nodes[i] * dim, dim);
  return out;
}

// Whole-mesh full dofs in the part's numbering (those of its nodes).
std::vector<Index> part_dofs(const std::vector<Index>& dofs, const std::vector<Index>& nodes,
                             int dim) {
  std::vector<Index> out;
  for (const Index d : dofs) {
    const auto it = std::lower_bound(nodes.begin(), nodes.end(), d / dim);
    if (it != nodes.end() && *it == d / dim)
      out.push_back(static_cast<Index>(it - nodes.begin()) * dim + d % dim);
  }
  return out;
}

}  // namespace

std::vector<char> send_model_parts(const Model& model, const FrictionLaw* friction,
                                   const Vector& whole_b, const std::vector<Vector>& whole_group_b,
                                   const ProblemSize& size, const DistributedEngine& engine,
                                   std::vector<char>& everyone) {
  const Mesh& mesh = model.mesh;
  const DofMap& dofs = model.dofs;
  const ContactProblem& p = model.problem;
  const int dim = mesh.dim();
  const std::vector<int> group_of_dof = load_group_of_dofs(model.load_groups, dofs.num_dofs());
  std::vector<char> own_part;
  {
    PartCells part_cells(mesh);
    // Rank 0 accounts for the nodes without a free dof (Model::node_rank) and writes the cells
    // without one: its part has the cells around them too.
    std::vector<Index> held;
    for (Index v = 0; v < mesh.num_nodes(); ++v) {
      bool any = false;
      for (int k = 0; k < dim; ++k) any = any || dofs.free_index(v, k) >= 0;
      if (!any) held.push_back(v);
    }
    for (int r = 0; r < engine.size(); ++r) {
      const Index first = p.row_starts[static_cast<std::size_t>(r)];
      const Index last = p.row_starts[static_cast<std::size_t>(r) + 1];
      std::vector<Index> own;
      for (Index i = first; i < last; ++i) {
        const Index node = p.node_of_unknown[static_cast<std::size_t>(i)];
        if (own.empty() || own.back() != node) own.push_back(node);
      }
      if (r == 0) own.insert(own.end(), held.begin(), held.end());
      const MeshPart part = mesh_part(mesh, part_cells.cells(own));
      const std::vector<Index>& nodes = part.global_nodes;
      ByteWriter out;
      pack(out, part.mesh);
      out.put(nodes);
      pack(out, dofs.part(nodes));
      out.put(Vector(whole_b.segment(first, last - first)));
      out.put(
          std::vector<Index>(p.node_of_unknown.begin() + first, p.node_of_unknown.begin() + last));
      out.put(nodes_rows(model.loads, nodes, dim));
      for (const ClampedPart& c : model.clamped_parts) out.put(part_dofs(c.dofs, nodes, dim));
      // Each group's prescribed dofs in the part's numbering.
      std::vector<std::vector<Index>> prescribed(model.load_groups.size());
      if (!group_of_dof.empty())
        for (std::size_t i = 0; i < nodes.size(); ++i)
          for (int k = 0; k < dim; ++k)
            if (const int g = group_of_dof[static_cast<std::size_t>(nodes[i] * dim + k)]; g >= 0)
              prescribed[static_cast<std::size_t>(g)].push_back(static_cast<Index>(i) * dim + k);
      for (std::size_t g = 0; g < model.load_groups.size(); ++g) {
        out.put(Vector(whole_group_b[g].segment(first, last - first)));
        out.put(prescribed[g]);
        out.put(nodes_rows(model.load_groups[g].loads, nodes, dim));
      }
      if (r == 0)
        own_part = std::move(out.bytes());
      else
        engine.send_from_root(r, out.bytes());
    }
  }
  // What every rank holds whole.
  ByteWriter out;
  out.put(p.row_starts);
  pack(out, p.contact);
  out.put(model.contact_starts);
  out.put(model.contact_boundaries);
  out.put(static_cast<std::uint8_t>(friction != nullptr));
  if (friction != nullptr) {
    out.put(friction->slip_bound());
    out.put(friction->mu());
  }
  out.put_matrix(model.contact_gap_shift);
  out.put(model.contact_gap_shift_group);
  out.put(static_cast<std::int32_t>(size.dimension));
  out.put(static_cast<std::int64_t>(size.nodes));
  out.put(static_cast<std::int64_t>(size.free_unknowns));
  out.put(static_cast<std::int64_t>(size.contact_nodes));
  out.put(size.memory_bytes);
  out.put(static_cast<std::uint8_t>(size.friction));
  // The whole mesh's facts (WholeMesh).
  const Vector centroid = mesh.coordinates().rowwise().mean();
  double radius = 0.0;
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    radius = std::max(radius, (mesh.node(v) - centroid).norm());
  Eigen::MatrixXd contact_points(dim, p.contact.size()), contact_prescribed(dim, p.contact.size());
  for (Index j = 0; j < p.contact.size(); ++j) {
    const Index node = p.contact.nodes[static_cast<std::size_t>(j)];
    contact_points.col(j) = mesh.node(node);
    contact_prescribed.col(j) = dofs.prescribed_at(node);
  }
  out.put(centroid);
  out.put(radius);
  out.put_matrix(contact_points);
  out.put_matrix(contact_prescribed);
  std::vector<std::string> clamp_names;
  for (const ClampedPart& c : model.clamped_parts) clamp_names.push_back(c.boundary);
  out.put(clamp_names);
  out.put(static_cast<std::uint64_t>(model.load_groups.size()));
  for (const LoadGroup& g : model.load_groups) {
    out.put(g.entry);
    out.put(g.factors);
  }
  everyone = std::move(out.bytes());
  engine.broadcast(everyone);
  return own_part;
}

std::map<std::string, std::vector<Index>> contact_orders(const ProblemSpec& spec,
                                                         const Mesh& mesh) {
  std::map<std::string, std::vector<Index>> out;
  if (mesh.dim() != 2) return out;
  for (const ContactSpec& c : spec.contacts)
    out[c.boundary] =
        boundary_nodes(mesh, mesh.boundary_part(c.boundary), "contact.boundary").nodes;
  return out;
}

std::vector<char> send_mesh_parts(const Mesh& mesh, const DofMap& dofs,
                                  const std::vector<int>& owner, const ContactProblem& problem,
                                  const std::map<std::string, std::vector<Index>>& contact_orders,
                                  const DistributedEngine& engine) {
  const int dim = mesh.dim(), ranks = engine.size();
  const Index nodes = mesh.num_nodes();
  PartCells part_cells(mesh);
  // The rank of each node: that of its unknowns; a node without one goes with a free node of one
  // of its cells, so that its cells are near that rank's (rank 0 where none has one).
  std::vector<int> node_rank(static_cast<std::size_t>(nodes), -1);
  for (int r = 0; r < ranks; ++r)
    for (Index i = problem.row_starts[static_cast<std::size_t>(r)];
         i < problem.row_starts[static_cast<std::size_t>(r) + 1]; ++i)
      node_rank[static_cast<std::size_t>(problem.node_of_unknown[static_cast<std::size_t>(i)])] = r;
  {
    std::vector<int> held_rank(static_cast<std::size_t>(nodes), -1);
    for (Index v = 0; v < nodes; ++v) {
      if (node_rank[static_cast<std::size_t>(v)] >= 0) continue;
      int& r = held_rank[static_cast<std::size_t>(v)];
      for (const Index c : part_cells.node_cells().of(v)) {
        for (const Index w : mesh.cell(c))
          if (node_rank[static_cast<std::size_t>(w)] >= 0) {
            r = node_rank[static_cast<std::size_t>(w)];
            break;
          }
        if (r >= 0) break;
      }
      if (r < 0) r = 0;
    }
    for (Index v = 0; v < nodes; ++v)
      if (node_rank[static_cast<std::size_t>(v)] < 0)
        node_rank[static_cast<std::size_t>(v)] = held_rank[static_cast<std::size_t>(v)];
  }
  std::vector<std::vector<Index>> own(static_cast<std::size_t>(ranks));
  for (Index v = 0; v < nodes; ++v)
    own[static_cast<std::size_t>(node_rank[static_cast<std::size_t>(v)])].push_back(v);
  // Each contact side's nodes (2D) with their places, by node, to look up.
  std::map<std::string, std::vector<std::pair<Index, Index>>> places;
  for (const auto& [name, order] : contact_orders) {
    std::vector<std::pair<Index, Index>>& p = places[name];
    for (std::size_t i = 0; i < order.size(); ++i) p.emplace_back(order[i], static_cast<Index>(i));
    std::sort(p.begin(), p.end());
  }
  // The boundary parts' facets by cell (side, place in the side), once: each rank's are then
  // found from its cells alone.
  const std::vector<std::string> names = mesh.boundary_part_names();
  std::vector<Index> facets_start(static_cast<std::size_t>(mesh.num_cells()) + 1, 0);
  std::vector<std::pair<int, Index>> facets_of_cell;
  {
    for (const std::string& name : names)
      for (const Facet& f : mesh.boundary_part(name).facets)
        ++facets_start[static_cast<std::size_t>(f.cell) + 1];
    for (std::size_t c = 0; c + 1 < facets_start.size(); ++c)
      facets_start[c + 1] += facets_start[c];
    facets_of_cell.resize(static_cast<std::size_t>(facets_start.back()));
    std::vector<Index> next(facets_start.begin(), facets_start.end() - 1);
    for (std::size_t side = 0; side < names.size(); ++side) {
      const std::vector<Facet>& facets = mesh.boundary_part(names[side]).facets;
      for (std::size_t f = 0; f < facets.size(); ++f)
        facets_of_cell[static_cast<std::size_t>(next[static_cast<std::size_t>(facets[f].cell)]++)] =
            {static_cast<int>(side), static_cast<Index>(f)};
    }
  }
  std::vector<char> own_bytes;
  for (int r = 0; r < ranks; ++r) {
    const std::vector<Index> cells = part_cells.cells(own[static_cast<std::size_t>(r)]);
    own[static_cast<std::size_t>(r)] = {};
    const MeshPart part = mesh_part(mesh, cells);
    const std::vector<Index>& global = part.global_nodes;
    ByteWriter out;
    pack(out, part.mesh);
    out.put(global);
    std::vector<int> ranks_of_part;
    ranks_of_part.reserve(global.size());
    for (const Index g : global) ranks_of_part.push_back(node_rank[static_cast<std::size_t>(g)]);
    out.put(ranks_of_part);
    // Each boundary part's facets in the part (their cells in the part's numbering), in the
    // whole part's order, with their places there.
    std::vector<std::vector<std::pair<Index, Index>>> in_part(names.size());  // (place, cell)
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const auto c = static_cast<std::size_t>(cells[i]);
      for (auto e = facets_start[c]; e < facets_start[c + 1]; ++e) {
        const auto& [side, place] = facets_of_cell[static_cast<std::size_t>(e)];
        in_part[static_cast<std::size_t>(side)].emplace_back(place, static_cast<Index>(i));
      }
    }
    out.put(names);
    for (std::size_t side = 0; side < names.size(); ++side) {
      std::vector<std::pair<Index, Index>>& kept = in_part[side];
      std::sort(kept.begin(), kept.end());
      const std::vector<Facet>& facets = mesh.boundary_part(names[side]).facets;
      std::vector<Index> facet_cells, keys;
      std::vector<int> locals;
      for (const auto& [place, cell] : kept) {
        facet_cells.push_back(cell);
        locals.push_back(facets[static_cast<std::size_t>(place)].local);
        keys.push_back(place);
      }
      out.put(facet_cells);
      out.put(locals);
      out.put(keys);
    }
    out.put(static_cast<std::uint64_t>(places.size()));
    for (const auto& [name, p] : places) {
      std::vector<Index> part_nodes, keys;
      for (std::size_t i = 0; i < global.size(); ++i) {
        const auto it =
            std::lower_bound(p.begin(), p.end(), std::pair<Index, Index>{global[i], -1});
        if (it == p.end() || it->first != global[i]) continue;
        part_nodes.push_back(static_cast<Index>(i));
        keys.push_back(it->second);
      }
      out.put(name);
      out.put(part_nodes);
      out.put(keys);
    }
    pack(out, dofs.part(global));
    std::vector<int> entries;
    entries.reserve(global.size() * static_cast<std::size_t>(dim));
    for (const Index g : global)
      for (int k = 0; k < dim; ++k) entries.push_back(owner[static_cast<std::size_t>(g * dim + k)]);
    out.put(entries);
    out.put(problem.row_starts);
    const Index first = problem.row_starts[static_cast<std::size_t>(r)];
    const Index last = problem.row_starts[static_cast<std::size_t>(r) + 1];
    out.put(std::vector<Index>(problem.node_of_unknown.begin() + first,
                               problem.node_of_unknown.begin() + last));
    if (r == 0)
      own_bytes = std::move(out.bytes());
    else
      engine.send_from_root(r, out.bytes());
  }
  return own_bytes;
}

Model model_from_mesh_part(const ProblemSpec& spec, std::vector<char> bytes,
                           DistributedEngine& engine, TimingTable timings) {
  ScopedTimer mesh_timer(timings, "mesh");
  ByteReader in(bytes);
  Mesh mesh = unpack_mesh(in);
  std::vector<Index> global_nodes = in.get_vector<Index>();
  std::vector<int> node_ranks = in.get_vector<int>();
  std::map<std::string, std::vector<Index>> facet_keys;
  for (const std::string& name : in.get_strings()) {
    const std::vector<Index> cells = in.get_vector<Index>();
    const std::vector<int> locals = in.get_vector<int>();
    std::vector<Facet> facets;
    for (std::size_t f = 0; f < cells.size(); ++f) facets.push_back({cells[f], locals.at(f)});
    mesh.set_boundary_part(name, std::move(facets));
    facet_keys[name] = in.get_vector<Index>();
  }
  std::map<std::string, std::vector<std::pair<Index, Index>>> node_keys;
  for (auto sides = in.get<std::uint64_t>(); sides > 0; --sides) {
    std::vector<std::pair<Index, Index>>& keys = node_keys[in.get_string()];
    const std::vector<Index> part_nodes = in.get_vector<Index>();
    const std::vector<Index> places = in.get_vector<Index>();
    for (std::size_t i = 0; i < part_nodes.size(); ++i)
      keys.emplace_back(part_nodes[i], places.at(i));
  }
  DofMap dofs = unpack_dof_map(in);
  std::vector<int> entry = in.get_vector<int>();
  std::vector<Index> row_starts = in.get_vector<Index>();
  std::vector<Index> node_of_unknown = in.get_vector<Index>();
  if (!in.done()) throw std::logic_error("a part of the mesh from rank 0 has a mismatched layout");
  bytes = {};
  mesh_timer.stop();
  OwnPart own{std::move(mesh),       std::move(global_nodes),
              std::move(node_ranks), std::move(facet_keys),
              std::move(dofs),       std::move(entry),
              std::move(row_starts), std::move(node_of_unknown),
              std::move(node_keys)};
  return model_from_own_part(spec, std::move(own), engine, std::move(timings));
}

Model receive_model_part(const ProblemSpec& spec, DistributedEngine& engine) {
  TimingTable timings;
  ScopedTimer mesh_timer(timings, "mesh");
  expect_root_went_on(engine);  // rank 0 read the mesh and numbered it
  mesh_timer.stop();
  {
    ScopedTimer t(timings, "partition");
    const std::vector<char> bytes = engine.receive_from_root();
    ByteReader in(bytes);
    const NodeGraph graph = unpack_node_graph(in);
    (void)engine.partition(graph, spec.solver.petsc_options);
  }
  expect_root_went_on(engine);  // rank 0 built the whole model but the stiffness (or, in
                                // parts, checked the cells)
  // A model made in parts (model_in_parts.hpp): rank 0 sends the part of the mesh only, and
  // every rank builds its model from it, agreeing on bad input.
  if (model_parts_support(spec, /*numbered_whole=*/true)) {
    ScopedTimer receive_timer(timings, "mesh");
    std::vector<char> part = engine.receive_from_root();
    receive_timer.stop();
    return model_from_mesh_part(spec, std::move(part), engine, std::move(timings));
  }
  // From here a failure is this rank's alone (rank 0 found the input good): not InputError,
  // which the tool takes as every rank's (app/tool.cpp), but one that ends every rank.
  try {
    ScopedTimer receive_timer(timings, "mesh");
    std::vector<char> part = engine.receive_from_root();
    std::vector<char> everyone;
    engine.broadcast(everyone);
    receive_timer.stop();
    return model_from_part(spec, std::move(part), std::move(everyone), engine, std::move(timings));
  } catch (const InputError& e) {
    throw std::runtime_error(fmt::format("building this rank's part of the model: {}", e.what()));
  }
}

Model model_from_part(const ProblemSpec& spec, std::vector<char> part, std::vector<char> everyone,
                      DistributedEngine& engine, TimingTable timings) {
  ScopedTimer receive_timer(timings, "mesh");
  ContactProblem problem;
  problem.engine = &engine;
  ByteReader in(part);
  Mesh mesh = unpack_mesh(in);
  std::vector<Index> global_nodes = in.get_vector<Index>();
  DofMap dofs = unpack_dof_map(in);
  problem.b = in.get_vector_xd();
  problem.node_of_unknown = in.get_vector<Index>();  // the rank's own unknowns' only
  Vector loads = in.get_vector_xd();
  ByteReader all(everyone);
  problem.row_starts = all.get_vector<Index>();
  problem.contact = unpack_contact_set(all);
  problem.rank = engine.rank();
  std::vector<Index> contact_starts = all.get_vector<Index>();
  std::vector<std::string> contact_boundaries = all.get_strings();
  std::shared_ptr<const FrictionLaw> friction;
  if (all.get<std::uint8_t>() != 0) {
    Vector s = all.get_vector_xd();
    Vector mu = all.get_vector_xd();
    friction = std::make_shared<const FrictionLaw>(mesh.dim(), std::move(s), std::move(mu),
                                                   friction_kinds(spec));
  }
  Eigen::MatrixXd gap_shift = all.get_matrix();
  std::vector<int> gap_shift_group = all.get_vector<int>();
  ProblemSize size;
  size.dimension = all.get<std::int32_t>();
  size.nodes = all.get<std::int64_t>();
  size.free_unknowns = all.get<std::int64_t>();
  size.contact_nodes = all.get<std::int64_t>();
  size.memory_bytes = all.get<double>();
  size.friction = all.get<std::uint8_t>() != 0;
  WholeMesh whole;
  whole.nodes = size.nodes;
  whole.centroid = all.get_vector_xd();
  whole.radius = all.get<double>();
  whole.contact_points = all.get_matrix();
  whole.contact_prescribed = all.get_matrix();
  std::vector<ClampedPart> clamps;
  for (std::string& name : all.get_strings())
    clamps.push_back({std::move(name), in.get_vector<Index>()});
  std::vector<LoadGroup> groups(static_cast<std::size_t>(all.get<std::uint64_t>()));
  for (LoadGroup& g : groups) {
    g.entry = all.get_string();
    g.factors = all.get_vector<double>();
    g.b = in.get_vector_xd();
    g.prescribed_dofs = in.get_vector<Index>();
    g.loads = in.get_vector_xd();
  }
  if (!in.done() || !all.done())
    throw NumericalError("the model's messages from rank 0 have a mismatched layout");
  part = {};
  everyone = {};
  receive_timer.stop();

  const ElasticityOptions elasticity = region_elasticity(spec, mesh.region_names());
  {
    ScopedTimer t(timings, "assembly");
    // The columns of the rank's unknowns (by symmetry its rows), from the cells around its
    // nodes: the part's first layer (problem/model_part.hpp).
    std::vector<bool> owned(static_cast<std::size_t>(mesh.num_nodes()), false);
    for (Index v = 0; v < mesh.num_nodes(); ++v)
      for (int k = 0; k < mesh.dim(); ++k) {
        const Index f = dofs.free_index(v, k);
        if (f >= problem.first_row() && f < problem.end_row())
          owned[static_cast<std::size_t>(v)] = true;
      }
    problem.A = assemble_stiffness(mesh, dofs, elasticity, &owned);
  }
  problem.law = friction;  // (the problem owns its law: contact_law.hpp)
  const SolverPlan plan = plan_model_solver(spec, size, &engine);
  if (uses_multigrid(plan.options))
    problem.near_null_space =
        rigid_body_modes(mesh, dofs, problem.first_row(), problem.end_row(), &whole.centroid);
  // The solution comes back as the part's unknowns only (no vector of all n on any rank).
  problem.solution_unknowns = part_unknowns(dofs);
  Model model{.mesh = std::move(mesh),
              .dofs = std::move(dofs),
              .problem = std::move(problem),
              .multigrid = {},
              .solver = plan.options,
              .solver_reason = plan.reason,
              .timings = std::move(timings),
              .elasticity = elasticity,
              .loads = std::move(loads),
              .clamped_parts = std::move(clamps),
              .point_loads = {},
              .contact_boundaries = std::move(contact_boundaries),
              .contact_starts = std::move(contact_starts),
              .load_groups = std::move(groups),
              .contact_gap_shift = std::move(gap_shift),
              .contact_gap_shift_group = std::move(gap_shift_group),
              .global_nodes = std::move(global_nodes),
              .whole = std::move(whole),
              .node_ranks = {}};
  return model;
}

}  // namespace signorini

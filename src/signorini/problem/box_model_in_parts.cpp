#include "signorini/problem/box_model_in_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

#include "signorini/core/error.hpp"
#include "signorini/core/peak_memory.hpp"
#include "signorini/fem/contact_boundary.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/parallel/box_partition.hpp"
#include "signorini/parallel/byte_message.hpp"
#include "signorini/problem/distributed_model.hpp"

namespace signorini {

bool box_in_parts(const ProblemSpec& spec, int ranks) {
  if (spec.mesh_type != MeshType::Box || spec.solver.partition != PartitionMode::Auto ||
      ranks < 2 || !spec.point_loads.empty() || !spec.body_force_factors.empty())
    return false;
  for (const ClampSpec& c : spec.clamps)
    if (c.at) return false;
  for (const DisplacementSpec& d : spec.displacements)
    if (!d.factors.empty()) return false;
  for (const TractionSpec& t : spec.tractions)
    if (!t.factors.empty()) return false;
  for (const PressureSpec& p : spec.pressures)
    if (!p.factors.empty()) return false;
  for (const ContactSpec& c : spec.contacts)
    if (c.friction != FrictionModel::None) return false;
  return BoxPartition(spec.box, ranks).possible();
}

namespace {

constexpr int kDim = 3;

// Bad input found by some rank: every rank throws the lowest such rank's message, so that all
// stop alike (a collective call).
void agree_on_input(const DistributedEngine& engine, const std::string& message) {
  for (const std::vector<char>& m :
       engine.allgather(std::vector<char>(message.begin(), message.end())))
    if (!m.empty()) throw InputError(std::string(m.begin(), m.end()));
}

// Runs f on this rank and then agrees with the others on whether the input was good.
template <class F>
void on_every_rank(const DistributedEngine& engine, const F& f) {
  std::string error;
  try {
    f();
  } catch (const InputError& e) {
    error = e.what();
    if (error.empty()) error = "bad input";
  }
  agree_on_input(engine, error);
}

// One value per rank, on every rank.
template <typename T>
std::vector<T> values_of_ranks(const DistributedEngine& engine, T value) {
  ByteWriter out;
  out.put(value);
  std::vector<T> all;
  for (const std::vector<char>& bytes : engine.allgather(out.bytes())) {
    ByteReader in(bytes);
    all.push_back(in.get<T>());
  }
  return all;
}

// The lattice points of the box along each axis, and a part's: its first point and count.
struct Lattice {
  std::array<Index, 3> first{}, count{};
  [[nodiscard]] Index index(Index I, Index J, Index K) const {
    return (I - first[0]) + count[0] * ((J - first[1]) + count[1] * (K - first[2]));
  }
};

Lattice part_lattice(const BoxPartition& blocks, int rank, Index order) {
  Lattice l;
  const auto first = blocks.first_part_cube(rank), end = blocks.end_part_cube(rank);
  for (std::size_t a = 0; a < 3; ++a) {
    l.first[a] = order * first[a];
    l.count[a] = order * (end[a] - first[a]) + 1;
  }
  return l;
}

// One contact row as a rank sends it: what the whole contact set and the results need.
struct ContactRow {
  Index node = 0;  // the whole box's
  Index key = 0;   // where the side's facets first name the node (the serial order)
  Eigen::Vector3d normal, point, prescribed;
  double weight = 0.0, gap = 0.0;
  bool movable = false;
  std::vector<std::pair<Index, double>> n;  // N's entries: free dof, value
};

struct ContactFacet {
  Index key = 0;
  std::vector<Index> nodes;  // the whole box's
};

void pack_row(ByteWriter& out, const ContactRow& r) {
  out.put(r.node);
  out.put(r.key);
  for (const Eigen::Vector3d* v : {&r.normal, &r.point, &r.prescribed}) out.put_array(v->data(), 3);
  out.put(r.weight);
  out.put(r.gap);
  out.put(static_cast<std::uint8_t>(r.movable));
  out.put(static_cast<std::uint64_t>(r.n.size()));
  for (const auto& [d, value] : r.n) {
    out.put(d);
    out.put(value);
  }
}

ContactRow unpack_row(ByteReader& in) {
  ContactRow r;
  r.node = in.get<Index>();
  r.key = in.get<Index>();
  for (Eigen::Vector3d* v : {&r.normal, &r.point, &r.prescribed}) {
    const std::vector<double> x = in.get_vector<double>();
    *v = Eigen::Vector3d(x.at(0), x.at(1), x.at(2));
  }
  r.weight = in.get<double>();
  r.gap = in.get<double>();
  r.movable = in.get<std::uint8_t>() != 0;
  r.n.resize(static_cast<std::size_t>(in.get<std::uint64_t>()));
  for (auto& [d, value] : r.n) {
    d = in.get<Index>();
    value = in.get<double>();
  }
  return r;
}

}  // namespace

Model build_box_model_in_parts(const ProblemSpec& spec, DistributedEngine& engine) {
  const int rank = engine.rank(), ranks = engine.size();
  const BoxMeshOptions& box = spec.box;
  const BoxPartition blocks(box, ranks);
  if (!blocks.possible()) throw std::logic_error("build_box_model_in_parts: no grid of blocks");
  const Index order = cell_order(box.cell);
  engine.note_partition(fmt::format("blocks of the box's cubes, {} x {} x {}", blocks.grid()[0],
                                    blocks.grid()[1], blocks.grid()[2]));
  TimingTable timings;  // (each phase's timers add up)

  // Each rank alone: its part of the mesh, the dofs that its nodes' clamps and displacements
  // hold, its loads. Which rigid motions the clamps leave free depends only on which sides hold
  // which components (each side is held whole or not at all, and each has points that span its
  // plane): one cube of the same box answers for the whole.
  std::optional<BoxMeshPart> part;
  std::optional<DofMap> local;
  std::vector<int> entry;  // per full dof of the part, the entry that holds it (number_dofs)
  ElasticityOptions elasticity;
  Vector loads;
  on_every_rank(engine, [&] {
    ScopedTimer mesh_timer(timings, "mesh");
    require_implied_dimension(spec, kDim);
    {
      BoxMeshOptions one = box;
      one.nx = one.ny = one.nz = 1;
      const Mesh cube = make_box_mesh(one);
      std::vector<int> held;
      require_no_free_rigid_motion(cube, number_dofs(cube, spec.clamps, spec.displacements, held));
    }
    part = make_box_mesh_part(box, blocks.first_part_cube(rank), blocks.end_part_cube(rank));
    elasticity = region_elasticity(spec, part->mesh.region_names());
    local = number_dofs(part->mesh, spec.clamps, spec.displacements, entry);
    mesh_timer.stop();
    ScopedTimer t(timings, "loads");
    loads = Vector::Zero(part->mesh.num_nodes() * kDim);
    add_surface_and_body_loads(
        spec, part->mesh,
        [&loads](const std::vector<double>&, const std::string&) -> Vector& { return loads; });
  });
  ScopedTimer mesh_timer(timings, "mesh");
  const Mesh& mesh = part->mesh;
  const std::vector<Index>& global_nodes = part->global_nodes;
  const Index nodes = mesh.num_nodes();
  std::vector<int> node_ranks(static_cast<std::size_t>(nodes));
  for (Index v = 0; v < nodes; ++v)
    node_ranks[static_cast<std::size_t>(v)] =
        blocks.owner(blocks.point(global_nodes[static_cast<std::size_t>(v)]));

  // The free dofs numbered rank by rank, each rank's nodes in the box's order (docs/
  // distributed.md): the counts of the ranks give each its first number.
  Index own_free = 0;
  for (Index v = 0; v < nodes; ++v)
    if (node_ranks[static_cast<std::size_t>(v)] == rank)
      for (int k = 0; k < kDim; ++k) own_free += local->free_index(v, k) >= 0 ? 1 : 0;
  std::vector<Index> row_starts{0};
  for (const Index count : values_of_ranks(engine, own_free))
    row_starts.push_back(row_starts.back() + count);
  if (row_starts.back() == 0) throw InputError("every dof is clamped: nothing to solve");
  const auto dofs_of_part = static_cast<std::size_t>(nodes * kDim);
  std::vector<Index> free(dofs_of_part, -1);
  Vector values = Vector::Zero(static_cast<Index>(dofs_of_part));
  std::vector<Index> node_of_unknown;
  bool own_values = false;  // a nonzero prescribed value at one of the rank's nodes
  {
    Index next = row_starts[static_cast<std::size_t>(rank)];
    for (Index v = 0; v < nodes; ++v) {
      if (node_ranks[static_cast<std::size_t>(v)] != rank) continue;
      for (int k = 0; k < kDim; ++k) {
        const auto d = static_cast<std::size_t>(v * kDim + k);
        values(v * kDim + k) = local->value(v, k);
        own_values = own_values || values(v * kDim + k) != 0.0;
        if (local->free_index(v, k) < 0) continue;
        free[d] = next++;
        node_of_unknown.push_back(global_nodes[static_cast<std::size_t>(v)]);
      }
    }
  }
  local.reset();
  // The other nodes of the part from their owners: each rank sends every other the free
  // numbers, prescribed values and holding entries of its own points in that rank's part, in
  // the box's order, which is the order in which the part lists them.
  {
    const std::array<Index, 3> own_first = blocks.first_point(rank),
                               own_end = blocks.end_point(rank);
    const Lattice mine = part_lattice(blocks, rank, order);
    std::vector<std::vector<char>> to(static_cast<std::size_t>(ranks));
    for (int s = 0; s < ranks; ++s) {
      if (s == rank) continue;
      const Lattice theirs = part_lattice(blocks, s, order);
      std::array<Index, 3> lo{}, hi{};
      bool empty = false;
      for (std::size_t a = 0; a < 3; ++a) {
        lo[a] = std::max(own_first[a], theirs.first[a]);
        hi[a] = std::min(own_end[a], theirs.first[a] + theirs.count[a]);
        empty = empty || lo[a] >= hi[a];
      }
      if (empty) continue;
      ByteWriter out;
      for (Index K = lo[2]; K < hi[2]; ++K)
        for (Index J = lo[1]; J < hi[1]; ++J)
          for (Index I = lo[0]; I < hi[0]; ++I) {
            const Index v = mine.index(I, J, K);
            for (int k = 0; k < kDim; ++k) {
              const auto d = static_cast<std::size_t>(v * kDim + k);
              out.put(free[d]);
              out.put(values(v * kDim + k));
              out.put(static_cast<std::int32_t>(entry[d]));
            }
          }
      to[static_cast<std::size_t>(s)] = std::move(out.bytes());
    }
    const std::vector<std::vector<char>> from = engine.exchange(to);
    for (int r = 0; r < ranks; ++r) {
      if (r == rank) continue;
      ByteReader in(from[static_cast<std::size_t>(r)]);
      for (Index v = 0; v < nodes; ++v) {
        if (node_ranks[static_cast<std::size_t>(v)] != r) continue;
        for (int k = 0; k < kDim; ++k) {
          const auto d = static_cast<std::size_t>(v * kDim + k);
          free[d] = in.get<Index>();
          values(v * kDim + k) = in.get<double>();
          entry[d] = in.get<std::int32_t>();
        }
      }
      if (!in.done())
        throw std::logic_error(fmt::format("box in parts: rank {} sent another set of nodes", r));
    }
  }
  // Whether any node of the box has a nonzero prescribed value (DofMap::has_prescribed_values
  // of the whole, which the gaps' shifts and b follow).
  const bool prescribed = engine.any(own_values);
  DofMap dofs(kDim, std::move(free), row_starts.back(), prescribed ? std::move(values) : Vector());
  mesh_timer.stop();

  ContactProblem problem;
  problem.row_starts = row_starts;
  problem.rank = rank;
  problem.node_of_unknown = std::move(node_of_unknown);
  const Index first_row = problem.first_row(), end_row = problem.end_row();
  // b = f - K u_D on the rank's rows (model.cpp's free part): every cell around its nodes is in
  // its part, in the whole box's order.
  {
    ScopedTimer t(timings, "loads");
    Vector f = loads;
    if (dofs.has_prescribed_values()) {
      const Vector u_d = dofs.prescribed_values();
      const auto touches = [&](Index cell) {
        for (const Index node : mesh.cell(cell))
          for (int k = 0; k < kDim; ++k)
            if (u_d(node * kDim + k) != 0.0) return true;
        return false;
      };
      f -= internal_forces(mesh, elasticity, u_d, touches);
    }
    problem.b = Vector::Zero(end_row - first_row);
    for (Index v = 0; v < nodes; ++v)
      for (int k = 0; k < kDim; ++k)
        if (const Index i = dofs.free_index(v, k); i >= first_row && i < end_row)
          problem.b(i - first_row) = f(v * kDim + k);
  }

  // The contact rows of the rank's nodes, in the order in which the side's facets first name
  // them (fem/contact_boundary.cpp): each rank has every facet around its nodes.
  ScopedTimer contact_timer(timings, "contact set");
  // The gap where a node's normal never meets the obstacle: 10 times the box's extent, as
  // make_contact_set measures it on the whole mesh (its far corner as make_box_mesh_part
  // places it).
  double far = 0.0;
  {
    const std::array<double, 3> size{box.length, box.width, box.height};
    const std::array<double, 3> origin{box.x0, box.y0, box.z0};
    const std::array<Index, 3> n{box.nx, box.ny, box.nz};
    for (std::size_t a = 0; a < 3; ++a) {
      const auto steps = static_cast<double>(order * n[a]);
      far = std::max(far, (origin[a] + size[a] * steps / steps) - origin[a]);
    }
    far *= 10.0;
  }
  const int facets_per = facets_per_cell(box.cell);
  ByteWriter rows_out;
  on_every_rank(engine, [&] {
    for (const ContactSpec& c : spec.contacts) {
      const BoundaryPart& side = mesh.boundary_part(c.boundary);  // InputError on other names
      std::vector<ContactRow> rows;
      std::vector<ContactFacet> facets;
      if (!side.facets.empty()) {
        RigidObstacle o = c.obstacle;
        if (o.shape == ObstacleShape::Gap) o.gap = c.gap;
        const ContactSet cs = make_contact_rows(mesh, side, dofs, o, c.surface_normal, far);
        // The key of each node: its first facet's place in the whole side, and its place there.
        std::vector<Index> key(static_cast<std::size_t>(nodes), -1);
        std::vector<Index> facet_key;
        for (const Facet& f : side.facets) {
          const Index fk =
              part->global_cells[static_cast<std::size_t>(f.cell)] * facets_per + f.local;
          facet_key.push_back(fk);
          const std::vector<Index> fn = mesh.facet_nodes(f);
          for (std::size_t a = 0; a < fn.size(); ++a)
            if (Index& k = key[static_cast<std::size_t>(fn[a])]; k < 0)
              k = fk * 32 + static_cast<Index>(a);
        }
        // N's entries of the kept rows (N is column-major: its columns walked once).
        std::vector<Index> row_of(static_cast<std::size_t>(cs.size()), -1);
        for (Index j = 0; j < cs.size(); ++j) {
          const Index v = cs.nodes[static_cast<std::size_t>(j)];
          if (node_ranks[static_cast<std::size_t>(v)] != rank) continue;
          row_of[static_cast<std::size_t>(j)] = static_cast<Index>(rows.size());
          ContactRow& r = rows.emplace_back();
          r.node = global_nodes[static_cast<std::size_t>(v)];
          r.key = key[static_cast<std::size_t>(v)];
          r.normal = cs.normals.col(j);
          r.point = mesh.node(v);
          r.prescribed = dofs.prescribed_at(v);
          r.weight = cs.weights(j);
          r.gap = cs.gaps(j);
          r.movable = cs.movable[static_cast<std::size_t>(j)];
        }
        for (int col = 0; col < cs.N.outerSize(); ++col)
          for (SparseMatrix::InnerIterator it(cs.N, col); it; ++it)
            if (const Index i = row_of[static_cast<std::size_t>(it.row())]; i >= 0)
              rows[static_cast<std::size_t>(i)].n.emplace_back(col, it.value());
        // Each facet from the owner of its first node, whose part has it.
        for (std::size_t f = 0; f < cs.facets.size(); ++f) {
          const std::vector<Index>& positions = cs.facets[f];
          const Index first = cs.nodes[static_cast<std::size_t>(positions.front())];
          if (node_ranks[static_cast<std::size_t>(first)] != rank) continue;
          ContactFacet out{facet_key[f], {}};
          for (const Index j : positions)
            out.nodes.push_back(
                global_nodes[static_cast<std::size_t>(cs.nodes[static_cast<std::size_t>(j)])]);
          facets.push_back(std::move(out));
        }
      }
      rows_out.put(static_cast<std::uint64_t>(rows.size()));
      for (const ContactRow& r : rows) pack_row(rows_out, r);
      rows_out.put(static_cast<std::uint64_t>(facets.size()));
      for (const ContactFacet& f : facets) {
        rows_out.put(f.key);
        rows_out.put(f.nodes);
      }
    }
  });
  // The whole contact set on every rank, each side's rows in the serial order.
  const std::vector<std::vector<char>> gathered = engine.allgather(rows_out.bytes());
  rows_out = ByteWriter();
  std::vector<ByteReader> readers;
  for (const std::vector<char>& bytes : gathered) readers.emplace_back(bytes);
  std::vector<std::string> contact_boundaries;
  std::vector<Index> contact_starts{0};
  std::vector<ContactRow> all_rows;
  for (std::size_t ci = 0; ci < spec.contacts.size(); ++ci) {
    const ContactSpec& c = spec.contacts[ci];
    std::vector<ContactRow> rows;
    std::vector<ContactFacet> facets;
    for (ByteReader& in : readers) {
      const auto count = static_cast<std::size_t>(in.get<std::uint64_t>());
      for (std::size_t i = 0; i < count; ++i) rows.push_back(unpack_row(in));
      const auto facet_count = static_cast<std::size_t>(in.get<std::uint64_t>());
      for (std::size_t i = 0; i < facet_count; ++i) {
        ContactFacet f;
        f.key = in.get<Index>();
        f.nodes = in.get_vector<Index>();
        facets.push_back(std::move(f));
      }
    }
    std::sort(rows.begin(), rows.end(),
              [](const ContactRow& a, const ContactRow& b) { return a.key < b.key; });
    std::sort(facets.begin(), facets.end(),
              [](const ContactFacet& a, const ContactFacet& b) { return a.key < b.key; });
    ContactSet cs;
    const auto n = static_cast<Index>(rows.size());
    cs.normals.resize(kDim, n);
    cs.weights.resize(n);
    cs.gaps.resize(n);
    std::vector<Eigen::Triplet<double, int>> triplets;
    std::vector<std::pair<Index, Index>> position;  // (node, row), for the facets
    for (Index j = 0; j < n; ++j) {
      const ContactRow& r = rows[static_cast<std::size_t>(j)];
      cs.nodes.push_back(r.node);
      cs.normals.col(j) = r.normal;
      cs.weights(j) = r.weight;
      cs.gaps(j) = r.gap;
      cs.movable.push_back(r.movable);
      for (const auto& [d, value] : r.n)
        triplets.emplace_back(static_cast<int>(j), static_cast<int>(d), value);
      position.emplace_back(r.node, j);
    }
    cs.N.resize(n, dofs.num_free());
    cs.N.setFromTriplets(triplets.begin(), triplets.end());
    cs.N.makeCompressed();
    std::sort(position.begin(), position.end());
    for (const ContactFacet& f : facets) {
      std::vector<Index>& out = cs.facets.emplace_back();
      for (const Index node : f.nodes)
        out.push_back(
            std::lower_bound(position.begin(), position.end(), std::pair<Index, Index>{node, -1})
                ->second);
    }
    if (cs.num_movable() == 0)  // (every rank alike: the set is whole)
      throw InputError("contact.boundary = '" + c.boundary +
                       "': every contact node is clamped in its normal direction, so no contact "
                       "can occur (does it coincide with the clamped boundary?)");
    append_contact_set(problem.contact, cs);
    contact_boundaries.push_back(c.boundary);
    contact_starts.push_back(problem.contact.size());
    all_rows.insert(all_rows.end(), std::make_move_iterator(rows.begin()),
                    std::make_move_iterator(rows.end()));
  }
  for (const ByteReader& in : readers)
    if (!in.done()) throw std::logic_error("box in parts: the contact rows' bytes do not add up");
  const Index contact_size = problem.contact.size();
  WholeMesh whole;
  whole.contact_points.resize(kDim, contact_size);
  whole.contact_prescribed.resize(kDim, contact_size);
  Eigen::MatrixXd gap_shift;
  std::vector<int> gap_shift_group;
  if (prescribed) {  // (model.cpp, contact_gap_shift: no frames in 3D)
    gap_shift.resize(kDim, contact_size);
    gap_shift_group.assign(static_cast<std::size_t>(kDim * contact_size), -1);
  }
  for (Index j = 0; j < contact_size; ++j) {
    const ContactRow& r = all_rows[static_cast<std::size_t>(j)];
    whole.contact_points.col(j) = r.point;
    whole.contact_prescribed.col(j) = r.prescribed;
    if (prescribed) gap_shift.col(j) = r.normal.cwiseProduct(r.prescribed);
  }
  all_rows = {};
  contact_timer.stop();

  // The whole box's facts: its nodes, their centroid and the largest distance from it.
  whole.nodes = 1;
  for (const Index n : {box.nx, box.ny, box.nz}) whole.nodes *= order * n + 1;
  {
    double sums[3] = {0.0, 0.0, 0.0};
    for (Index v = 0; v < nodes; ++v)
      if (node_ranks[static_cast<std::size_t>(v)] == rank)
        for (int k = 0; k < kDim; ++k) sums[k] += mesh.node(v)(k);
    engine.sum(sums, 3);
    whole.centroid = Eigen::Vector3d(sums[0], sums[1], sums[2]) / static_cast<double>(whole.nodes);
    double radius = 0.0;
    for (Index v = 0; v < nodes; ++v)
      if (node_ranks[static_cast<std::size_t>(v)] == rank)
        radius = std::max(radius, (mesh.node(v) - whole.centroid).norm());
    for (const double r : values_of_ranks(engine, radius)) whole.radius = std::max(whole.radius, r);
  }
  // The plan from rank 0's machine, so that every rank takes the same path.
  const ProblemSize size{kDim,
                         whole.nodes,
                         dofs.num_free(),
                         contact_size,
                         values_of_ranks(engine, physical_memory_bytes()).front(),
                         false};
  const SolverPlan plan = plan_model_solver(spec, size, nullptr, /*distributed=*/true);
  {
    ScopedTimer t(timings, "assembly");
    // The columns of the rank's unknowns (by symmetry its rows), from the cells around its
    // nodes (docs/distributed.md, "The partitioned model").
    std::vector<bool> owned(static_cast<std::size_t>(nodes));
    for (Index v = 0; v < nodes; ++v)
      owned[static_cast<std::size_t>(v)] = node_ranks[static_cast<std::size_t>(v)] == rank;
    problem.A = assemble_stiffness(mesh, dofs, elasticity, &owned);
  }
  if (uses_multigrid(plan.options))
    problem.near_null_space = rigid_body_modes(mesh, dofs, first_row, end_row, &whole.centroid);
  std::vector<ClampedPart> clamps = clamped_parts(spec.clamps, spec.displacements, entry);
  entry = {};
  std::vector<Index> part_nodes = std::move(part->global_nodes);
  Mesh part_mesh = std::move(part->mesh);
  part.reset();
  return Model{std::move(part_mesh),
               std::move(dofs),
               std::move(problem),
               MultigridHierarchy{},
               plan.options,
               plan.reason,
               std::move(timings),
               elasticity,
               std::move(loads),
               std::move(clamps),
               {},
               std::move(contact_boundaries),
               std::move(contact_starts),
               nullptr,
               {},
               std::move(gap_shift),
               std::move(gap_shift_group),
               std::move(part_nodes),
               std::move(whole),
               std::move(node_ranks)};
}

}  // namespace signorini

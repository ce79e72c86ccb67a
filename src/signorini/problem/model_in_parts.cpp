#include "signorini/problem/model_in_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <limits>
#include <stdexcept>

#include "signorini/contact/friction_law.hpp"
#include "signorini/core/peak_memory.hpp"
#include "signorini/fem/elasticity_assembly.hpp"
#include "signorini/fem/rigid_body_modes.hpp"
#include "signorini/interface/contact_boundary.hpp"
#include "signorini/interface/contact_tangents.hpp"
#include "signorini/problem/distributed_model.hpp"
#include "signorini/problem/model_part.hpp"

namespace signorini {

bool model_parts_support(const ProblemSpec& spec, bool numbered_whole) {
  if (spec.solver.partition != PartitionMode::Auto) return false;
  if (numbered_whole) return true;
  // A box whose ranks number their own parts: a pinned clamp's node is the whole box's nearest,
  // and a normal displacement (2D) needs the whole side's normals.
  for (const ClampSpec& c : spec.clamps)
    if (c.at) return false;
  for (const DisplacementSpec& d : spec.displacements)
    if (d.normal) return false;
  return true;
}

void agree_on_input(const DistributedEngine& engine, const std::string& message) {
  for (const std::vector<char>& m :
       engine.allgather(std::vector<char>(message.begin(), message.end())))
    if (!m.empty()) throw InputError(std::string(m.begin(), m.end()));
}

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
template std::vector<Index> values_of_ranks(const DistributedEngine&, Index);
template std::vector<double> values_of_ranks(const DistributedEngine&, double);

namespace {

// One contact row as a rank sends it: what the whole contact set and the results need.
struct ContactRow {
  Index node = 0;  // the whole mesh's
  Index key = 0;   // where the side's facets first name the node (the serial order)
  Vector normal, point, prescribed;
  double weight = 0.0, gap = 0.0;
  bool movable = false;
  std::vector<std::pair<Index, double>> n;  // N's entries: free dof, value
  std::vector<int> groups;  // the load group of each component's prescribed value, or -1
  Vector shift;             // what prescribed values take off the gap, per component
  // Friction's tangential rows (interface/contact_tangents.hpp): entries (dof * dim + k, value) of
  // the node's row for tangent k.
  std::vector<std::pair<Index, double>> t;
};

struct ContactFacet {
  Index key = 0;
  std::vector<Index> nodes;  // the whole mesh's
};

void pack_row(ByteWriter& out, const ContactRow& r) {
  out.put(r.node);
  out.put(r.key);
  for (const Vector* v : {&r.normal, &r.point, &r.prescribed}) out.put(*v);
  out.put(r.weight);
  out.put(r.gap);
  out.put(static_cast<std::uint8_t>(r.movable));
  out.put(static_cast<std::uint64_t>(r.n.size()));
  for (const auto& [d, value] : r.n) {
    out.put(d);
    out.put(value);
  }
  out.put(r.groups);
  out.put(r.shift);
  out.put(static_cast<std::uint64_t>(r.t.size()));
  for (const auto& [d, value] : r.t) {
    out.put(d);
    out.put(value);
  }
}

ContactRow unpack_row(ByteReader& in) {
  ContactRow r;
  r.node = in.get<Index>();
  r.key = in.get<Index>();
  for (Vector* v : {&r.normal, &r.point, &r.prescribed}) *v = in.get_vector_xd();
  r.weight = in.get<double>();
  r.gap = in.get<double>();
  r.movable = in.get<std::uint8_t>() != 0;
  r.n.resize(static_cast<std::size_t>(in.get<std::uint64_t>()));
  for (auto& [d, value] : r.n) {
    d = in.get<Index>();
    value = in.get<double>();
  }
  r.groups = in.get_vector<int>();
  r.shift = in.get_vector_xd();
  r.t.resize(static_cast<std::size_t>(in.get<std::uint64_t>()));
  for (auto& [d, value] : r.t) {
    d = in.get<Index>();
    value = in.get<double>();
  }
  return r;
}

// The smallest and largest coordinates of the whole mesh along each axis, from the ranks' own
// nodes (every node is some rank's): min and max are exact, whatever the order.
std::pair<Eigen::VectorXd, Eigen::VectorXd> whole_extent(const Mesh& mesh,
                                                         const std::vector<int>& node_ranks,
                                                         int rank,
                                                         const DistributedEngine& engine) {
  const int dim = mesh.dim();
  constexpr double inf = std::numeric_limits<double>::infinity();
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(dim, inf), hi = -lo;
  for (Index v = 0; v < mesh.num_nodes(); ++v)
    if (node_ranks[static_cast<std::size_t>(v)] == rank) {
      lo = lo.cwiseMin(mesh.node(v));
      hi = hi.cwiseMax(mesh.node(v));
    }
  ByteWriter out;
  out.put(Vector(lo));
  out.put(Vector(hi));
  for (const std::vector<char>& bytes : engine.allgather(out.bytes())) {
    ByteReader in(bytes);
    const Vector a = in.get_vector_xd(), b = in.get_vector_xd();
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(b);
  }
  return {lo, hi};
}

// The tractions, pressures and body force on a part of the mesh: a full vector of its nodes, and
// one in `groups` for each entry with load factors of its own (model.cpp's order).
Vector surface_and_body_loads(const ProblemSpec& spec, const Mesh& mesh,
                              std::vector<LoadGroup>& groups) {
  const Index n = mesh.num_nodes() * mesh.dim();
  Vector loads = Vector::Zero(n);
  add_surface_and_body_loads(
      spec, mesh, [&](const std::vector<double>& factors, std::string entry) -> Vector& {
        if (factors.empty()) return loads;
        groups.push_back({std::move(entry), factors, Vector::Zero(n), {}, {}});
        return groups.back().loads;
      });
  return loads;
}

// Each point load at the whole mesh's node nearest to it (on its boundary where it names one),
// as nearest_node finds it on the whole mesh: each rank's nearest of its own nodes, and the
// nearest of those, the lower node number on a tie (the whole mesh's scan keeps the first).
std::vector<PlacedPointLoad> place_point_loads(const ProblemSpec& spec, const OwnPart& part,
                                               int rank, const DistributedEngine& engine) {
  const Mesh& mesh = part.mesh;
  constexpr double inf = std::numeric_limits<double>::infinity();
  ByteWriter out;
  on_every_rank(engine, [&] {
    for (std::size_t i = 0; i < spec.point_loads.size(); ++i) {
      const PointLoadSpec& pl = spec.point_loads[i];
      if (!pl.at.allFinite() || !pl.force.allFinite())
        throw InputError(fmt::format("point_load[{}]: expected finite 'at' and 'force'", i));
      std::vector<bool> on_boundary;
      if (!pl.boundary.empty()) {
        on_boundary.assign(static_cast<std::size_t>(mesh.num_nodes()), false);
        for (const Index v : mesh.boundary_part_nodes(pl.boundary))
          on_boundary[static_cast<std::size_t>(v)] = true;
      }
      // The nearest own node on the boundary, and the nearest of all (nearest_node takes every
      // node where the boundary has none), each with its point.
      std::array<double, 2> best{inf, inf};
      std::array<Index, 2> node{-1, -1};
      std::array<Point, 2> at{Point::Zero(), Point::Zero()};
      for (Index v = 0; v < mesh.num_nodes(); ++v) {
        if (part.node_ranks[static_cast<std::size_t>(v)] != rank) continue;
        const Point x = mesh.point(v);
        const double d = (x - pl.at).squaredNorm();
        for (std::size_t which = 0; which < 2; ++which) {
          if (which == 0 && !on_boundary.empty() && !on_boundary[static_cast<std::size_t>(v)])
            continue;
          if (d < best[which]) {
            best[which] = d;
            node[which] = part.global_nodes[static_cast<std::size_t>(v)];
            at[which] = x;
          }
        }
      }
      for (std::size_t which = 0; which < 2; ++which) {
        out.put(best[which]);
        out.put(node[which]);
        out.put_array(at[which].data(), 3);
      }
    }
  });
  const std::vector<std::vector<char>> all = engine.allgather(out.bytes());
  std::vector<ByteReader> readers;
  for (const std::vector<char>& bytes : all) readers.emplace_back(bytes);
  std::vector<PlacedPointLoad> placed;
  for (const PointLoadSpec& pl : spec.point_loads) {
    std::array<double, 2> best{inf, inf};
    std::array<PlacedPointLoad, 2> nearest;
    nearest[0].node = nearest[1].node = -1;
    for (ByteReader& in : readers)
      for (std::size_t which = 0; which < 2; ++which) {
        const double d = in.get<double>();
        const Index v = in.get<Index>();
        const std::vector<double> x = in.get_vector<double>();
        PlacedPointLoad& p = nearest[which];
        if (v >= 0 && (d < best[which] || (d == best[which] && v < p.node))) {
          best[which] = d;
          p.node = v;
          p.at = Point(x.at(0), x.at(1), x.at(2));
        }
      }
    PlacedPointLoad p = nearest[0].node >= 0 ? nearest[0] : nearest[1];
    p.requested = pl.at;
    p.force = pl.force;
    p.distance = (p.at - p.requested).norm();
    placed.push_back(p);
  }
  for (const ByteReader& in : readers)
    if (!in.done()) throw std::logic_error("model in parts: the point loads' bytes do not add up");
  return placed;
}

}  // namespace

Model model_from_own_part(const ProblemSpec& spec, OwnPart part, DistributedEngine& engine,
                          TimingTable timings) {
  const int rank = engine.rank();
  const Mesh& mesh = part.mesh;
  const int dim = mesh.dim();
  const Index nodes = mesh.num_nodes();
  const std::vector<int>& node_ranks = part.node_ranks;
  const DofMap& dofs = part.dofs;
  ScopedTimer loads_timer(timings, "loads");
  ElasticityOptions elasticity;
  Vector loads;
  std::vector<LoadGroup> groups;  // in model.cpp's order: surface and body, points, displacements
  on_every_rank(engine, [&] {
    elasticity = region_elasticity(spec, mesh.region_names());
    loads = surface_and_body_loads(spec, mesh, groups);
  });
  std::vector<PlacedPointLoad> placed = place_point_loads(spec, part, rank, engine);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const PointLoadSpec& pl = spec.point_loads[i];
    Vector* target = &loads;
    if (!pl.factors.empty()) {
      groups.push_back(
          {fmt::format("point_load[{}]", i), pl.factors, Vector::Zero(nodes * dim), {}, {}});
      target = &groups.back().loads;
    }
    const auto it =
        std::lower_bound(part.global_nodes.begin(), part.global_nodes.end(), placed[i].node);
    if (it == part.global_nodes.end() || *it != placed[i].node) continue;
    const auto v = static_cast<Index>(it - part.global_nodes.begin());
    if (node_ranks[static_cast<std::size_t>(v)] != rank) continue;  // (its owner's load)
    for (int k = 0; k < dim; ++k) (*target)(v * dim + k) += pl.force(k);
  }
  for (std::size_t i = 0; i < spec.displacements.size(); ++i) {
    if (spec.displacements[i].factors.empty()) continue;
    LoadGroup g{fmt::format("displacement[{}]", i), spec.displacements[i].factors, {}, {}, {}};
    for (std::size_t d = 0; d < part.entry.size(); ++d)
      if (part.entry[d] == static_cast<int>(spec.clamps.size() + i))
        g.prescribed_dofs.push_back(static_cast<Index>(d));
    groups.push_back(std::move(g));
  }

  ContactProblem problem;
  problem.engine = &engine;
  problem.row_starts = std::move(part.row_starts);
  problem.rank = rank;
  problem.node_of_unknown = std::move(part.node_of_unknown);
  const Index first_row = problem.first_row(), end_row = problem.end_row();
  // The rank's rows of a full vector of the part (DofMap::restrict_to_free: at a node with
  // local axes, its components along them).
  const auto own_rows = [&](const Vector& full) {
    Vector rows = Vector::Zero(end_row - first_row);
    for (Index v = 0; v < nodes; ++v) {
      Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, 3, 1> at =
          full.segment(v * dim, dim);
      if (dofs.has_frame(v))  // (2D only, as DofMap::rotate_frames turns it)
        at = Eigen::Vector2d(dofs.frame(v).transpose() * Eigen::Vector2d(at));
      for (int k = 0; k < dim; ++k)
        if (const Index i = dofs.free_index(v, k); i >= first_row && i < end_row)
          rows(i - first_row) = at(k);
    }
    return rows;
  };
  // b = f - K u_D on the rank's rows (model.cpp's free part), and each load group's part of it:
  // every cell around the rank's nodes is in its part, in the whole mesh's order, so the sums
  // run as the whole mesh's do.
  for (LoadGroup& g : groups) {
    Vector scales = Vector::Zero(nodes * dim);
    for (const Index d : g.prescribed_dofs) scales(d) = 1.0;
    const Vector u_d = dofs.prescribed_values(scales);
    g.b = own_rows(free_loads(mesh, dofs, elasticity,
                              g.loads.size() != 0 ? g.loads : Vector(Vector::Zero(nodes * dim)),
                              u_d));
    if (g.loads.size() != 0) loads += g.loads;
  }
  problem.b = own_rows(free_loads(mesh, dofs, elasticity, loads));
  loads_timer.stop();
  const std::vector<int> group_of_dof = load_group_of_dofs(groups, nodes * dim);

  // The contact rows of the rank's nodes, in the order in which the side's facets first name
  // them (interface/contact_boundary.cpp): each rank has every facet around its nodes.
  ScopedTimer contact_timer(timings, "contact set");
  // The initial interference allowed, from the whole mesh's extent as make_contact_set
  // measures it.
  const auto [lo, hi] = whole_extent(mesh, node_ranks, rank, engine);
  const double limit = interference_limit(hi - lo);
  bool with_friction = false;
  for (const ContactSpec& c : spec.contacts)
    with_friction = with_friction || c.friction != FrictionModel::None;
  ByteWriter rows_out;
  on_every_rank(engine, [&] {
    for (const ContactSpec& c : spec.contacts) {
      const BoundaryPart& side = mesh.boundary_part(c.boundary);  // InputError on other names
      // (each rank its part's nodes: together the whole body)
      check_body_outside(mesh, c.obstacle, limit, "contact.boundary = '" + c.boundary + "'");
      std::vector<ContactRow> rows;
      std::vector<ContactFacet> facets;
      if (!side.facets.empty()) {
        const std::vector<Index>& facet_key = part.facet_keys.at(c.boundary);
        if (facet_key.size() != side.facets.size())
          throw std::logic_error("model in parts: a side's facets and their places differ");
        RigidObstacle o = c.obstacle;
        if (o.shape == ObstacleShape::Gap) o.gap = c.gap;
        const ContactSet cs = make_contact_rows(mesh, side, dofs, o, c.surface_normal, limit);
        // The key of each node: its first facet's place in the whole side, and its place there
        // (or, where given, its place in the whole side's order).
        std::vector<Index> key(static_cast<std::size_t>(nodes), -1);
        if (const auto given = part.node_keys.find(c.boundary); given != part.node_keys.end()) {
          for (const auto& [v, place] : given->second) key[static_cast<std::size_t>(v)] = place;
        } else {
          for (std::size_t f = 0; f < side.facets.size(); ++f) {
            const std::vector<Index> fn = mesh.facet_nodes(side.facets[f]);
            for (std::size_t a = 0; a < fn.size(); ++a)
              if (Index& k = key[static_cast<std::size_t>(fn[a])]; k < 0)
                k = facet_key[f] * 32 + static_cast<Index>(a);
          }
        }
        // N's entries of the kept rows (N is column-major: its columns walked once).
        std::vector<Index> row_of(static_cast<std::size_t>(cs.size()), -1);
        for (Index j = 0; j < cs.size(); ++j) {
          const Index v = cs.nodes[static_cast<std::size_t>(j)];
          if (node_ranks[static_cast<std::size_t>(v)] != rank) continue;
          row_of[static_cast<std::size_t>(j)] = static_cast<Index>(rows.size());
          ContactRow& r = rows.emplace_back();
          r.node = part.global_nodes[static_cast<std::size_t>(v)];
          r.key = key[static_cast<std::size_t>(v)];
          r.normal = cs.normals.col(j);
          r.point = mesh.node(v);
          r.prescribed = dofs.prescribed_at(v);
          r.weight = cs.weights(j);
          r.gap = cs.gaps(j);
          r.movable = cs.movable[static_cast<std::size_t>(j)];
          r.groups.assign(static_cast<std::size_t>(dim), -1);
          // (model.cpp, contact_gap_shift: each component along the node's axes)
          r.shift.resize(dim);
          for (int k = 0; k < dim; ++k) {
            Eigen::VectorXd axis = Eigen::VectorXd::Unit(dim, k);
            if (dofs.has_frame(v)) axis = dofs.frame(v).col(k);
            r.shift(k) = cs.normals.col(j).dot(axis) * dofs.value(v, k);
          }
          if (!group_of_dof.empty())
            for (int k = 0; k < dim; ++k)
              r.groups[static_cast<std::size_t>(k)] =
                  group_of_dof[static_cast<std::size_t>(v * dim + k)];
        }
        for (int col = 0; col < cs.N.outerSize(); ++col)
          for (SparseMatrix::InnerIterator it(cs.N, col); it; ++it)
            if (const Index i = row_of[static_cast<std::size_t>(it.row())]; i >= 0)
              rows[static_cast<std::size_t>(i)].n.emplace_back(col, it.value());
        if (with_friction) {  // (rows (dim - 1) j + k of T for the set's node j)
          const SparseMatrix T = tangential_operator(cs, dofs);
          for (int col = 0; col < T.outerSize(); ++col)
            for (SparseMatrix::InnerIterator it(T, col); it; ++it)
              if (const Index i = row_of[static_cast<std::size_t>(it.row() / (dim - 1))]; i >= 0)
                rows[static_cast<std::size_t>(i)].t.emplace_back(
                    static_cast<Index>(col) * dim + it.row() % (dim - 1), it.value());
        }
        // Each facet from the owner of its first node, whose part has it.
        for (std::size_t f = 0; f < cs.facets.size(); ++f) {
          const std::vector<Index>& positions = cs.facets[f];
          const Index first = cs.nodes[static_cast<std::size_t>(positions.front())];
          if (node_ranks[static_cast<std::size_t>(first)] != rank) continue;
          ContactFacet out{facet_key[f], {}};
          for (const Index j : positions)
            out.nodes.push_back(
                part.global_nodes[static_cast<std::size_t>(cs.nodes[static_cast<std::size_t>(j)])]);
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
  for (const ContactSpec& c : spec.contacts) {
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
    cs.normals.resize(dim, n);
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
    if (rows.empty())  // (every rank alike: no part has a facet of the side)
      throw InputError("contact.boundary = '" + c.boundary + "': the boundary part has no facets");
    check_contact_can_occur(cs, c.boundary);  // (every rank alike: the set is whole)
    append_contact_set(problem.contact, cs);
    contact_boundaries.push_back(c.boundary);
    contact_starts.push_back(problem.contact.size());
    all_rows.insert(all_rows.end(), std::make_move_iterator(rows.begin()),
                    std::make_move_iterator(rows.end()));
  }
  for (const ByteReader& in : readers)
    if (!in.done()) throw std::logic_error("model in parts: the contact rows' bytes do not add up");
  // Friction: the law per node and the tangential rows in N (model.cpp, make_friction), from the
  // gathered rows' points and tangential entries, on every rank alike.
  const std::shared_ptr<const FrictionLaw> friction = contact_friction_law(
      spec, dim, contact_starts,
      [&](Index j) {
        Point x = Point::Zero();
        x.head(dim) = all_rows[static_cast<std::size_t>(j)].point;
        return x;
      },
      &engine);
  if (friction) {
    std::vector<Eigen::Triplet<double, int>> triplets;
    for (std::size_t j = 0; j < all_rows.size(); ++j)
      for (const auto& [code, value] : all_rows[j].t)
        triplets.emplace_back(static_cast<int>((dim - 1) * static_cast<Index>(j) + code % dim),
                              static_cast<int>(code / dim), value);
    SparseMatrix T((dim - 1) * problem.contact.size(), dofs.num_free());
    T.setFromTriplets(triplets.begin(), triplets.end());
    add_tangential_rows(problem.contact, T);
  }
  const Index contact_size = problem.contact.size();
  WholeMesh whole;
  whole.contact_points.resize(dim, contact_size);
  whole.contact_prescribed.resize(dim, contact_size);
  Eigen::MatrixXd gap_shift;
  std::vector<int> gap_shift_group;
  const bool prescribed = dofs.has_prescribed_values();  // (the whole problem's, on a part)
  if (prescribed) {                                      // (model.cpp, contact_gap_shift)
    gap_shift.resize(dim, contact_size);
    gap_shift_group.assign(static_cast<std::size_t>(dim * contact_size), -1);
  }
  for (Index j = 0; j < contact_size; ++j) {
    const ContactRow& r = all_rows[static_cast<std::size_t>(j)];
    whole.contact_points.col(j) = r.point;
    whole.contact_prescribed.col(j) = r.prescribed;
    if (prescribed) {
      gap_shift.col(j) = r.shift;
      for (int k = 0; k < dim; ++k)
        gap_shift_group[static_cast<std::size_t>(j * dim + k)] =
            r.groups.at(static_cast<std::size_t>(k));
    }
  }
  all_rows = {};
  contact_timer.stop();

  // The whole mesh's facts: its nodes, their centroid and the largest distance from it.
  {
    std::vector<double> sums(static_cast<std::size_t>(dim) + 1, 0.0);
    for (Index v = 0; v < nodes; ++v)
      if (node_ranks[static_cast<std::size_t>(v)] == rank) {
        for (int k = 0; k < dim; ++k) sums[static_cast<std::size_t>(k)] += mesh.node(v)(k);
        sums.back() += 1.0;
      }
    engine.sum(sums.data(), dim + 1);
    whole.nodes = static_cast<Index>(sums.back());
    whole.centroid =
        Eigen::Map<const Eigen::VectorXd>(sums.data(), dim) / static_cast<double>(whole.nodes);
    double radius = 0.0;
    for (Index v = 0; v < nodes; ++v)
      if (node_ranks[static_cast<std::size_t>(v)] == rank)
        radius = std::max(radius, (mesh.node(v) - whole.centroid).norm());
    for (const double r : values_of_ranks(engine, radius)) whole.radius = std::max(whole.radius, r);
  }
  // The plan from rank 0's machine, so that every rank takes the same path.
  const ProblemSize size{dim,
                         whole.nodes,
                         dofs.num_free(),
                         contact_size,
                         values_of_ranks(engine, physical_memory_bytes()).front(),
                         friction != nullptr};
  problem.law = friction;  // (the problem owns its law: contact_law.hpp)
  const SolverPlan plan = plan_model_solver(spec, size, &engine);
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
  std::vector<ClampedPart> clamps = clamped_parts(spec.clamps, spec.displacements, part.entry);
  part.entry = {};
  // The solution comes back as the part's unknowns only (no vector of all n on any rank).
  problem.solution_unknowns = part_unknowns(part.dofs);
  return Model{.mesh = std::move(part.mesh),
               .dofs = std::move(part.dofs),
               .problem = std::move(problem),
               .multigrid = {},
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
               .contact_gap_shift = std::move(gap_shift),
               .contact_gap_shift_group = std::move(gap_shift_group),
               .global_nodes = std::move(part.global_nodes),
               .whole = std::move(whole),
               .node_ranks = std::move(part.node_ranks)};
}

}  // namespace signorini

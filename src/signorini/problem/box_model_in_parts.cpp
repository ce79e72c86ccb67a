#include "signorini/problem/box_model_in_parts.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <map>
#include <optional>
#include <stdexcept>

#include "signorini/core/error.hpp"
#include "signorini/mesh/box_mesh.hpp"
#include "signorini/parallel/box_partition.hpp"
#include "signorini/parallel/byte_message.hpp"
#include "signorini/problem/distributed_model.hpp"
#include "signorini/problem/model_in_parts.hpp"

namespace signorini {

bool box_in_parts(const ProblemSpec& spec, int ranks) {
  return spec.mesh_type == MeshType::Box && ranks >= 2 &&
         model_parts_support(spec, /*numbered_whole=*/false) &&
         BoxPartition(spec.box, ranks).possible();
}

namespace {

constexpr int kDim = 3;

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
    local = number_dofs(part->mesh, spec.clamps, spec.displacements, entry);
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
  // Each side's facets by their place in the whole box's: the box lists a side's facets in the
  // order of its cubes' cells.
  std::map<std::string, std::vector<Index>> facet_keys;
  const int facets_per = facets_per_cell(box.cell);
  for (const std::string& name : mesh.boundary_part_names()) {
    std::vector<Index>& keys = facet_keys[name];
    for (const Facet& f : mesh.boundary_part(name).facets)
      keys.push_back(part->global_cells[static_cast<std::size_t>(f.cell)] * facets_per + f.local);
  }
  mesh_timer.stop();
  OwnPart own{std::move(part->mesh), std::move(part->global_nodes),
              std::move(node_ranks), std::move(facet_keys),
              std::move(dofs),       std::move(entry),
              std::move(row_starts), std::move(node_of_unknown)};
  part.reset();
  return model_from_own_part(spec, std::move(own), engine, std::move(timings));
}

}  // namespace signorini

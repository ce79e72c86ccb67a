#include "signorini/problem/model_part.hpp"

#include <algorithm>

namespace signorini {

PartCells::PartCells(const Mesh& mesh)
    : mesh_(mesh),
      node_cells_(mesh),
      cell_mark_(static_cast<std::size_t>(mesh.num_cells()), -1),
      near_mark_(static_cast<std::size_t>(mesh.num_cells()), -1),
      node_mark_(static_cast<std::size_t>(mesh.num_nodes()), -1) {}

std::vector<Index> PartCells::cells(const std::vector<Index>& own) {
  const int call = call_++;
  const auto around = [&](Index v, const auto& visit) {
    for (const Index c : node_cells_.of(v)) visit(c);
  };
  // The first layer, and the nodes of its cells.
  std::vector<Index> near;
  for (const Index v : own)
    around(v, [&](Index c) {
      int& mark = cell_mark_[static_cast<std::size_t>(c)];
      if (mark == call) return;
      mark = call;
      for (const Index w : mesh_.cell(c)) {
        int& seen = node_mark_[static_cast<std::size_t>(w)];
        if (seen != call) {
          seen = call;
          near.push_back(w);
        }
      }
    });
  // The second: every cell around those nodes.
  std::vector<Index> cells;
  for (const Index v : near)
    around(v, [&](Index c) {
      int& mark = near_mark_[static_cast<std::size_t>(c)];
      if (mark == call) return;
      mark = call;
      cells.push_back(c);
    });
  std::sort(cells.begin(), cells.end());
  return cells;
}

std::vector<Index> part_unknowns(const DofMap& dofs) {
  std::vector<Index> unknowns;
  for (Index v = 0; v < dofs.num_nodes(); ++v)
    for (int k = 0; k < dofs.dim(); ++k)
      if (const Index f = dofs.free_index(v, k); f >= 0) unknowns.push_back(f);
  std::sort(unknowns.begin(), unknowns.end());
  unknowns.erase(std::unique(unknowns.begin(), unknowns.end()), unknowns.end());
  return unknowns;
}

MeshPart mesh_part(const Mesh& mesh, const std::vector<Index>& cells) {
  std::vector<Index> global;
  for (const Index c : cells)
    for (const Index v : mesh.cell(c)) global.push_back(v);
  std::sort(global.begin(), global.end());
  global.erase(std::unique(global.begin(), global.end()), global.end());
  const auto local = [&](Index v) {
    return static_cast<Index>(std::lower_bound(global.begin(), global.end(), v) - global.begin());
  };
  Eigen::MatrixXd coordinates(mesh.dim(), static_cast<Index>(global.size()));
  for (std::size_t i = 0; i < global.size(); ++i)
    coordinates.col(static_cast<Index>(i)) = mesh.node(global[i]);
  std::vector<CellType> types;
  std::vector<Index> connectivity;
  std::vector<int> regions;
  std::vector<Index> tags;
  for (const Index c : cells) {
    types.push_back(mesh.cell_type(c));
    for (const Index v : mesh.cell(c)) connectivity.push_back(local(v));
    regions.push_back(mesh.cell_region(c));
    tags.push_back(mesh.cell_source_tag(c));
  }
  Mesh part(std::move(types), std::move(coordinates), std::move(connectivity));
  if (!mesh.region_names().empty()) part.set_cell_regions(mesh.region_names(), regions);
  if (mesh.num_cells() > 0 && mesh.cell_source_tag(0) >= 0)
    part.set_cell_source_tags(std::move(tags));
  return {std::move(part), std::move(global)};
}

void pack(ByteWriter& out, const Mesh& mesh) {
  std::vector<CellType> types;
  std::vector<Index> connectivity;
  std::vector<int> regions;
  std::vector<Index> tags;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    types.push_back(mesh.cell_type(c));
    const auto nodes = mesh.cell(c);
    connectivity.insert(connectivity.end(), nodes.begin(), nodes.end());
    regions.push_back(mesh.cell_region(c));
    tags.push_back(mesh.cell_source_tag(c));
  }
  out.put(types);
  out.put_matrix(mesh.coordinates());
  out.put(connectivity);
  out.put(mesh.region_names());
  out.put(regions);
  out.put(tags);
}

Mesh unpack_mesh(ByteReader& in) {
  std::vector<CellType> types = in.get_vector<CellType>();
  Eigen::MatrixXd coordinates = in.get_matrix();
  std::vector<Index> connectivity = in.get_vector<Index>();
  Mesh mesh(std::move(types), std::move(coordinates), std::move(connectivity));
  std::vector<std::string> names = in.get_strings();
  std::vector<int> regions = in.get_vector<int>();
  std::vector<Index> tags = in.get_vector<Index>();
  if (!names.empty()) mesh.set_cell_regions(std::move(names), std::move(regions));
  if (!tags.empty() && tags.front() >= 0) mesh.set_cell_source_tags(std::move(tags));
  return mesh;
}

void pack(ByteWriter& out, const DofMap& dofs) {
  std::vector<Index> free;
  free.reserve(static_cast<std::size_t>(dofs.num_dofs()));
  Vector values = dofs.has_prescribed_values() ? Vector(dofs.num_dofs()) : Vector();
  std::vector<Index> framed;
  std::vector<double> axes;
  for (Index v = 0; v < dofs.num_nodes(); ++v) {
    for (int k = 0; k < dofs.dim(); ++k) {
      free.push_back(dofs.free_index(v, k));
      if (values.size() != 0) values(v * dofs.dim() + k) = dofs.value(v, k);
    }
    if (dofs.has_frame(v)) {
      framed.push_back(v);
      const Eigen::Matrix2d Q = dofs.frame(v);
      axes.insert(axes.end(), Q.data(), Q.data() + 4);
    }
  }
  out.put(static_cast<std::int32_t>(dofs.dim()));
  out.put(static_cast<std::int64_t>(dofs.num_free()));
  out.put(free);
  out.put(values);
  out.put(framed);
  out.put(axes);
}

DofMap unpack_dof_map(ByteReader& in) {
  const auto dim = static_cast<int>(in.get<std::int32_t>());
  const auto num_free = static_cast<Index>(in.get<std::int64_t>());
  std::vector<Index> free = in.get_vector<Index>();
  Vector values = in.get_vector_xd();
  const std::vector<Index> framed = in.get_vector<Index>();
  const std::vector<double> axes = in.get_vector<double>();
  std::vector<std::pair<Index, Eigen::Matrix2d>> frames;
  for (std::size_t i = 0; i < framed.size(); ++i)
    frames.emplace_back(framed[i], Eigen::Map<const Eigen::Matrix2d>(axes.data() + 4 * i));
  return DofMap(dim, std::move(free), num_free, std::move(values), frames);
}

void pack(ByteWriter& out, const ContactSet& c) {
  out.put(c.nodes);
  out.put_matrix(c.normals);
  out.put(c.weights);
  out.put(c.gaps);
  // N in compressed columns (a matrix that grew by insertion keeps gaps in its arrays).
  SparseMatrix compressed;
  const SparseMatrix* N = &c.N;
  if (!c.N.isCompressed()) {
    compressed = c.N;
    compressed.makeCompressed();
    N = &compressed;
  }
  out.put(static_cast<std::int64_t>(N->rows()));
  out.put(static_cast<std::int64_t>(N->cols()));
  std::vector<int> outer(N->outerIndexPtr(), N->outerIndexPtr() + N->outerSize() + 1);
  std::vector<int> inner(N->innerIndexPtr(), N->innerIndexPtr() + N->nonZeros());
  std::vector<double> values(N->valuePtr(), N->valuePtr() + N->nonZeros());
  out.put(outer);
  out.put(inner);
  out.put(values);
  out.put(static_cast<std::int32_t>(c.components));
  out.put(c.slip_origin);
  out.put(c.movable);
  out.put(static_cast<std::uint64_t>(c.facets.size()));
  for (const std::vector<Index>& f : c.facets) out.put(f);
}

ContactSet unpack_contact_set(ByteReader& in) {
  ContactSet c;
  c.nodes = in.get_vector<Index>();
  c.normals = in.get_matrix();
  c.weights = in.get_vector_xd();
  c.gaps = in.get_vector_xd();
  const auto rows = static_cast<Index>(in.get<std::int64_t>());
  const auto cols = static_cast<Index>(in.get<std::int64_t>());
  const std::vector<int> outer = in.get_vector<int>();
  const std::vector<int> inner = in.get_vector<int>();
  const std::vector<double> values = in.get_vector<double>();
  c.N = Eigen::Map<const SparseMatrix>(rows, cols, static_cast<Index>(values.size()), outer.data(),
                                       inner.data(), values.data());
  c.components = static_cast<int>(in.get<std::int32_t>());
  c.slip_origin = in.get_vector_xd();
  c.movable = in.get_vector<bool>();
  c.facets.resize(static_cast<std::size_t>(in.get<std::uint64_t>()));
  for (std::vector<Index>& f : c.facets) f = in.get_vector<Index>();
  return c;
}

void pack(ByteWriter& out, const NodeGraph& g) {
  out.put(static_cast<std::int64_t>(g.vertices));
  out.put(static_cast<std::int64_t>(g.first));
  out.put(static_cast<std::int64_t>(g.last));
  out.put(g.offsets);
  out.put(g.neighbours);
  out.put(g.weights);
  out.put(g.node);
}

NodeGraph unpack_node_graph(ByteReader& in) {
  NodeGraph g;
  g.vertices = static_cast<Index>(in.get<std::int64_t>());
  g.first = static_cast<Index>(in.get<std::int64_t>());
  g.last = static_cast<Index>(in.get<std::int64_t>());
  g.offsets = in.get_vector<Index>();
  g.neighbours = in.get_vector<Index>();
  g.weights = in.get_vector<Index>();
  g.node = in.get_vector<Index>();
  return g;
}

}  // namespace signorini

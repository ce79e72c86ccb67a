// signorini.Mesh: a mesh from numpy arrays (mesh/mesh_arrays.hpp) or a file, and what it holds.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "numpy_views.hpp"
#include "signorini/core/error.hpp"
#include "signorini/mesh/gmsh_reader.hpp"
#include "signorini/mesh/mesh_arrays.hpp"
#include "signorini/mesh/mesh_description.hpp"

namespace signorini::python {

namespace {

CellType cell_type_named(const std::string& name, const std::string& what) {
  const auto t = enum_from_string(kCellTypeNames, name);
  if (!t || cell_dimension(*t) < 2)
    throw InputError(fmt::format(
        "mesh: {} '{}' is not a cell type: expected tri3, tri6, quad4, quad8, quad9 (2D), tet4, "
        "tet10, hex8 or hex27 (3D)",
        what, name));
  return *t;
}

// An integer array of `columns` per row (any integer dtype), as node numbers.
std::vector<Index> node_numbers(const py::handle& values, py::ssize_t columns,
                                const std::string& what) {
  const py::array raw = py::array::ensure(values);
  if (!raw) throw InputError(fmt::format("mesh: {}: expected an integer array", what));
  if (raw.size() > 0 && raw.dtype().kind() != 'i' && raw.dtype().kind() != 'u')
    throw InputError(fmt::format("mesh: {}: expected integers (node numbers), got dtype {}", what,
                                 py::str(raw.dtype()).cast<std::string>()));
  const auto a = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(raw);
  if (a.ndim() != 2 || (columns > 0 && a.shape(1) != columns))
    throw InputError(fmt::format("mesh: {}: expected an array of shape (count, {}), got shape {}",
                                 what, columns > 0 ? std::to_string(columns) : "nodes per facet",
                                 py::str(py::tuple(raw.attr("shape"))).cast<std::string>()));
  return {a.data(), a.data() + a.size()};
}

PyMesh make_mesh(const py::handle& points, const py::handle& cells, const py::handle& boundaries) {
  MeshArrays arrays;
  {
    const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(points);
    if (!p || p.ndim() != 2 || (p.shape(1) != 2 && p.shape(1) != 3))
      throw InputError(
          "mesh: points: expected an array of shape (count, 2) or (count, 3) of coordinates");
    // Row per point in numpy, column per point here: the same bytes.
    arrays.points = Eigen::Map<const Eigen::MatrixXd>(p.data(), p.shape(1), p.shape(0));
  }
  // cells: {"quad4": array} or [("quad4", array), ("tri3", array, "region"), ...].
  const auto add_block = [&](const py::handle& type, const py::handle& nodes,
                             const std::string& region) {
    const std::string name = py::str(type);
    CellBlock b;
    b.type = cell_type_named(name, "cell type");
    b.nodes = node_numbers(nodes, nodes_per_cell(b.type), "cells '" + name + "'");
    b.region = region;
    arrays.blocks.push_back(std::move(b));
  };
  if (py::isinstance<py::dict>(cells)) {
    for (const auto& [type, nodes] : py::reinterpret_borrow<py::dict>(cells))
      add_block(type, nodes, "");
  } else {
    for (const py::handle entry : py::reinterpret_borrow<py::iterable>(cells)) {
      const py::tuple t(py::reinterpret_borrow<py::object>(entry));
      if (t.size() != 2 && t.size() != 3)
        throw InputError(
            "mesh: cells: expected a dict {type: array} or a list of (type, array) or (type, "
            "array, region)");
      add_block(t[0], t[1], t.size() == 3 ? py::str(t[2]).cast<std::string>() : "");
    }
  }
  if (!boundaries.is_none())
    for (const auto& [name, nodes] : py::reinterpret_borrow<py::dict>(boundaries)) {
      BoundaryFacets f;
      f.name = py::str(name);
      const py::array a = py::array::ensure(nodes);
      f.nodes = node_numbers(nodes, 0, "boundary '" + f.name + "'");
      f.nodes_per_facet = a && a.ndim() == 2 ? static_cast<int>(a.shape(1)) : 0;
      arrays.boundaries.push_back(std::move(f));
    }
  return PyMesh{std::make_shared<const Mesh>(mesh_from_arrays(arrays))};
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<PyMesh>(m, "Mesh", R"(A mesh: points, cells and named boundary parts.

Mesh(points, cells, boundaries=None)
  points      (n, 2) or (n, 3) array of coordinates (2D cells on (n, 3) points
              whose z is one constant make a 2D mesh, as from_meshio does)
  cells       {"quad4": (k, 4) int array, ...} or [(type, array[, region]), ...];
              types tri3 tri6 quad4 quad8 quad9 (2D), tet4 tet10 hex8 hex27 (3D),
              node orders as Gmsh's; a region names the cells of a [[region]] material
  boundaries  {"name": (k, nodes per facet) int array}: the facets of each boundary
              part (lines in 2D, triangles or quadrilaterals in 3D), corners first

2D cells given clockwise are turned counterclockwise. Every point must belong to a
cell; a cell that names a node twice, two cells with the same nodes, and two cells on
the same side of a facet they share are refused (InputError). Mesh.read(path) reads a Gmsh .msh (or meshes a .geo); Mesh.from_meshio(mesh)
converts a meshio.Mesh.)")
      .def(py::init(&make_mesh), py::arg("points"), py::arg("cells"),
           py::arg("boundaries") = py::none())
      .def_static(
          "read",
          [](const py::object& path) {
            const std::string p = path_text(path);
            py::gil_scoped_release release;
            return PyMesh{std::make_shared<const Mesh>(read_mesh_file(p))};
          },
          py::arg("path"), "Reads a Gmsh .msh file (or meshes a .geo file with the gmsh program).")
      .def_property_readonly("dim", [](const PyMesh& s) { return s.mesh->dim(); })
      .def_property_readonly("num_nodes", [](const PyMesh& s) { return s.mesh->num_nodes(); })
      .def_property_readonly("num_cells", [](const PyMesh& s) { return s.mesh->num_cells(); })
      .def_property_readonly(
          "points",
          [](const py::object& self) {
            return columns_view(self.cast<const PyMesh&>().mesh->coordinates(), self);
          },
          "(n, dim) array of the node coordinates (read-only, not a copy)")
      .def_property_readonly("cell_types",
                             [](const PyMesh& s) {
                               std::vector<std::string> out;
                               for (const CellType t : s.mesh->cell_types())
                                 out.emplace_back(enum_to_string(kCellTypeNames, t));
                               return out;
                             })
      .def_property_readonly("boundary_names",
                             [](const PyMesh& s) { return s.mesh->boundary_part_names(); })
      .def_property_readonly("region_names",
                             [](const PyMesh& s) {
                               std::vector<std::string> out;
                               for (const std::string& n : s.mesh->region_names())
                                 if (!n.empty()) out.push_back(n);
                               return out;
                             })
      .def(
          "cells",
          [](const PyMesh& s, const std::string& type) {
            const CellType t = cell_type_named(type, "cell type");
            std::vector<std::int64_t> nodes;
            py::ssize_t count = 0;
            for (Index c = 0; c < s.mesh->num_cells(); ++c)
              if (s.mesh->cell_type(c) == t) {
                for (const Index v : s.mesh->cell(c)) nodes.push_back(v);
                ++count;
              }
            py::array_t<std::int64_t> a({count, static_cast<py::ssize_t>(nodes_per_cell(t))});
            std::copy(nodes.begin(), nodes.end(), a.mutable_data());
            return a;
          },
          py::arg("type"),
          "The cells of one type, (count, nodes per cell), counterclockwise in 2D.")
      .def(
          "boundary_nodes",
          [](const PyMesh& s, const std::string& name) {
            const std::vector<Index> nodes = s.mesh->boundary_part_nodes(name);
            py::array_t<std::int64_t> a(static_cast<py::ssize_t>(nodes.size()));
            std::copy(nodes.begin(), nodes.end(), a.mutable_data());
            return a;
          },
          py::arg("name"), "The distinct nodes of a boundary part, sorted.")
      .def("__repr__",
           [](const PyMesh& s) { return "<signorini.Mesh: " + mesh_description(*s.mesh) + ">"; });
}

}  // namespace signorini::python

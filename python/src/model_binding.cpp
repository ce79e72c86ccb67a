// signorini.Model: the discrete problem of a Problem (build_model): mesh, dofs, stiffness, loads
// and contact set, with the solver path planned from its size.

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "blas_threads.hpp"
#include "numpy_views.hpp"
#include "signorini/core/error.hpp"

namespace signorini::python {

std::shared_ptr<const ModelData> model_of(const py::object& problem_or_model) {
  if (py::isinstance<PyModel>(problem_or_model))
    return problem_or_model.cast<const PyModel&>().data;
  if (!py::isinstance<PyProblem>(problem_or_model))
    throw InputError("expected a signorini.Problem or a signorini.Model, got a " +
                     py::str(py::type::of(problem_or_model).attr("__name__")).cast<std::string>());
  std::shared_ptr<const LoadedProblem> loaded = problem_or_model.cast<const PyProblem&>().loaded;
  py::gil_scoped_release release;
  const SingleThreadedBlas blas;
  try {
    return std::make_shared<const ModelData>(ModelData{loaded, build_model(loaded->spec)});
  } catch (const InputError& e) {
    // As the tool says it (app/model_loading.cpp): the file (or "problem dict") first.
    throw InputError(loaded->path + ": " + e.what());
  }
}

Vector vector_from_numpy(const py::handle& values, Index size, const std::string& what) {
  const auto a = py::array_t<double, py::array::forcecast>::ensure(values);
  if (!a || a.ndim() != 1 || a.shape(0) != size)
    throw InputError(what + ": expected " + std::to_string(size) + " numbers (a 1-D array)");
  Vector v(size);
  const auto r = a.unchecked<1>();
  for (Index i = 0; i < size; ++i) {
    v(i) = r(i);
    if (!std::isfinite(v(i))) throw InputError(what + "[" + std::to_string(i) + "] is not finite");
  }
  return v;
}

namespace {

// A copy of a vector (one the model computes on request).
py::array vector_copy(const Vector& v) {
  py::array_t<double> a(v.size());
  std::copy(v.data(), v.data() + v.size(), a.mutable_data());
  return a;
}

}  // namespace

void bind_model(py::module_& m) {
  py::class_<PyModel>(m, "Model", R"(The discrete problem of a Problem: mesh, unknowns, stiffness,
loads and contact set (built once; a Solver solves it as often as needed).

Model(problem)   problem: a signorini.Problem)")
      .def(py::init([](const py::object& problem) { return PyModel{model_of(problem)}; }),
           py::arg("problem"))
      .def_property_readonly("dim", [](const PyModel& s) { return s.data->model.mesh.dim(); })
      .def_property_readonly("num_dofs",
                             [](const PyModel& s) { return s.data->model.dofs.num_dofs(); })
      .def_property_readonly("num_free_dofs",
                             [](const PyModel& s) { return s.data->model.dofs.num_free(); })
      .def_property_readonly("num_contact_nodes",
                             [](const PyModel& s) { return s.data->model.problem.contact.size(); })
      .def_property_readonly(
          "mesh",
          [](const PyModel& s) {
            // Shares the model's mesh (aliasing: the model stays alive with it).
            return PyMesh{std::shared_ptr<const Mesh>(s.data, &s.data->model.mesh)};
          })
      .def_property_readonly("problem", [](const PyModel& s) { return PyProblem{s.data->loaded}; })
      .def_property_readonly(
          "b",
          [](const py::object& self) {
            return vector_view(self.cast<const PyModel&>().data->model.problem.b, self);
          },
          "The loads on the free unknowns, b = f - K u_D, at load factor 1 (read-only).")
      .def_property_readonly(
          "gaps",
          [](const py::object& self) {
            return vector_view(self.cast<const PyModel&>().data->model.problem.contact.gaps, self);
          },
          "The gap g_j of each contact node to the obstacle (read-only).")
      .def_property_readonly(
          "contact_nodes",
          [](const PyModel& s) {
            const std::vector<Index>& n = s.data->model.problem.contact.nodes;
            py::array_t<std::int64_t> a(static_cast<py::ssize_t>(n.size()));
            std::copy(n.begin(), n.end(), a.mutable_data());
            return a;
          },
          "The mesh node of each contact node, in the order of the solution's pressure.")
      .def_property_readonly(
          "contact_normals",
          [](const py::object& self) {
            return columns_view(self.cast<const PyModel&>().data->model.problem.contact.normals,
                                self);
          },
          "(contact nodes, dim): the outward unit normal at each contact node.")
      .def(
          "free_loads",
          [](const PyModel& s, double factor, int step) {
            return vector_copy(s.data->model.free_loads(factor, step));
          },
          py::arg("factor") = 1.0, py::arg("step") = 0,
          "b at a load factor (and step of the loading history, for loads with factors of "
          "their own).")
      .def(
          "contact_gaps",
          [](const PyModel& s, double factor, int step) {
            return vector_copy(s.data->model.contact_gaps(factor, step));
          },
          py::arg("factor") = 1.0, py::arg("step") = 0,
          "The gaps with the prescribed displacements at a load factor.")
      .def_property_readonly("solver_reason",
                             [](const PyModel& s) { return s.data->model.solver_reason; })
      .def_property_readonly("timings",
                             [](const PyModel& s) { return timings_dict(s.data->model.timings); })
      .def("__repr__", [](const PyModel& s) {
        const Model& md = s.data->model;
        return "<signorini.Model '" + s.data->loaded->spec.name +
               "': " + std::to_string(md.dofs.num_dofs()) + " dofs (" +
               std::to_string(md.dofs.num_free()) + " free), " +
               std::to_string(md.problem.contact.size()) + " contact nodes>";
      });
}

}  // namespace signorini::python

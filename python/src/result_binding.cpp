// signorini.Result: a solution as numpy arrays (views of the solver's vectors where they are
// stored as such), the summary as a dict (the same as summary.json), and the result files
// written by the tool's writers.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cstdlib>
#include <sstream>

#include "bindings.hpp"
#include "numpy_views.hpp"
#include "signorini/core/error.hpp"
#include "signorini/output/contact_csv.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/output/summary_json.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini::python {

namespace {

const Eigen::MatrixXd& displacement_of(PyResult& r) {
  if (!r.displacement) {
    const Model& m = r.data->model;
    const Vector full = m.full_displacement(r.result);
    r.displacement =
        Eigen::Map<const Eigen::MatrixXd>(full.data(), m.mesh.dim(), m.mesh.num_nodes());
  }
  return *r.displacement;
}

const NodalStress& stress_of(PyResult& r) {
  if (!r.stress) {
    const Model& m = r.data->model;
    r.stress = nodal_stress(m.mesh, m.elasticity, m.full_displacement(r.result));
  }
  return *r.stress;
}

// contact.csv's columns (output/contact_csv.hpp), each a numpy array (a list of str for the text
// columns): the file's numbers have 17 digits, so they read back exactly.
py::dict contact_table(const PyResult& r) {
  const std::string csv = contact_csv(r.result, r.data->model);
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  {
    std::istringstream h(line);
    std::string n;
    while (std::getline(h, n, ',')) names.push_back(n);
  }
  std::vector<std::vector<std::string>> columns(names.size());
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    std::istringstream row(line);
    std::string cell;
    for (std::size_t k = 0; k < names.size() && std::getline(row, cell, ','); ++k)
      columns[k].push_back(cell);
  }
  py::dict out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    const std::vector<std::string>& c = columns[k];
    bool numeric = true;
    std::vector<double> v(c.size());
    for (std::size_t i = 0; i < c.size() && numeric; ++i) {
      char* end = nullptr;
      v[i] = std::strtod(c[i].c_str(), &end);
      numeric = end != c[i].c_str() && *end == '\0';
    }
    if (numeric) {
      py::array_t<double> a(static_cast<py::ssize_t>(v.size()));
      std::copy(v.begin(), v.end(), a.mutable_data());
      out[py::str(names[k])] = a;
    } else {
      out[py::str(names[k])] = py::cast(c);
    }
  }
  return out;
}

py::object json_to_python(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

}  // namespace

py::object make_result(ContactResult result, std::shared_ptr<const ModelData> data) {
  result.summary.path_reason = data->model.solver_reason;  // as the tool reports it
  return py::cast(PyResult{std::move(result), std::move(data), std::nullopt, std::nullopt});
}

void raise_if_not_converged(const py::object& result) {
  const SolveSummary& s = result.cast<const PyResult&>().result.summary;
  if (s.converged() || s.termination == Termination::StoppedByCallback) return;
  const py::object type = py::module_::import("signorini._signorini").attr("ConvergenceError");
  const py::object e = type(fmt::format(
      "not converged ({}): {}", enum_to_string(kTerminationNames, s.termination), s.message));
  e.attr("result") = result;
  PyErr_SetObject(type.ptr(), e.ptr());
  throw py::error_already_set();
}

void bind_result(py::module_& m) {
  py::class_<PyResult>(m, "Result", R"(A solution of a Model.

Arrays (read-only; u, pressure, tangential and slip are views of the solver's
vectors, not copies): u (free unknowns), displacement (nodes, dim), pressure
(contact nodes), stress (nodes, 6: xx yy zz xy yz xz), von_mises (nodes); contact
(dict of contact.csv's columns); summary (dict, as summary.json); write(folder)
writes the tool's result files.)")
      .def_property_readonly("u",
                             [](const py::object& self) {
                               return vector_view(self.cast<const PyResult&>().result.u, self);
                             })
      .def_property_readonly("pressure",
                             [](const py::object& self) {
                               return vector_view(self.cast<const PyResult&>().result.l, self);
                             })
      .def_property_readonly(
          "tangential",
          [](const py::object& self) -> py::object {
            const Matrix& t = self.cast<const PyResult&>().result.tangential;
            if (t.size() == 0) return py::none();
            return columns_view(t, self);
          },
          "Friction: (contact nodes, dim - 1) tangential traction in each node's tangent basis; "
          "None without friction.")
      .def_property_readonly("slip",
                             [](const py::object& self) -> py::object {
                               const Vector& s = self.cast<const PyResult&>().result.slip;
                               if (s.size() == 0) return py::none();
                               return vector_view(s, self);
                             })
      .def_property_readonly(
          "displacement",
          [](const py::object& self) {
            return columns_view(displacement_of(self.cast<PyResult&>()), self);
          },
          "(nodes, dim): the displacement of every mesh node, prescribed values included.")
      .def_property_readonly("stress",
                             [](const py::object& self) {
                               return columns_view(stress_of(self.cast<PyResult&>()).sigma, self);
                             })
      .def_property_readonly("von_mises",
                             [](const py::object& self) {
                               return vector_view(stress_of(self.cast<PyResult&>()).von_mises,
                                                  self);
                             })
      .def_property_readonly("contact", &contact_table)
      .def_property_readonly(
          "summary",
          [](const PyResult& r) {
            return json_to_python(summary_to_json(r.result, r.data->model, r.data->loaded->spec));
          })
      .def_property_readonly("converged",
                             [](const PyResult& r) { return r.result.summary.converged(); })
      .def_property_readonly(
          "termination",
          [](const PyResult& r) {
            return std::string(enum_to_string(kTerminationNames, r.result.summary.termination));
          })
      .def_property_readonly("message", [](const PyResult& r) { return r.result.summary.message; })
      .def_property_readonly("iterations",
                             [](const PyResult& r) { return r.result.summary.outer_iterations; })
      .def_property_readonly("energy", [](const PyResult& r) { return r.result.summary.energy; })
      .def_property_readonly("contact_force",
                             [](const PyResult& r) { return r.result.summary.contact_force; })
      .def_property_readonly("num_active",
                             [](const PyResult& r) { return r.result.summary.num_active; })
      .def_property_readonly("load_factor", [](const PyResult& r) { return r.result.load_factor; })
      .def_property_readonly("load_step", [](const PyResult& r) { return r.result.load_step; })
      .def_property_readonly(
          "timings", [](const PyResult& r) { return timings_dict(r.result.summary.timings); })
      .def(
          "write",
          [](const PyResult& r, const py::object& folder) {
            const std::string f = path_text(folder);
            py::gil_scoped_release release;
            const Resultants resultants = compute_resultants(r.data->model, r.result);
            write_results(f, r.result, r.data->model, r.data->loaded->spec, resultants);
          },
          py::arg("folder"),
          "Writes summary.json, contact.csv, solution.vtu and contact.vtu into `folder` (made if "
          "needed), all or none, as the tool does.")
      .def("__repr__", [](const PyResult& r) {
        const SolveSummary& s = r.result.summary;
        return fmt::format(
            "<signorini.Result: {} after {} iterations, energy {:.10e}, {} nodes in "
            "contact>",
            s.converged() ? "converged"
                          : std::string("NOT converged (") +
                                std::string(enum_to_string(kTerminationNames, s.termination)) + ")",
            s.outer_iterations, s.energy, s.num_active);
      });
}

}  // namespace signorini::python

// signorini.Problem: a problem file, or a dict with the same keys, read by the problem-file
// reader (the same checks and messages), optionally with a Mesh in place of [mesh].

#include <pybind11/stl.h>

#include "bindings.hpp"
#include "python_to_toml.hpp"
#include "signorini/core/error.hpp"
#include "signorini/input/problem_table.hpp"

namespace signorini::python {

namespace {

// --set overrides: a list of "key=value" strings, or a dict {dotted key: Python value}.
std::vector<std::string> override_list(const py::handle& overrides, const std::string& what) {
  std::vector<std::string> out;
  if (overrides.is_none()) return out;
  if (py::isinstance<py::dict>(overrides)) {
    for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(overrides)) {
      const std::string key = py::str(k);
      out.push_back(key + "=" + toml_value_text(v, key, what));
    }
    return out;
  }
  if (py::isinstance<py::str>(overrides))
    throw InputError("overrides: expected a list of \"key=value\" strings or a dict, got a string");
  for (const py::handle o : py::reinterpret_borrow<py::iterable>(overrides))
    out.push_back(py::str(o).cast<std::string>());
  return out;
}

PyProblem make_problem(const py::object& source, const py::object& mesh,
                       const py::object& overrides) {
  std::shared_ptr<const Mesh> given;
  if (!mesh.is_none()) given = mesh.cast<const PyMesh&>().mesh;
  if (py::isinstance<py::dict>(source)) {
    const std::string what = "problem dict";
    const std::vector<std::string> o = override_list(overrides, what);
    toml::table t = toml_table(source.cast<py::dict>(), what);
    // A dict has no file name to give the problem its name.
    if (!t.contains("name")) t.insert("name", "problem");
    py::gil_scoped_release release;
    return PyProblem{std::make_shared<const LoadedProblem>(
        read_problem_table(std::move(t), what, o, std::move(given)))};
  }
  if (!py::isinstance<py::str>(source) && !py::hasattr(source, "__fspath__"))
    throw InputError("Problem: expected the path of a problem file or a dict, got a " +
                     py::str(py::type::of(source).attr("__name__")).cast<std::string>());
  const std::string path = path_text(source);
  const std::vector<std::string> o = override_list(overrides, path);
  py::gil_scoped_release release;
  return PyProblem{
      std::make_shared<const LoadedProblem>(read_problem_file(path, o, std::move(given)))};
}

}  // namespace

void bind_problem(py::module_& m) {
  py::class_<PyProblem>(m, "Problem", R"(A contact problem, read and checked.

Problem(source, mesh=None, overrides=None)
  source     the path of a problem file (TOML), or a dict with the same keys
             (docs/problem-format.md): {"material": {"E": 2e5, "nu": 0.3}, ...}
  mesh       a signorini.Mesh for a problem without [mesh]
  overrides  ["mesh.nx=60", ...] or {"mesh.nx": 60, ...}, as the tool's --set

Errors raise signorini.InputError with the tool's one-line message.)")
      .def(py::init(&make_problem), py::arg("source"), py::arg("mesh") = py::none(),
           py::arg("overrides") = py::none())
      .def_property_readonly("name", [](const PyProblem& p) { return p.loaded->spec.name; })
      .def_property_readonly(
          "path", [](const PyProblem& p) { return p.loaded->path; },
          "The file name (or \"problem dict\") that messages use.")
      .def_property_readonly(
          "settings", [](const PyProblem& p) { return p.loaded->effective_toml; },
          "The effective settings as TOML: every default filled in, overrides applied.")
      .def_property_readonly("warnings", [](const PyProblem& p) { return p.loaded->warnings; })
      .def_property_readonly("load_factors",
                             [](const PyProblem& p) { return p.loaded->spec.load_factors; })
      .def("__repr__", [](const PyProblem& p) {
        return "<signorini.Problem '" + p.loaded->spec.name + "' from " + p.loaded->path + ">";
      });
}

}  // namespace signorini::python

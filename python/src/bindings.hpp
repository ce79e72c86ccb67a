#pragma once
// The parts of the extension module signorini._signorini, one file each (module.cpp joins them).

#include <pybind11/pybind11.h>

#include "bound_objects.hpp"

namespace signorini::python {

namespace py = pybind11;

void bind_errors(py::module_& m);
void bind_mesh(py::module_& m);
void bind_problem(py::module_& m);
void bind_model(py::module_& m);
void bind_result(py::module_& m);
void bind_solver(py::module_& m);

/// A path argument (str or os.PathLike) as text.
inline std::string path_text(const py::handle& path) {
  return py::str(py::module_::import("os").attr("fspath")(path));
}

/// A timing table as {phase: seconds}.
inline py::dict timings_dict(const TimingTable& t) {
  py::dict d;
  for (const auto& [phase, seconds] : t.phases()) d[py::str(phase)] = seconds;
  return d;
}

/// A Result object for a solution of `data`'s model.
py::object make_result(ContactResult result, std::shared_ptr<const ModelData> data);

/// Raises signorini.ConvergenceError, with the Result as its `result`, where a solve stopped
/// short of convergence (except when a callback stopped it: the caller asked for that).
void raise_if_not_converged(const py::object& result);

/// The model of a Problem or a Model argument (a Problem is built here, the GIL released).
std::shared_ptr<const ModelData> model_of(const py::object& problem_or_model);

}  // namespace signorini::python

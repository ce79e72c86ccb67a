#pragma once
// What the Python objects hold. A Problem, a Model and the results made from it share the
// model's data (shared_ptr), so that a Result outlives the Solver and the Model objects that made
// it, and numpy arrays over a Result's vectors keep the Result alive (numpy_views.hpp).

#include <pybind11/pybind11.h>

#include <exception>
#include <memory>
#include <mutex>
#include <optional>

#include "signorini/contact/contact_solver.hpp"
#include "signorini/fem/nodal_stress.hpp"
#include "signorini/input/problem_file.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::python {

namespace py = pybind11;

/// signorini.Mesh: a mesh, immutable once made (shared with the problems given it).
struct PyMesh {
  std::shared_ptr<const Mesh> mesh;
};

/// signorini.Problem: a problem read and checked (LoadedProblem: spec, effective settings,
/// warnings).
struct PyProblem {
  std::shared_ptr<const LoadedProblem> loaded;
};

/// The model with the problem it was built from (the writers and the summary need the spec).
struct ModelData {
  std::shared_ptr<const LoadedProblem> loaded;
  Model model;
};

/// signorini.Model.
struct PyModel {
  std::shared_ptr<const ModelData> data;
};

/// signorini.Result: a solution with its model, and what is computed from it on first use.
struct PyResult {
  ContactResult result;
  std::shared_ptr<const ModelData> data;
  std::optional<Eigen::MatrixXd> displacement;  // dim x nodes
  std::optional<NodalStress> stress;
};

/// signorini.Solver: a ContactSolver set up once for a model, solved as often as needed.
struct PySolver {
  std::shared_ptr<const ModelData> data;
  py::object callback;  // None, or called with each iteration's event
  std::unique_ptr<ContactSolver> solver;
  std::mutex busy;  // one solve at a time (the GIL is released while it runs)
  double load_factor = 1.0;
  int load_step = 0;
  std::exception_ptr callback_error;  // raised by the callback, re-raised after the solve
};

}  // namespace signorini::python

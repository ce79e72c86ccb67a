// signorini.Solver: ContactSolver (the engine: set up once, solve again with new loads or gaps,
// warm starts) with the GIL released while it solves, and a Python callback that sees every
// iteration and may stop the run; and signorini.solve(), what `signorini solve` does.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include "bindings.hpp"
#include "blas_threads.hpp"
#include "numpy_views.hpp"
#include "signorini/core/error.hpp"
#include "signorini/output/result_writer.hpp"
#include "signorini/problem/load_stepping.hpp"
#include "signorini/problem/resultants.hpp"

namespace signorini::python {

namespace {

py::dict event_dict(const IterationEvent& e) {
  py::dict d;
  d["kind"] = e.kind == IterationEvent::Kind::Outer ? "outer" : "inner";
  d["outer"] = e.outer;
  d["inner"] = e.inner;
  d["active"] = e.active;
  d["residual"] = e.residual;
  d["armijo"] = e.armijo;
  d["linear_iterations"] = e.linear_iterations;
  return d;
}

// The solver's callback: with the GIL, Ctrl-C (a pending KeyboardInterrupt) and then the user's
// function; a false return value (not None) stops the run, an exception stops it and is raised
// again once the solve has returned.
CallbackAction call_back(const py::object& callback, std::exception_ptr& error,
                         const IterationEvent& e) {
  py::gil_scoped_acquire gil;
  try {
    if (PyErr_CheckSignals() != 0) throw py::error_already_set();
    if (callback.is_none()) return CallbackAction::Continue;
    const py::object answer = callback(event_dict(e));
    if (!answer.is_none() && PyObject_IsTrue(answer.ptr()) == 0) return CallbackAction::Stop;
  } catch (...) {
    error = std::current_exception();
    return CallbackAction::Stop;
  }
  return CallbackAction::Continue;
}

ContactSolverOptions options_for(const ModelData& data, PySolver* s) {
  ContactSolverOptions o = data.model.solver;  // the path planned from the problem's size
  o.callback = [s](const IterationEvent& e) {
    return call_back(s->callback, s->callback_error, e);
  };
  return o;
}

void rethrow_callback_error(std::exception_ptr& error) {
  if (!error) return;
  std::exception_ptr e = error;
  error = nullptr;
  std::rethrow_exception(e);
}

py::object solve_once(PySolver& s, bool check) {
  std::unique_lock lock(s.busy, std::try_to_lock);
  if (!lock.owns_lock())
    throw std::runtime_error("Solver.solve: this solver is solving already (in another thread)");
  ContactResult r;
  {
    py::gil_scoped_release release;
    const SingleThreadedBlas blas;
    r = s.solver->solve();
  }
  rethrow_callback_error(s.callback_error);
  r.load_factor = s.load_factor;
  r.load_step = s.load_step;
  py::object result = make_result(std::move(r), s.data);
  if (check) raise_if_not_converged(result);
  return result;
}

// signorini.solve(problem, output=None, ...): the tool's `solve` as a library call.
py::object solve_problem(const py::object& problem, const py::object& output,
                         const py::object& callback, const py::object& each_step, bool check) {
  const std::shared_ptr<const ModelData> data = model_of(problem);
  const Model& model = data->model;
  const ProblemSpec& spec = data->loaded->spec;
  const std::string folder = output.is_none() ? "" : path_text(output);
  if (!folder.empty()) create_output_folder(folder);  // before the solve: a bad folder fails fast
  std::exception_ptr error;
  ContactSolverOptions options = model.solver;
  options.callback = [&](const IterationEvent& e) { return call_back(callback, error, e); };
  ContactResult result;
  {
    py::gil_scoped_release release;
    const SingleThreadedBlas blas;
    result = solve_model(model, options, spec.load_factors, [&](int step, const ContactResult& r) {
      if (!folder.empty()) write_load_step(folder, step, r, model);
      if (each_step.is_none() || error) return;
      py::gil_scoped_acquire gil;
      try {
        ContactResult copy = r;
        each_step(step, make_result(std::move(copy), data));
      } catch (...) {
        error = std::current_exception();
      }
    });
  }
  rethrow_callback_error(error);
  py::object out = make_result(std::move(result), data);
  if (!folder.empty()) {
    const PyResult& r = out.cast<const PyResult&>();
    py::gil_scoped_release release;
    write_results(folder, r.result, model, spec, compute_resultants(model, r.result));
  }
  if (check) raise_if_not_converged(out);
  return out;
}

}  // namespace

void bind_solver(py::module_& m) {
  py::class_<PySolver>(m, "Solver", R"(A contact solver set up once for a Model, solved as often
as needed (new loads or gaps, warm starts): the engine of `signorini solve`.

Solver(model, callback=None)
  model     a signorini.Model (or a Problem, built here)
  callback  called with a dict per iteration (kind "inner"/"outer", outer, inner,
            active, residual, armijo, linear_iterations); returning False stops
            the run (the result then says termination "stopped_by_callback"), an
            exception stops it and is raised from solve()

solve(check=True) releases the GIL while it runs; with check, a run that stops short
of convergence raises signorini.ConvergenceError (its .result holds the iterate).)")
      .def(py::init([](const py::object& model, const py::object& callback) {
             auto s = std::make_unique<PySolver>();
             s->data = model_of(model);
             s->callback = callback;
             const ContactSolverOptions o = options_for(*s->data, s.get());
             const Model& md = s->data->model;
             py::gil_scoped_release release;
             const SingleThreadedBlas blas;
             s->solver = std::make_unique<ContactSolver>(md.problem, o, &md.multigrid);
             return s;
           }),
           py::arg("model"), py::arg("callback") = py::none())
      .def("solve", &solve_once, py::arg("check") = true)
      .def(
          "set_loads",
          [](PySolver& s, const py::handle& b) {
            s.solver->set_loads(
                vector_from_numpy(b, s.data->model.dofs.num_free(), "Solver.set_loads: b"));
          },
          py::arg("b"), "New loads b on the free unknowns (Model.b's size).")
      .def(
          "set_gaps",
          [](PySolver& s, const py::handle& g) {
            s.solver->set_gaps(vector_from_numpy(g, s.data->model.problem.contact.size(),
                                                 "Solver.set_gaps: gaps"));
          },
          py::arg("gaps"), "New gaps of the contact nodes (Model.gaps's size).")
      .def(
          "set_load_factor",
          [](PySolver& s, double factor, int step) {
            if (!std::isfinite(factor))
              throw InputError("Solver.set_load_factor: factor must be finite");
            // A step picks the factors of the entries with their own: it must be one of the
            // history's (0: none, every load times `factor`).
            const auto steps = static_cast<int>(s.data->loaded->spec.load_factors.size());
            if (step < 0 || step > steps)
              throw InputError(fmt::format(
                  "Solver.set_load_factor: step = {} is not a step of the problem's loading "
                  "history: expected {}",
                  step,
                  steps == 0 ? "0 (the problem has no [loading])"
                             : fmt::format("0 to {} ([loading] has {} steps)", steps, steps)));
            const Model& md = s.data->model;
            s.solver->set_loads(md.free_loads(factor, step));
            if (md.dofs.has_prescribed_values()) s.solver->set_gaps(md.contact_gaps(factor, step));
            s.load_factor = factor;
            s.load_step = step;
          },
          py::arg("factor"), py::arg("step") = 0,
          "Loads and prescribed displacements times `factor` (those with factors of their own "
          "at step `step` of the problem's loading history); results remember it.")
      .def(
          "warm_start",
          [](PySolver& s, const PyResult& previous) {
            if (previous.data != s.data)
              throw InputError("Solver.warm_start: the result is of another model");
            s.solver->warm_start(previous.result);
          },
          py::arg("result"), "Start the next solves from this result's (u, l).")
      .def(
          "cold_start", [](PySolver& s) { s.solver->cold_start(); },
          "Back to the paper's start u = 0, l = 0.")
      .def(
          "set_slip_origin",
          [](PySolver& s, const PyResult& r) { s.solver->set_slip_origin(r.result.u); },
          py::arg("result"), "Friction: slip is measured from this result's displacement.")
      .def_property_readonly(
          "path",
          [](const PySolver& s) {
            return std::string(enum_to_string(kSolvePathNames, s.solver->path()));
          })
      .def_property_readonly("model", [](const PySolver& s) { return PyModel{s.data}; });

  m.def("solve", &solve_problem, py::arg("problem"), py::arg("output") = py::none(),
        py::arg("callback") = py::none(), py::arg("each_step") = py::none(),
        py::arg("check") = true,
        R"(Solves a Problem (or Model) as `signorini solve` does: the loading history of
[loading] step by step (each_step(step, result) after each), and with `output` the
result files in that folder (and steps/, solution.pvd for a history). Returns the
(last step's) Result; raises ConvergenceError where it did not converge (check=True).)");
}

}  // namespace signorini::python

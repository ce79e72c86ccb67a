// signorini._signorini, the extension module of the Python package signorini (python/signorini/
// adds what is plain Python: meshio conversion). Errors become Python exceptions with the tool's
// one-line messages: InputError (a ValueError) for bad input, NumericalError (a RuntimeError),
// ConvergenceError (a RuntimeError) where a solve stopped short.

#include "bindings.hpp"
#include "signorini/config.hpp"
#include "signorini/core/error.hpp"

namespace signorini::python {

namespace {
struct ConvergenceTag {};  // ConvergenceError has no C++ exception of its own
}  // namespace

void bind_errors(py::module_& m) {
  static py::exception<InputError> input_error(m, "InputError", PyExc_ValueError);
  static py::exception<NumericalError> numerical_error(m, "NumericalError", PyExc_RuntimeError);
  // Raised by raise_if_not_converged, with the Result attached.
  static py::exception<ConvergenceTag> convergence_error(m, "ConvergenceError", PyExc_RuntimeError);
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(input_error.ptr(), e.what());
    } catch (const NumericalError& e) {
      PyErr_SetString(numerical_error.ptr(), e.what());
    }
  });
}

}  // namespace signorini::python

PYBIND11_MODULE(_signorini, m) {
  namespace sp = signorini::python;
  m.doc() = "signorini: contact problems of linear elasticity (the C++ library's bindings)";
  m.attr("__version__") = SIGNORINI_VERSION;
  sp::bind_errors(m);
  sp::bind_mesh(m);
  sp::bind_problem(m);
  sp::bind_model(m);
  sp::bind_result(m);
  sp::bind_solver(m);
}

#pragma once
// numpy arrays over memory that a Python object owns (a Result's vectors): no copy, read-only
// (the solver's output is not the user's to change in place), and the owner kept alive for as
// long as the array is.

#include <pybind11/numpy.h>

#include "signorini/core/types.hpp"

namespace signorini::python {

namespace py = pybind11;

/// A read-only array of `shape` over `data` with strides in bytes, owned by `owner`.
inline py::array readonly_view(const double* data, std::vector<py::ssize_t> shape,
                               std::vector<py::ssize_t> strides, py::handle owner) {
  py::array a(py::dtype::of<double>(), std::move(shape), std::move(strides), data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

/// A vector as a 1-D array.
inline py::array vector_view(const Vector& v, py::handle owner) {
  return readonly_view(v.data(), {v.size()}, {static_cast<py::ssize_t>(sizeof(double))}, owner);
}

/// A column-major rows x cols matrix (one point or node per column) as a cols x rows array:
/// numpy's row per point, the same memory.
inline py::array columns_view(const Eigen::MatrixXd& m, py::handle owner) {
  const auto s = static_cast<py::ssize_t>(sizeof(double));
  return readonly_view(m.data(), {m.cols(), m.rows()}, {m.rows() * s, s}, owner);
}

/// A copy of a numpy vector (any float dtype, any strides) of `size` entries; `what` names it
/// in the InputError for a wrong size or a value that is not finite.
Vector vector_from_numpy(const py::handle& values, Index size, const std::string& what);

}  // namespace signorini::python

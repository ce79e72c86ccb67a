#include "python_to_toml.hpp"

#include <fmt/format.h>

#include <cmath>
#include <sstream>
#include <variant>

#include "signorini/core/error.hpp"

namespace signorini::python {

namespace {

using Value = std::variant<bool, std::int64_t, double, std::string, toml::array, toml::table>;

std::string type_of(const py::handle& v) {
  return py::str(py::type::of(v).attr("__name__"));
}

// Whether v is an instance of numpy's `name` (bool_, floating, ndarray): false where numpy has
// not been imported, in which case no value can be one (and a dict of plain values does not
// import it).
bool is_numpy(const py::handle& v, const char* name) {
  const py::dict modules = py::module_::import("sys").attr("modules");
  if (!modules.contains("numpy")) return false;
  return py::isinstance(v, modules["numpy"].attr(name));
}

Value convert(const py::handle& v, const std::string& key, const std::string& what);

toml::table table_of(const py::handle& d, const std::string& path, const std::string& what) {
  toml::table t;
  for (const auto& [k, v] : py::reinterpret_borrow<py::dict>(d)) {
    if (!py::isinstance<py::str>(k))
      throw InputError(fmt::format("{}: key {} in '{}' is a {}, expected a string", what,
                                   py::repr(k).cast<std::string>(), path.empty() ? "" : path,
                                   type_of(k)));
    const std::string name = k.cast<std::string>();
    const std::string full = path.empty() ? name : path + "." + name;
    std::visit([&](auto&& x) { t.insert_or_assign(name, std::move(x)); }, convert(v, full, what));
  }
  return t;
}

Value convert(const py::handle& v, const std::string& key, const std::string& what) {
  PyObject* o = v.ptr();
  if (o == Py_None)
    throw InputError(fmt::format(
        "{}: key '{}' is None: give a value, or leave the key out for its default", what, key));
  if (PyBool_Check(o)) return o == Py_True;
  if (is_numpy(v, "bool_")) return PyObject_IsTrue(o) == 1;
  if (py::isinstance<py::str>(v)) return v.cast<std::string>();
  // Before the numbers: an array has __index__ too (for its 0-d integer kind).
  if (is_numpy(v, "ndarray")) return convert(v.attr("tolist")(), key, what);
  if (PyFloat_Check(o) || is_numpy(v, "floating")) return PyFloat_AsDouble(o);
  if (PyIndex_Check(o)) {
    int overflow = 0;
    const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(o));
    if (!i) throw py::error_already_set();
    const long long x = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
    if (overflow != 0)
      throw InputError(fmt::format("{}: key '{}' = {} does not fit a 64-bit integer", what, key,
                                   py::str(v).cast<std::string>()));
    return static_cast<std::int64_t>(x);
  }
  if (py::hasattr(v, "__fspath__")) return py::str(v.attr("__fspath__")()).cast<std::string>();
  if (PyDict_Check(o) || py::isinstance(v, py::module_::import("collections.abc").attr("Mapping")))
    return table_of(py::dict(py::reinterpret_borrow<py::object>(v)), key, what);
  if (PyList_Check(o) || PyTuple_Check(o)) {
    toml::array a;
    std::size_t i = 0;
    for (const py::handle item : py::reinterpret_borrow<py::sequence>(v)) {
      std::visit([&](auto&& x) { a.push_back(std::move(x)); },
                 convert(item, fmt::format("{}[{}]", key, i++), what));
    }
    return a;
  }
  throw InputError(fmt::format(
      "{}: key '{}' is a {}, which a problem cannot hold (expected a bool, number, string, "
      "list or dict)",
      what, key, type_of(v)));
}

}  // namespace

toml::table toml_table(const py::dict& d, const std::string& what) {
  return table_of(d, "", what);
}

namespace {

std::string toml_string(const std::string& s) {
  std::ostringstream os;
  os << toml::toml_formatter(toml::value<std::string>(s), toml::format_flags::none);
  return os.str();
}

// TOML text of a value; floats in the shortest form that reads back to the same double.
std::string text_of(const Value& v) {
  return std::visit(
      [](const auto& x) -> std::string {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, bool>) {
          return x ? "true" : "false";
        } else if constexpr (std::is_same_v<T, std::int64_t>) {
          return std::to_string(x);
        } else if constexpr (std::is_same_v<T, double>) {
          if (std::isnan(x)) return "nan";
          if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
          std::string t = fmt::format("{}", x);
          if (t.find_first_of(".eE") == std::string::npos) t += ".0";
          return t;
        } else if constexpr (std::is_same_v<T, std::string>) {
          return toml_string(x);
        } else {
          std::ostringstream os;
          os << toml::toml_formatter(x, toml::format_flags::none);
          return os.str();
        }
      },
      v);
}

}  // namespace

std::string toml_value_text(const py::handle& value, const std::string& key,
                            const std::string& what) {
  const Value v = convert(value, key, what);
  if (const auto* a = std::get_if<toml::array>(&v)) {
    // Element by element, so that every float keeps all its digits.
    std::string out = "[";
    std::size_t i = 0;
    const py::object items = is_numpy(value, "ndarray") ? py::object(value.attr("tolist")())
                                                        : py::reinterpret_borrow<py::object>(value);
    for (const py::handle item : py::reinterpret_borrow<py::sequence>(items)) {
      out += (i == 0 ? "" : ", ") + toml_value_text(item, fmt::format("{}[{}]", key, i), what);
      ++i;
    }
    (void)a;
    return out + "]";
  }
  if (std::holds_alternative<toml::table>(v))
    throw InputError(
        fmt::format("{}: key '{}' is a dict: give each of its keys as a dotted name ('{}.name')",
                    what, key, key));
  return text_of(v);
}

}  // namespace signorini::python

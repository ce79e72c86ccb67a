#pragma once
// A problem given as a Python dict, with the keys of a problem file (docs/problem-format.md),
// turned into the TOML table the problem-file reader reads: the same checks and messages as a
// file, from one set of option tables. Python values map to TOML's: bool, int, float, str (and
// os.PathLike), dict (a table), list or tuple or numpy array (an array; a list of dicts is an
// array of tables, [[clamp]]); numpy scalars count as Python numbers.

#include <pybind11/pybind11.h>
#include <toml++/toml.h>

#include <string>

namespace signorini::python {

namespace py = pybind11;

/// The table of a dict; `what` names the dict in messages ("problem dict"). Throws InputError
/// "<what>: key 'material.E' is None: ..." or "... is a <type>, which a problem file cannot
/// hold".
toml::table toml_table(const py::dict& d, const std::string& what);

/// A value as the TOML text of an override ("mesh.nx=60" from ("mesh.nx", 60)).
std::string toml_value_text(const py::handle& value, const std::string& key,
                            const std::string& what);

}  // namespace signorini::python

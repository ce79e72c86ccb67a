#pragma once
// Problem files: a TOML description of a contact problem (docs/problem-format.md), read into a
// ProblemSpec. Keys equal the option names of the library structs; every key is checked (unknown
// keys, types, ranges) before any work starts, and every error is one line naming the file and
// the key.

#include <memory>
#include <string>
#include <vector>

#include "signorini/mesh/mesh.hpp"
#include "signorini/problem/memory_estimate.hpp"
#include "signorini/problem/problem_spec.hpp"

namespace signorini {

struct LoadedProblem {
  ProblemSpec spec;
  /// The settings of the run, after --set overrides and with every default filled in, as TOML
  /// text that reads back to the same spec: echoed at the start of a run so that a log says
  /// exactly what was solved.
  std::string effective_toml;
  /// The file name, as given (used in messages).
  std::string path;
  /// Settings that are valid but probably not what was meant, one line each, naming the file and
  /// the key (e.g. a Poisson ratio above 0.49, where Q1 elements lock): printed as warnings.
  std::vector<std::string> warnings;
};

/// Reads a problem file and applies overrides, each "dotted.key=value", e.g. "mesh.nx=480" or
/// "solver.method=semismooth_newton". The value is read as a TOML value ("1e8", "[\"0\", \"1\"]",
/// "true"); text that is not valid TOML is taken as a string. Missing tables on the way are
/// created; "clamp.0.boundary" indexes an array of tables. Throws InputError: "cannot read
/// '<path>': <reason>", "<path>:<line>:<column>: TOML syntax error: ...", or "<path>: ..." for
/// unknown keys, missing keys, wrong types and values out of range.
///
/// `mesh`: a mesh the program gives (mesh/mesh_arrays.hpp) instead of the file's [mesh], which
/// must then be left out (mesh.type is then "given", and points and vectors are checked against
/// the mesh's dimension as the file is read).
LoadedProblem read_problem_file(const std::string& path,
                                const std::vector<std::string>& overrides = {},
                                std::shared_ptr<const Mesh> mesh = nullptr);

/// As read_problem_file, from the text of a file; `name_for_errors` stands for the file name in
/// messages (and gives the default problem name, its stem).
LoadedProblem parse_problem_string(const std::string& toml_text, const std::string& name_for_errors,
                                   const std::vector<std::string>& overrides = {},
                                   std::shared_ptr<const Mesh> mesh = nullptr);

}  // namespace signorini

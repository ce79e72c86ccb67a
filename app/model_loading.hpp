#pragma once
// Building the model of a problem file, with the file named in the errors build_model() finds
// (an unknown boundary name is a mistake in the file).

#include <string>
#include <vector>

#include "signorini/input/problem_file.hpp"
#include "signorini/problem/model.hpp"

namespace signorini::app {

/// build_model(loaded.spec, engine); an InputError gets the prefix "<file>: ".
Model build_model_for(const LoadedProblem& loaded, DistributedEngine* engine = nullptr);

/// "signorini: warning: <message>" on stderr for each of loaded.warnings (also with --quiet:
/// stderr is for what needs attention).
void print_warnings(const LoadedProblem& loaded);

/// The warnings that the built model adds (mesh_warnings: a Gmsh mesh's cells), each with the
/// problem file's name first.
[[nodiscard]] std::vector<std::string> model_warnings(const LoadedProblem& loaded,
                                                      const Model& model);
/// As print_warnings, for these.
void print_warnings(const std::vector<std::string>& warnings);

}  // namespace signorini::app

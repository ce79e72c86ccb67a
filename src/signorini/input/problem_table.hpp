#pragma once
// A problem from a TOML table already in memory, as a program builds it (the Python package turns
// a dict into one): the same reader, checks and messages as a problem file, with `name_for_errors`
// in place of the file name. A value built in memory has no line, so its messages name the key
// alone. Kept out of the public headers, which do not expose toml++.

#include <toml++/toml.h>

#include "signorini/input/problem_file.hpp"

namespace signorini {

/// As parse_problem_string, from a table.
LoadedProblem read_problem_table(toml::table root, const std::string& name_for_errors,
                                 const std::vector<std::string>& overrides = {},
                                 std::shared_ptr<const Mesh> mesh = nullptr);

}  // namespace signorini

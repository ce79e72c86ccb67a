#pragma once
// The effective settings of a run (docs/problem-format.md, "What a run prints and writes"): the
// problem after --set overrides, with every default filled in, as TOML that reads back to the
// same problem. The option tables give the keys, their order and their values; the sections of
// formulas and lists are written from the texts they were read from.

#include <string>
#include <vector>

#include "signorini/problem/problem_spec.hpp"

namespace signorini {

/// The expressions as written, for the effective settings (the spec keeps only callables).
struct ExpressionTexts {
  std::vector<std::vector<std::string>> tractions;
  std::vector<std::string> body_force;
};

std::string effective_toml(const ProblemSpec& spec, const ExpressionTexts& texts);

}  // namespace signorini

#pragma once
// The usual mistakes behind a TOML syntax error, said in the problem file's terms
// (docs/problem-format.md, "Syntax errors"): a number with a unit ("E = 210000 MPa") and a formula
// without quotes ("gap = 0.1*x", "p = [0, -x]").

#include <cstddef>
#include <string>

namespace signorini {

/// What is wrong with line `number` (1-based) of `text`, as "key 'material.E' = 210000 MPa: a
/// number cannot carry a unit; ...", or an empty string when the line is none of the usual
/// mistakes (the parser's own message is then the best there is).
std::string explain_syntax_error(const std::string& text, std::size_t number);

}  // namespace signorini

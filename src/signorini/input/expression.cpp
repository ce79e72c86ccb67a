#include "signorini/input/expression.hpp"

#include <fmt/format.h>
#include <muParser.h>

#include <numbers>

#include "signorini/core/error.hpp"

namespace signorini {

namespace {

// Error messages are one line (core/error.hpp), but a formula from a TOML multi-line string may
// hold line breaks, and muParser quotes the offending token: control characters are written as
// escapes, and a very long formula is shortened.
std::string one_line(const std::string& text, std::size_t max_length = 200) {
  std::string out;
  for (const char c : text) {
    if (out.size() >= max_length) {
      out += "...";
      break;
    }
    const auto u = static_cast<unsigned char>(c);
    if (c == '\n')
      out += "\\n";
    else if (c == '\r')
      out += "\\r";
    else if (c == '\t')
      out += "\\t";
    else if (u < 0x20 || u == 0x7f)
      out += fmt::format("\\x{:02x}", u);
    else
      out += c;
  }
  return out;
}

// muParser's built-in functions (and the ternary `c ? a : b`, comparisons, && and ||).
constexpr const char* kFunctionNames =
    "sqrt, abs, exp, log (natural), log10, sin, cos, tan, atan, min, max, sign and c ? a : b";

}  // namespace

struct ScalarExpression::State {
  std::string text;
  mu::Parser parser;
  // muParser reads the variables through these addresses at every Eval().
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

ScalarExpression::ScalarExpression(const std::string& expression, const std::string& key)
    : state_(std::make_shared<State>()) {
  State& s = *state_;
  s.text = expression;
  const auto fail = [&](const std::string& why) {
    return InputError(key + ": cannot parse expression '" + one_line(expression) +
                      "': " + one_line(why));
  };
  try {
    s.parser.DefineVar("x", &s.x);
    s.parser.DefineVar("y", &s.y);
    s.parser.DefineVar("z", &s.z);
    s.parser.DefineConst("pi", std::numbers::pi);
    s.parser.DefineConst("e", std::numbers::e);
    s.parser.SetExpr(expression);
    // muParser parses lazily, at the first Eval(): evaluate once now so that syntax errors and
    // unknown names surface here, while the problem file is read.
    s.parser.Eval();
  } catch (const mu::Parser::exception_type& e) {
    // An unknown name is the usual mistake ("X", "t", "sqr"): say which names there are.
    if (e.GetCode() == mu::ecUNASSIGNABLE_TOKEN && !e.GetToken().empty())
      throw fail(
          fmt::format("unknown name '{}' at position {}; the variables are x, y, z and the "
                      "constants pi and e; functions: {}",
                      one_line(e.GetToken()), e.GetPos(), kFunctionNames));
    throw fail(e.GetMsg());
  }
  // "1, 2" is valid muParser (several results); as one component it is surely a mistake.
  if (s.parser.GetNumResults() != 1) throw fail("expected a single value, got a list");
}

double ScalarExpression::operator()(double x, double y, double z) const {
  State& s = *state_;
  s.x = x;
  s.y = y;
  s.z = z;
  // Parsing succeeded at construction, so Eval() can only fail on numerics, which muParser
  // reports as NaN/inf: the assembly checks those and names the field.
  return s.parser.Eval();
}

const std::string& ScalarExpression::text() const {
  return state_->text;
}

ScalarField make_scalar_field(const std::string& expression, const std::string& key) {
  ScalarExpression e(expression, key);
  return [e](const Point& p) { return e(p); };
}

VectorField make_vector_field(const std::vector<std::string>& expressions, const std::string& key) {
  if (expressions.empty() || expressions.size() > 3)
    throw InputError(key + ": expected 2 or 3 component expressions, got " +
                     std::to_string(expressions.size()));
  std::vector<ScalarExpression> components;
  components.reserve(expressions.size());
  for (std::size_t i = 0; i < expressions.size(); ++i)
    components.emplace_back(expressions[i], key + "[" + std::to_string(i) + "]");
  return [components](const Point& p) {
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < components.size(); ++i)
      v(static_cast<Eigen::Index>(i)) = components[i](p);
    return v;
  };
}

}  // namespace signorini

#pragma once
// Fields given in a problem file as formulas of the position, e.g. "-2/3*(3 - x)", evaluated by
// muParser. The variables are x, y, z; `pi` and muParser's built-in functions (sin, exp, sqrt, ...,
// min, max, and the ternary `c ? a : b`) are available.

#include <memory>
#include <string>
#include <vector>

#include "signorini/fem/vector_field.hpp"

namespace signorini {

/// One formula of x, y, z. The formula is parsed at construction, so that a typo is reported
/// while the problem file is read and not in the middle of an assembly.
///
/// Not thread-safe: muParser evaluates through variables bound to this object, so one
/// ScalarExpression (and every copy of it, which shares the parser) must be evaluated by one
/// thread at a time. Make a new one per thread instead.
class ScalarExpression {
 public:
  /// Throws InputError "<key>: cannot parse expression '<expr>': <reason>" on a syntax error, an
  /// unknown variable or a list of several values; `key` names where the formula came from.
  ScalarExpression(const std::string& expression, const std::string& key);

  double operator()(double x, double y, double z = 0.0) const;
  double operator()(const Point& p) const { return (*this)(p(0), p(1), p(2)); }

  [[nodiscard]] const std::string& text() const;

 private:
  struct State;
  // Shared, not copied: muParser keeps pointers to the bound variables, so the parser and the
  // doubles it reads must keep their addresses, and copies of a std::function stay cheap.
  std::shared_ptr<State> state_;
};

/// A ScalarField evaluating `expression`; errors as ScalarExpression.
ScalarField make_scalar_field(const std::string& expression, const std::string& key);

/// A VectorField with one formula per component (2 or 3; missing components are 0). The key of
/// component i in error messages is "<key>[i]". Throws InputError on an empty or too long list.
VectorField make_vector_field(const std::vector<std::string>& expressions, const std::string& key);

}  // namespace signorini

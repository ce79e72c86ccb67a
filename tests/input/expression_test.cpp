// Formulas of the problem file: evaluation, constants, and errors reported when the file is read.

#include "signorini/input/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "expect_contains.hpp"
#include "signorini/core/error.hpp"

namespace signorini {
namespace {

std::string error_of(const std::string& expr, const std::string& key = "traction[0].p[1]") {
  try {
    ScalarExpression e(expr, key);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Expression, EvaluatesFormulasOfThePosition) {
  const ScalarExpression e("-2/3*(3 - x)", "p");
  EXPECT_DOUBLE_EQ(e(0.0, 0.0), -2.0);
  EXPECT_DOUBLE_EQ(e(1.5, 7.0), -1.0);
  EXPECT_DOUBLE_EQ(e(3.0, 1.0), 0.0);
  EXPECT_EQ(e.text(), "-2/3*(3 - x)");
}

TEST(Expression, UsesXYZAndPi) {
  const ScalarExpression e("x + 10*y + 100*z + pi", "g");
  EXPECT_DOUBLE_EQ(e(1.0, 2.0, 3.0), 321.0 + std::numbers::pi);
  EXPECT_DOUBLE_EQ(e(Point(1.0, 2.0, 0.0)), 21.0 + std::numbers::pi);
  EXPECT_DOUBLE_EQ(ScalarExpression("sin(pi/2) + max(x, 2)", "g")(1.0, 0.0), 3.0);
}

TEST(Expression, NumbersAreExpressions) {
  EXPECT_DOUBLE_EQ(ScalarExpression("0", "k")(5.0, 5.0), 0.0);
  EXPECT_DOUBLE_EQ(ScalarExpression("-9.81e-3", "k")(5.0, 5.0), -9.81e-3);
}

TEST(Expression, CopiesEvaluateIndependentlyOfOrder) {
  const ScalarField f = make_scalar_field("x*y", "gap");
  const ScalarField g = f;  // shares the parser: evaluation must not depend on earlier calls
  EXPECT_DOUBLE_EQ(f(Point(2.0, 3.0, 0.0)), 6.0);
  EXPECT_DOUBLE_EQ(g(Point(4.0, 5.0, 0.0)), 20.0);
  EXPECT_DOUBLE_EQ(f(Point(2.0, 3.0, 0.0)), 6.0);
}

TEST(Expression, VectorFieldHasOneFormulaPerComponent) {
  const VectorField p = make_vector_field({"0", "-2/3*(3 - x)"}, "traction[1].p");
  const Eigen::Vector3d v = p(Point(1.5, 1.0, 0.0));
  EXPECT_DOUBLE_EQ(v(0), 0.0);
  EXPECT_DOUBLE_EQ(v(1), -1.0);
  EXPECT_DOUBLE_EQ(v(2), 0.0);
  const Eigen::Vector3d w = make_vector_field({"x", "y", "z"}, "f")(Point(1.0, 2.0, 3.0));
  EXPECT_EQ(w, Eigen::Vector3d(1.0, 2.0, 3.0));
}

TEST(Expression, SyntaxErrorsNameTheKeyAndTheExpression) {
  const std::string m = error_of("2*(x + ");
  EXPECT_CONTAINS(m, "traction[0].p[1]: cannot parse expression '2*(x + ': ");
  EXPECT_EQ(m.find('\n'), std::string::npos);
}

TEST(Expression, UnknownVariablesAreErrorsAtConstruction) {
  EXPECT_CONTAINS(error_of("2*t", "contact.gap"), "contact.gap: cannot parse expression '2*t'");
  EXPECT_CONTAINS(error_of("foo(x)"), "cannot parse expression 'foo(x)'");
}

TEST(Expression, EmptyAndListExpressionsAreErrors) {
  EXPECT_CONTAINS(error_of(""), "cannot parse expression ''");
  EXPECT_CONTAINS(error_of("1, 2"), "expected a single value");
}

TEST(Expression, ErrorsAreOneLineWhateverTheFormulaHolds) {
  // Found by tests/fuzz: a formula from a TOML multi-line string holds line breaks.
  const std::string m = error_of("1 +\n2 +\t\x01");
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
  EXPECT_CONTAINS(m, "cannot parse expression '1 +\\n2 +\\t\\x01': ");
  const std::string long_formula(5000, '(');
  EXPECT_LT(error_of(long_formula).size(), 400U);
}

TEST(Expression, VectorFieldErrorsNameTheComponent) {
  try {
    make_vector_field({"0", "1 +"}, "traction[0].p");
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_CONTAINS(e.what(), "traction[0].p[1]: cannot parse expression '1 +'");
  }
  EXPECT_THROW(make_vector_field({}, "f"), InputError);
  EXPECT_THROW(make_vector_field({"1", "2", "3", "4"}, "f"), InputError);
}

TEST(Expression, NonFiniteValuesAreReturnedForTheAssemblyToReport) {
  // Not a parse error: 1/x is fine away from x = 0, and the assembly names the key if it is hit.
  const ScalarExpression e("1/x", "gap");
  EXPECT_TRUE(std::isinf(e(0.0, 0.0)));
  EXPECT_DOUBLE_EQ(e(2.0, 0.0), 0.5);
}

}  // namespace
}  // namespace signorini

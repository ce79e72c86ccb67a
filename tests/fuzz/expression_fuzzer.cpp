// libFuzzer target: the expression evaluator (ScalarExpression, muParser underneath) on arbitrary
// text. Besides crashes and sanitizer reports, it checks that every error is an InputError with a
// one-line message, and that an expression that parses evaluates anywhere (NaN and infinity are
// values, not errors, at this level). Built and run by tests/fuzz/run.sh.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "signorini/core/error.hpp"
#include "signorini/input/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const signorini::ScalarExpression e(text, "fuzz");
    const signorini::ScalarExpression copy = e;  // shares the parser
    for (const double x : {0.0, 1.0, -0.5, 1e300})
      for (const double y : {0.0, 2.0}) {
        (void)e(x, y);
        (void)copy(y, x, 1.0);
      }
    const signorini::VectorField f = signorini::make_vector_field({text, "x"}, "fuzz.p");
    (void)f(signorini::Point(0.25, 0.75, 0.0));
  } catch (const signorini::InputError& e) {
    if (std::strchr(e.what(), '\n') != nullptr) {
      std::fprintf(stderr, "expression_fuzzer: multi-line error message: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}

#pragma once
// EXPECT_CONTAINS(text, part): the message checks of the io and app tests, without gmock (the
// test executable links GoogleTest only); input_error_of(f), the message of an InputError.

#include <gtest/gtest.h>

#include <string>

#include "signorini/core/error.hpp"

#define EXPECT_CONTAINS(text, part)                          \
  EXPECT_NE(std::string(text).find(part), std::string::npos) \
      << "  text: " << std::string(text) << "\n  part: " << std::string(part)

namespace signorini::testing {

/// The message of the InputError that `f` throws ("no InputError" if it throws none).
template <class F>
std::string input_error_of(const F& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "no InputError";
}

}  // namespace signorini::testing

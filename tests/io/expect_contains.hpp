#pragma once
// EXPECT_CONTAINS(text, part): the message checks of the io and app tests, without gmock (the
// test executable links GoogleTest only).

#include <gtest/gtest.h>

#include <string>

#define EXPECT_CONTAINS(text, part)                          \
  EXPECT_NE(std::string(text).find(part), std::string::npos) \
      << "  text: " << std::string(text) << "\n  part: " << std::string(part)

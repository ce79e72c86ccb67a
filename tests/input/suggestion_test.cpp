#include "signorini/input/suggestion.hpp"

#include <gtest/gtest.h>

namespace signorini {
namespace {

TEST(Suggestion, EditDistance) {
  EXPECT_EQ(edit_distance("", ""), 0U);
  EXPECT_EQ(edit_distance("nx", "nx"), 0U);
  EXPECT_EQ(edit_distance("nx", "nxx"), 1U);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3U);
  EXPECT_EQ(edit_distance("", "abc"), 3U);
}

TEST(Suggestion, ClosestWithinTwoEdits) {
  const std::vector<std::string> keys{"r", "uzawa_tolerance", "gnm_tolerance", "method"};
  EXPECT_EQ(closest_match("methd", keys), "method");
  EXPECT_EQ(closest_match("gnm_tolerence", keys), "gnm_tolerance");
  EXPECT_EQ(closest_match("completely_different", keys), "");
  EXPECT_EQ(closest_match("x", keys), "");  // one edit from "r", but nothing alike
}

TEST(Suggestion, CaseAndShortWords) {
  EXPECT_EQ(closest_match("e", {"E", "nu"}), "E");
  EXPECT_EQ(closest_match("lu", {"cholmod", "cg"}), "");
  EXPECT_EQ(closest_match("ng", {"cholmod", "cg"}), "cg");
}

TEST(Suggestion, AbbreviationsOfOneKey) {
  const std::vector<std::string> keys{"uzawa_tolerance", "max_uzawa_iterations",
                                      "max_gnm_iterations"};
  EXPECT_EQ(closest_match("uzawa_tol", keys), "uzawa_tolerance");
  EXPECT_EQ(closest_match("max_", keys), "");  // ambiguous
  EXPECT_EQ(closest_match("uz", keys), "");    // too short to be sure
}

}  // namespace
}  // namespace signorini

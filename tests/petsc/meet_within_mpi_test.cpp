// DistributedEngine::meet_within (app/tool.cpp's failure path): ranks that all call it meet at
// once; a rank that calls it while the others are inside another collective call times out and
// learns that it is alone, and its open meeting is the one its next call joins.

#include <gtest/gtest.h>

#include <chrono>

#include "mpi_test_problems.hpp"
#include "signorini/contact/distributed_engine.hpp"

namespace signorini {
namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

TEST(MeetWithin, AllRanksMeetAtOnce) {
  const DistributedEngine& engine = testing::mpi_engine();
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(engine.meet_within(60.0));
  EXPECT_LT(seconds_since(start), 30.0);
  EXPECT_TRUE(engine.meet_within(60.0));  // a second meeting after the first
}

TEST(MeetWithin, ARankAloneTimesOutWhileTheOthersWaitInACollective) {
  const DistributedEngine& engine = testing::mpi_engine();
  if (engine.size() == 1) {
    EXPECT_TRUE(engine.meet_within(0.0));  // alone and all: it meets itself
    return;
  }
  // Rank 0 fails alone: the others wait in a reduction (any) that rank 0 joins only after its
  // meeting timed out, as a rank stuck in the solve would wait.
  bool alone = false;
  if (engine.rank() == 0) {
    const auto start = std::chrono::steady_clock::now();
    alone = !engine.meet_within(0.3);
    EXPECT_GE(seconds_since(start), 0.3);
  }
  EXPECT_TRUE(engine.any(alone));
  // The others join the meeting now: rank 0's next call completes the meeting it left open.
  EXPECT_TRUE(engine.meet_within(60.0));
  EXPECT_TRUE(engine.meet_within(60.0));  // and a fresh one after it
}

}  // namespace
}  // namespace signorini

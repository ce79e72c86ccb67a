// The outer loop every contact method shares (outer_iteration.cpp), driven by scripted steps:
// records, observer events, and the three ways it stops.

#include "signorini/contact/outer_iteration.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace signorini {
namespace {

// Steps that halve l each time, starting from 1, with a dual change of 1/k.
OuterLoop halving_loop(int max_steps) {
  OuterLoop loop;
  loop.max_steps = max_steps;
  loop.step = [](int k, const Vector& l) {
    OuterStepOutcome o;
    o.l = k == 1 ? Vector::Ones(l.size()) : Vector(0.5 * l);
    o.record.inner_iterations = k;
    o.record.dual_change = 1.0 / k;
    o.record.active_set_size = l.size();
    return o;
  };
  loop.limit_message = [](const OuterStepRecord& last) {
    return "limit, last change " + std::to_string(last.dual_change);
  };
  return loop;
}

TEST(OuterIteration, IterationLimitKeepsEveryRecordAndReportsEachStep) {
  ContactSolverOptions o;
  std::vector<IterationEvent> events;
  o.observer = [&](const IterationEvent& e) { events.push_back(e); };
  ContactResult out;
  run_outer_loop(halving_loop(4), Vector::Zero(3), o, out);
  EXPECT_EQ(out.summary.termination, Termination::IterationLimit);
  EXPECT_EQ(out.summary.steps.size(), 4U);
  EXPECT_EQ(out.summary.message, "limit, last change " + std::to_string(0.25));
  ASSERT_EQ(events.size(), 4U);
  EXPECT_EQ(events[2].kind, IterationEvent::Kind::Outer);
  EXPECT_EQ(events[2].outer, 3);
  EXPECT_EQ(events[2].inner, 3);
  EXPECT_DOUBLE_EQ(events[2].residual, 1.0 / 3.0);
  EXPECT_DOUBLE_EQ(out.l(0), 0.125);  // 1, 1/2, 1/4, 1/8
}

TEST(OuterIteration, ConvergedStepEndsTheLoopWithItsMultipliers) {
  OuterLoop loop = halving_loop(100);
  const auto inner = loop.step;
  loop.step = [inner](int k, const Vector& l) {
    OuterStepOutcome o = inner(k, l);
    if (k == 3) {
      o.stop = Termination::Converged;
      o.message = "done";
    }
    return o;
  };
  ContactResult out;
  run_outer_loop(loop, Vector::Zero(2), ContactSolverOptions{}, out);
  EXPECT_TRUE(out.summary.converged());
  EXPECT_EQ(out.summary.message, "done");
  EXPECT_EQ(out.summary.steps.size(), 3U);
  EXPECT_DOUBLE_EQ(out.l(1), 0.25);
}

// A step that fails with the inner method's own iteration limit stops the loop with that
// reason and message (not the outer limit's), and keeps l^(k-1).
TEST(OuterIteration, FailedStepKeepsThePreviousMultipliersAndItsMessage) {
  OuterLoop loop = halving_loop(100);
  const auto inner = loop.step;
  loop.step = [inner](int k, const Vector& l) {
    OuterStepOutcome o = inner(k, l);
    if (k == 2) {
      o.l.resize(0);
      o.stop = Termination::IterationLimit;
      o.message = "GNM did not converge";
    }
    return o;
  };
  int reported = 0;
  ContactSolverOptions o;
  o.observer = [&](const IterationEvent&) { ++reported; };
  ContactResult out;
  run_outer_loop(loop, Vector::Zero(2), o, out);
  EXPECT_EQ(out.summary.termination, Termination::IterationLimit);
  EXPECT_EQ(out.summary.message, "GNM did not converge");
  EXPECT_EQ(out.summary.steps.size(), 2U);
  EXPECT_EQ(reported, 1);
  EXPECT_DOUBLE_EQ(out.l(0), 1.0);
}

TEST(OuterIteration, ReportFilterChoosesTheStepsTheObserverSees) {
  OuterLoop loop = halving_loop(250);
  loop.report = [](int k) { return k <= 2 || k % 100 == 0; };
  std::vector<int> seen;
  ContactSolverOptions o;
  o.observer = [&](const IterationEvent& e) { seen.push_back(e.outer); };
  ContactResult out;
  run_outer_loop(loop, Vector::Zero(1), o, out);
  EXPECT_EQ(seen, (std::vector<int>{1, 2, 100, 200}));
}

}  // namespace
}  // namespace signorini

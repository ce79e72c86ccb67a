// The progress display of the tool as a unit: what it writes on a terminal (a status line redrawn
// in place, shown only once a run is older than the delay), in a plain log, in JSON and with
// --quiet.

#include "progress.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <memory>
#include <sstream>
#include <thread>

#include "expect_contains.hpp"

namespace signorini::app {
namespace {

// Progress writes to a FILE*; the tests read back what it wrote.
class Capture {
 public:
  Capture() : file_(std::tmpfile(), &std::fclose) {}
  [[nodiscard]] std::FILE* get() const { return file_.get(); }
  [[nodiscard]] std::string text() const {
    std::fflush(file_.get());
    std::rewind(file_.get());
    std::string out;
    char buffer[4096];
    std::size_t n = 0;
    while ((n = std::fread(buffer, 1, sizeof buffer, file_.get())) > 0) out.append(buffer, n);
    return out;
  }

 private:
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file_;
};

IterationEvent inner(int k, int m) {
  IterationEvent e;
  e.kind = IterationEvent::Kind::Inner;
  e.outer = k;
  e.inner = m;
  e.active = 12;
  e.residual = 1e-3;
  return e;
}

IterationEvent outer(int k) {
  IterationEvent e;
  e.kind = IterationEvent::Kind::Outer;
  e.outer = k;
  e.inner = 2;
  e.active = 12;
  e.residual = 4.5e-9;
  return e;
}

Progress::Options options_for(const Capture& c, LogFormat format, bool terminal) {
  Progress::Options o;
  o.format = format;
  o.terminal = terminal;
  o.out = c.get();
  return o;
}

std::size_t count(const std::string& text, const std::string& part) {
  std::size_t n = 0;
  for (auto pos = text.find(part); pos != std::string::npos; pos = text.find(part, pos + 1)) ++n;
  return n;
}

TEST(Progress, PlainLogHasEveryIterationAndNoControlCharacters) {
  const Capture c;
  {
    Progress p(ContactMethod::UzawaGnm, options_for(c, LogFormat::Text, false));
    p.phase("contact solve");
    p.iteration(inner(1, 1));
    IterationEvent with_cg = inner(1, 2);
    with_cg.linear_iterations = 7;  // an iterative path's Newton system
    p.iteration(with_cg);
    p.iteration(outer(1));
    p.report("done\n", {{"event", "x"}});
  }
  EXPECT_EQ(c.text(),
            "  uzawa 1  gnm 1  active 12  residual 1.0e-03  armijo 0\n"
            "  uzawa 1  gnm 2  active 12  residual 1.0e-03  armijo 0  cg 7\n"
            "uzawa 1: ||dl||/||l|| = 4.5e-09, active 12, gnm 2\n"
            "done\n");
}

TEST(Progress, TerminalShowsAStatusLineAfterTheDelay) {
  const Capture c;
  {
    Progress::Options o = options_for(c, LogFormat::Text, true);
    o.delay_seconds = 0.0;
    o.refresh_seconds = 0.01;
    Progress p(ContactMethod::UzawaGnm, o);
    p.phase("contact solve");
    std::this_thread::sleep_for(std::chrono::milliseconds(50));  // the ticker redraws
    p.iteration(inner(3, 2));
    p.iteration(outer(3));
    p.report("report\n", {});
  }
  const std::string t = c.text();
  // Redrawn in place, with the phase, the time and, before the first iteration, what it does.
  EXPECT_CONTAINS(t, "\r\033[Kcontact solve  0.");
  EXPECT_CONTAINS(t, " s  (setting up)");
  EXPECT_GE(count(t, "\r\033[K"), 3U);
  // GNM iterations only in the status line; the Uzawa step also as a line of its own.
  EXPECT_CONTAINS(t, "|  uzawa 3  gnm 2  active 12  gnm residual 1.0e-03");
  EXPECT_EQ(count(t, "uzawa 3: ||dl||/||l|| = 4.5e-09, active 12, gnm 2\n"), 1U);
  EXPECT_EQ(t.find("  uzawa 3  gnm 2  active 12  residual"), std::string::npos);
  // Permanent text starts on a cleared line, and the status line is gone at the end.
  EXPECT_CONTAINS(t, "\r\033[Kreport\n");
  EXPECT_EQ(t.substr(t.size() - 4), "\r\033[K");
}

TEST(Progress, TerminalShowsNoStatusLineInAShortRun) {
  const Capture c;
  {
    Progress::Options o = options_for(c, LogFormat::Text, true);
    o.delay_seconds = 60.0;
    o.refresh_seconds = 0.01;
    Progress p(ContactMethod::UzawaGnm, o);
    p.phase("contact solve");
    p.iteration(inner(1, 1));
    p.iteration(outer(1));
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  EXPECT_EQ(c.text(), "uzawa 1: ||dl||/||l|| = 4.5e-09, active 12, gnm 2\n");
}

TEST(Progress, TerminalLimitsTheRateOfUzawaLines) {
  const Capture c;
  {
    Progress::Options o = options_for(c, LogFormat::Text, true);
    o.delay_seconds = 60.0;
    Progress p(ContactMethod::ClassicalUzawa, o);
    p.phase("contact solve");
    for (int k = 1; k <= 5000; ++k) p.iteration(outer(k));
    p.finish_iterations();
  }
  const std::string t = c.text();
  // The first 20 steps, then (in well under a second) only the last one.
  EXPECT_EQ(count(t, "\n"), 21U) << t;
  EXPECT_CONTAINS(t, "uzawa 20: ");
  EXPECT_CONTAINS(t, "uzawa 5000: ");
  EXPECT_EQ(t.find("uzawa 21: "), std::string::npos);
}

TEST(Progress, JsonHasOneObjectPerLine) {
  const Capture c;
  {
    Progress p(ContactMethod::SemismoothNewton, options_for(c, LogFormat::Json, false));
    p.phase("contact solve");
    p.iteration(outer(1));
    p.report("ignored in JSON\n", {{"event", "summary"}, {"converged", true}});
  }
  std::istringstream in(c.text());
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);) lines.push_back(nlohmann::json::parse(line));
  ASSERT_EQ(lines.size(), 3U);
  EXPECT_EQ(lines[0]["event"], "phase");
  EXPECT_EQ(lines[0]["phase"], "contact solve");
  EXPECT_GE(lines[0]["elapsed"].get<double>(), 0.0);
  EXPECT_EQ(lines[1], nlohmann::json({{"event", "iteration"},
                                      {"level", "outer"},
                                      {"outer", 1},
                                      {"inner", 2},
                                      {"active", 12},
                                      {"residual", 4.5e-9},
                                      {"armijo", 0},
                                      {"linear_iterations", 0}}));
  EXPECT_EQ(lines[2], nlohmann::json({{"event", "summary"}, {"converged", true}}));
}

TEST(Progress, QuietWritesNothing) {
  const Capture c;
  {
    Progress::Options o = options_for(c, LogFormat::Text, true);
    o.quiet = true;
    o.delay_seconds = 0.0;
    Progress p(ContactMethod::UzawaGnm, o);
    p.phase("contact solve");
    p.iteration(outer(1));
    p.report("text\n", {});
    p.finish_iterations();
  }
  EXPECT_EQ(c.text(), "");
}

TEST(Progress, QuietSaysNowAndThenThatALongRunStillSolves) {
  const Capture c;
  const Capture notes;
  {
    Progress::Options o = options_for(c, LogFormat::Text, false);
    o.quiet = true;
    o.note_after_seconds = 0.05;
    o.notes = notes.get();
    Progress p(ContactMethod::ClassicalUzawa, o);
    p.phase("contact solve");
    p.iteration(outer(1));  // before the first note is due
    std::this_thread::sleep_for(std::chrono::milliseconds(60));
    p.iteration(outer(776));  // the first note
    p.iteration(outer(777));  // not yet again: the next is due at twice the elapsed time
  }
  EXPECT_EQ(c.text(), "");
  const std::string text = notes.text();
  EXPECT_EQ(count(text, "signorini: still solving: contact solve"), 1U) << text;
  EXPECT_CONTAINS(text, "uzawa 776");
  EXPECT_CONTAINS(text, "solver.time_limit");
}

}  // namespace
}  // namespace signorini::app

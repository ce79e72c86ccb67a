#include "progress.hpp"

#include <fmt/format.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>

#include "iteration_log.hpp"

namespace signorini::app {

namespace {

// On a terminal, Uzawa step lines are printed for the first steps and then at most one a second:
// classical_uzawa takes thousands of steps, which would scroll everything else away.
constexpr int kAlwaysShownOuterSteps = 20;
constexpr double kOuterLineInterval = 1.0;

// Columns of the terminal; a status line longer than that would wrap, and "\r" would then return
// to the start of its last row only.
std::size_t terminal_width(std::FILE* stream) {
  winsize ws{};
  if (::ioctl(::fileno(stream), TIOCGWINSZ, &ws) == 0 && ws.ws_col > 0) return ws.ws_col;
  return 80;
}

}  // namespace

Progress::Progress(ContactMethod method, const Options& options)
    : method_(method),
      options_(options),
      start_(std::chrono::steady_clock::now()),
      next_note_(options.note_after_seconds) {
  if (!options_.quiet && options_.format == LogFormat::Text && options_.terminal)
    ticker_ = std::thread([this] { tick(); });
}

Progress::~Progress() {
  {
    const std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (ticker_.joinable()) ticker_.join();
  const std::lock_guard lock(mutex_);
  clear_status_locked();
}

bool Progress::is_terminal(std::FILE* stream) {
  if (::isatty(::fileno(stream)) == 0) return false;
  const char* term = std::getenv("TERM");
  return term == nullptr || std::strcmp(term, "dumb") != 0;
}

double Progress::elapsed_seconds() const {
  const std::chrono::duration<double> dt = std::chrono::steady_clock::now() - start_;
  return dt.count();
}

void Progress::phase(const std::string& name) {
  const std::lock_guard lock(mutex_);
  phase_ = name;  // also when quiet: the "still solving" lines name it
  last_event_.reset();
  if (options_.quiet) return;
  suspended_ = false;
  if (options_.format == LogFormat::Json) {
    write_locked(
        nlohmann::json{{"event", "phase"}, {"phase", name}, {"elapsed", elapsed_seconds()}}.dump() +
        "\n");
  } else if (options_.terminal && elapsed_seconds() >= options_.delay_seconds) {
    draw_status_locked();
  }
}

void Progress::report(const std::string& text, const nlohmann::json& event) {
  if (options_.quiet) return;
  const std::lock_guard lock(mutex_);
  write_locked(options_.format == LogFormat::Json ? event.dump() + "\n" : text);
}

void Progress::iteration(const IterationEvent& e) {
  const std::lock_guard lock(mutex_);
  last_event_ = e;
  if (options_.quiet) {
    // A quiet run that goes on for minutes (classical_uzawa on a hard problem) says now and then
    // that it still works, and what stops it, so that a script's log does not look hung.
    const double now = elapsed_seconds();
    if (options_.note_after_seconds > 0.0 && now >= next_note_) {
      next_note_ = 2.0 * now;
      fmt::print(options_.notes, "signorini: still solving: {} (solver.time_limit stops a run)\n",
                 status_text_locked());
      std::fflush(options_.notes);
    }
    return;
  }
  if (options_.format == LogFormat::Json) {
    write_locked(iteration_json(e).dump() + "\n");
    return;
  }
  if (!options_.terminal) {
    write_locked(iteration_line(method_, e) + "\n");
    return;
  }
  // Terminal: GNM iterations live in the status line only; Uzawa steps get lines, rate-limited.
  if (e.kind == IterationEvent::Kind::Outer) {
    const double now = elapsed_seconds();
    if (e.outer <= kAlwaysShownOuterSteps || now - last_outer_line_ >= kOuterLineInterval) {
      last_outer_line_ = now;
      held_back_.reset();
      write_locked(iteration_line(method_, e) + "\n");
      return;
    }
    held_back_ = e;
  }
  if (elapsed_seconds() >= options_.delay_seconds) draw_status_locked();
}

void Progress::finish_iterations() {
  if (options_.quiet) return;
  const std::lock_guard lock(mutex_);
  if (held_back_) write_locked(iteration_line(method_, *held_back_) + "\n");
  held_back_.reset();
}

void Progress::suspend() {
  const std::lock_guard lock(mutex_);
  clear_status_locked();
  suspended_ = true;
}

void Progress::write_locked(const std::string& text) {
  const bool redraw = status_shown_;
  clear_status_locked();
  std::fputs(text.c_str(), options_.out);
  if (redraw) draw_status_locked();
  // Progress is for watching a long run as it goes: never leave it in a buffer.
  std::fflush(options_.out);
}

std::string Progress::status_text_locked() const {
  std::string s = fmt::format("{}  {:.1f} s", phase_, elapsed_seconds());
  // Before its first iteration a solver condenses or factorises, which takes a while on a large
  // mesh and reports nothing.
  if (!last_event_) return phase_ == "contact solve" ? s + "  (setting up)" : s;
  const IterationEvent& e = *last_event_;
  const char* outer = method_ == ContactMethod::SemismoothNewton ? "newton" : "uzawa";
  if (e.kind == IterationEvent::Kind::Inner)
    return s + fmt::format("  |  {} {}  gnm {}  active {}  gnm residual {:.1e}", outer, e.outer,
                           e.inner, e.active, e.residual);
  return s + fmt::format("  |  {} {}  active {}  ||dl||/||l|| {:.1e}", outer, e.outer, e.active,
                         e.residual);
}

void Progress::draw_status_locked() {
  if (suspended_ || stop_ || phase_.empty()) return;
  std::string line = status_text_locked();
  const std::size_t width = terminal_width(options_.out);
  if (line.size() >= width) line.resize(width - 1);
  std::fputs(("\r\033[K" + line).c_str(), options_.out);
  std::fflush(options_.out);
  status_shown_ = true;
}

void Progress::clear_status_locked() {
  if (!status_shown_) return;
  std::fputs("\r\033[K", options_.out);
  std::fflush(options_.out);
  status_shown_ = false;
}

void Progress::tick() {
  std::unique_lock lock(mutex_);
  const auto period = std::chrono::duration<double>(options_.refresh_seconds);
  while (!stop_) {
    wake_.wait_for(lock, period);
    if (!stop_ && elapsed_seconds() >= options_.delay_seconds) draw_status_locked();
  }
}

}  // namespace signorini::app

#pragma once
// What a run prints while it works (docs/output.md, "Progress"), in one of four forms:
//   quiet      nothing (errors and warnings still go to stderr, from elsewhere), but for a run
//              that goes on and on: a "still solving" line on `notes` once a minute has passed,
//              then after each doubling of the time (note_after_seconds);
//   terminal   text, and once the run is older than a second a status line at the bottom,
//              redrawn in place, with the phase, the elapsed time and the current iteration;
//              GNM iterations appear only there, Uzawa steps also as lines of their own;
//   plain      text for a file or a pipe: every line is final, one per GNM iteration and per
//              Uzawa step, no control characters;
//   json       one JSON object per line, each with an "event" key.
// The solver reports from its thread through iteration(); a ticker thread redraws the status line
// while a long phase (an assembly, a factorisation) reports nothing.

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>

#include "signorini/contact/contact_solver_options.hpp"
#include "signorini/core/enum_names.hpp"

namespace signorini::app {

enum class LogFormat { Text, Json };

inline constexpr EnumNames<LogFormat, 2> kLogFormatNames{{
    {LogFormat::Text, "text"},
    {LogFormat::Json, "json"},
}};

class Progress {
 public:
  struct Options {
    bool quiet = false;
    LogFormat format = LogFormat::Text;
    bool terminal = false;         ///< text with a status line (see is_terminal())
    double delay_seconds = 1.0;    ///< no status line for runs shorter than this
    double refresh_seconds = 0.2;  ///< how often the status line is redrawn
    std::FILE* out = stdout;
    /// Quiet: the first "still solving" line after this long (0: none), the next ones each time
    /// the elapsed time has doubled; on `notes`.
    double note_after_seconds = 0.0;
    std::FILE* notes = stderr;
  };

  Progress(ContactMethod method, const Options& options);
  ~Progress();
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  /// A terminal that understands "\r" and "\033[K" (isatty, and TERM is not "dumb").
  static bool is_terminal(std::FILE* stream);

  /// A new phase ("building model", "contact solve", ...): shown in the status line, and as a
  /// {"event": "phase", "phase": ..., "elapsed": seconds} object in JSON.
  void phase(const std::string& name);
  /// Prints `text` (text formats) or `event` (json) as it is; text should end with a newline.
  void report(const std::string& text, const nlohmann::json& event);
  /// An event of the contact solver (its observer calls this).
  void iteration(const IterationEvent& event);
  /// After the solve: prints an Uzawa step line held back by the terminal's rate limit.
  void finish_iterations();
  /// Clears the status line and stops redrawing it until the next phase(), so that another
  /// program can write to the terminal.
  void suspend();

  [[nodiscard]] double elapsed_seconds() const;

 private:
  void write_locked(const std::string& text);  // clears the status line, writes, redraws it
  void draw_status_locked();
  void clear_status_locked();
  [[nodiscard]] std::string status_text_locked() const;
  void tick();

  ContactMethod method_;
  Options options_;
  std::chrono::steady_clock::time_point start_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  bool suspended_ = false;
  bool status_shown_ = false;
  std::string phase_;
  std::optional<IterationEvent> last_event_;  // the latest, for the status line
  std::optional<IterationEvent> held_back_;   // an Uzawa line not printed yet (terminal)
  double last_outer_line_ = -1e300;           // elapsed seconds at the last one printed
  double next_note_ = 0.0;                    // quiet: when the next "still solving" line is due
  std::thread ticker_;
};

}  // namespace signorini::app

#include "timing_report.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "signorini/output/summary_json.hpp"

namespace signorini::app {

std::string timing_report(const Model& model, const SolveSummary& summary) {
  const double total = run_total_seconds(model, summary);
  // Wide enough for the longest phase name (indented by 2), so that the columns line up.
  std::size_t width = 20;
  const TimingTable all = run_timings(model, summary);  // named: phases() refers into it
  for (const auto& [phase, seconds] : all.phases()) width = std::max(width, phase.size() + 2);
  const auto row = [&](const std::string& phase, double seconds) {
    const double percent = total > 0.0 ? 100.0 * seconds / total : 0.0;
    return fmt::format("  {:<{}} {:>10.4f} {:>6.1f}\n", phase, width, seconds, percent);
  };
  std::string s = fmt::format("  {:<{}} {:>10} {:>6}\n", "phase", width, "seconds", "%");
  for (const auto& [phase, seconds] : model.timings.phases()) s += row(phase, seconds);
  // "contact solve" first, then what happened inside it.
  const auto& phases = summary.timings.phases();
  for (const auto& [phase, seconds] : phases)
    if (phase == "contact solve") s += row(phase, seconds);
  for (const auto& [phase, seconds] : phases)
    if (phase != "contact solve") s += row("  " + phase, seconds);
  s += row("total", total);
  return s;
}

std::string seconds_text(double s) {
  return s >= 100.0 ? fmt::format("{:.1f}", s) : fmt::format("{:.3f}", s);
}

}  // namespace signorini::app

#include "signorini/input/suggestion.hpp"

#include <algorithm>
#include <numeric>

namespace signorini {

std::size_t edit_distance(std::string_view a, std::string_view b) {
  // One row of the dynamic-programming table at a time: keys are short, but this stays cheap for
  // long strings too.
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      row[j] = std::min({above + 1, row[j - 1] + 1, substitution});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest_match(std::string_view word, const std::vector<std::string>& candidates,
                          std::size_t max_distance) {
  const auto lower = [](std::string_view t) {
    std::string out(t);
    for (char& c : out)
      if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
  };
  for (const std::string& c : candidates)
    if (lower(c) == lower(word)) return c;  // "e" for "E"

  std::string best;
  std::size_t best_distance = max_distance + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(word, c);
    // Two edits turn any two-letter word into any other ("lu" into "cg"): a suggestion must keep
    // at least half of the candidate.
    if (d < best_distance && 2 * d <= c.size()) {
      best = c;
      best_distance = d;
    }
  }
  if (!best.empty() || word.size() < 3) return best;
  // Truncated names are a common slip that edit distance misses.
  for (const std::string& c : candidates) {
    if (c.starts_with(word)) {
      if (!best.empty()) return {};  // ambiguous: suggest nothing rather than a guess
      best = c;
    }
  }
  return best;
}

}  // namespace signorini

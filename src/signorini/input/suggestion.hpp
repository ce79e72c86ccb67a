#pragma once
// "Did you mean ...?" for misspelt keys and names in problem files and on the command line.

#include <string>
#include <string_view>
#include <vector>

namespace signorini {

/// Levenshtein distance (insertions, deletions, substitutions), case-sensitive.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// The candidate that equals `word` but for case; else the closest one within `max_distance`
/// edits that keeps at least half of the candidate (ties: the first one); else the only candidate
/// that `word` (3 characters or more) abbreviates, as "uzawa_tol" for "uzawa_tolerance"; else an
/// empty string.
std::string closest_match(std::string_view word, const std::vector<std::string>& candidates,
                          std::size_t max_distance = 2);

}  // namespace signorini

// libFuzzer target: the problem-file reader (parse_problem_string) on arbitrary bytes.
//
// The input is a problem file; lines after a line "#--set" are --set overrides, so that the
// override parser is fuzzed as well. Besides crashes and sanitizer reports, it checks what the
// reader promises:
//   - every error is an InputError with a one-line message;
//   - the effective settings of a file that reads read back, to the same settings;
//   - the fields it builds (loads, gap) evaluate without crashing.
// Built and run by tests/fuzz/run.sh, not by the normal build.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/input/problem_file.hpp"

namespace {

[[noreturn]] void broken(const char* what, const std::string& detail) {
  std::fprintf(stderr, "problem_file_fuzzer: %s: %s\n", what, detail.c_str());
  std::abort();
}

void evaluate_fields(const signorini::ProblemSpec& spec) {
  for (const double x : {0.0, 0.5, 1.0, -2.0})
    for (const double y : {0.0, 1.0}) {
      const signorini::Point p(x, y, 0.0);
      try {
        for (const auto& t : spec.tractions) (void)t.p(p);
        if (spec.body_force) (void)spec.body_force(p);
        (void)spec.contacts[0].gap(p);
      } catch (const signorini::InputError& e) {
        // A value that is not finite somewhere: reported, with a one-line message.
        if (std::strchr(e.what(), '\n') != nullptr) broken("multi-line field error", e.what());
      }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  std::string text = input;
  std::vector<std::string> overrides;
  const std::string marker = "\n#--set\n";
  if (const auto at = input.find(marker); at != std::string::npos) {
    text = input.substr(0, at + 1);
    std::size_t start = at + marker.size();
    while (start < input.size()) {
      const auto end = input.find('\n', start);
      overrides.push_back(input.substr(start, end == std::string::npos ? end : end - start));
      if (end == std::string::npos) break;
      start = end + 1;
    }
  }

  signorini::LoadedProblem loaded;
  try {
    loaded = signorini::parse_problem_string(text, "fuzz.toml", overrides);
  } catch (const signorini::InputError& e) {
    if (std::strchr(e.what(), '\n') != nullptr) broken("multi-line error message", e.what());
    return 0;
  }
  // Read back without the overrides: the effective settings include them.
  signorini::LoadedProblem again;
  try {
    again = signorini::parse_problem_string(loaded.effective_toml, "fuzz.toml");
  } catch (const signorini::InputError& e) {
    broken("the effective settings do not read back",
           std::string(e.what()) + "\n--- settings:\n" + loaded.effective_toml);
  }
  if (again.effective_toml != loaded.effective_toml)
    broken("the effective settings change when read back",
           loaded.effective_toml + "\n--- became:\n" + again.effective_toml);
  evaluate_fields(loaded.spec);
  return 0;
}

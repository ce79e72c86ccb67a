#pragma once
// A valid value of an option other than its default, chosen from its declaration (kind, range,
// choices), so that tests can set every option without naming each one.

#include <optional>
#include <string>

#include "signorini/core/option_table.hpp"

namespace signorini::testing {

/// Empty for options that have no other value (mesh.type) or that other options depend on
/// (solver.method and solver.device: the backend path runs only some combinations), and for the
/// options that their sections' own readers read.
inline std::optional<OptionValue> other_value(const OptionInfo& o, const std::string& key) {
  if (!o.default_value || key == "solver.method" || key == "solver.device") return std::nullopt;
  const OptionValue& d = *o.default_value;
  switch (o.kind) {
    case OptionKind::Number: {
      const double x = std::get<double>(d);
      for (const double candidate : {x + 1.0, x / 2.0, x - 1.0, 0.25})
        if (candidate != x && o.range.contains(candidate)) return candidate;
      return std::nullopt;
    }
    case OptionKind::Integer: {
      const std::int64_t i = std::get<std::int64_t>(d);
      for (const std::int64_t candidate : {i + 1, i - 1})
        if (in_range(o, OptionValue(candidate))) return candidate;
      return std::nullopt;
    }
    case OptionKind::NumberOrAuto:
      return std::holds_alternative<double>(d) ? OptionValue(std::monostate{})
                                               : OptionValue(1234.5);
    case OptionKind::Boolean:
      return !std::get<bool>(d);
    case OptionKind::Choice:
      for (const std::string& c : o.choices)
        if (c != std::get<std::string>(d)) return c;
      return std::nullopt;
    case OptionKind::Text:
      return std::get<std::string>(d) + "_other";
    case OptionKind::Coordinates: {
      std::vector<double> v = std::get<std::vector<double>>(d);
      for (std::size_t k = 0; k < v.size(); ++k) v[k] += k % 2 == 0 ? 1.0 : -0.5;
      return v;
    }
    case OptionKind::Custom:
      break;
  }
  return std::nullopt;
}

}  // namespace signorini::testing

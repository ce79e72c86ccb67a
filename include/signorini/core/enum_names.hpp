#pragma once
// One table of names per enumeration, shared by the C++ API, the problem file and the JSON output
// (as Ceres does with StringToLinearSolverType): a name is spelled the same everywhere.

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace signorini {

template <class Enum, std::size_t N>
using EnumNames = std::array<std::pair<Enum, std::string_view>, N>;

template <class Enum, std::size_t N>
constexpr std::string_view enum_to_string(const EnumNames<Enum, N>& names, Enum value) {
  for (const auto& [e, s] : names)
    if (e == value) return s;
  return "unknown";
}

template <class Enum, std::size_t N>
constexpr std::optional<Enum> enum_from_string(const EnumNames<Enum, N>& names,
                                               std::string_view text) {
  for (const auto& [e, s] : names)
    if (s == text) return e;
  return std::nullopt;
}

/// "a", "b" or "c": the allowed names, for error messages.
template <class Enum, std::size_t N>
std::string enum_choices(const EnumNames<Enum, N>& names) {
  std::string out;
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0) out += (i + 1 == N) ? " or " : ", ";
    out += '"';
    out += names[i].second;
    out += '"';
  }
  return out;
}

}  // namespace signorini

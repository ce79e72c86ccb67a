#pragma once
// Writes TOML text in the order the caller chooses (toml++ prints tables sorted by key), so that
// the effective settings of a run read like the problem file: [mesh] before [material], and so on.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "signorini/core/option_table.hpp"

namespace signorini {

class TomlEmitter {
 public:
  /// Starts "[name]"; keys that follow belong to it.
  void table(std::string_view name);
  /// Starts one "[[name]]" entry of an array of tables.
  void array_table(std::string_view name);

  void value(std::string_view key, std::string_view text);
  void value(std::string_view key, const char* text) { value(key, std::string_view(text)); }
  // Without it a std::string would convert as well to a string_view as to an OptionValue.
  void value(std::string_view key, const std::string& text) { value(key, std::string_view(text)); }
  void value(std::string_view key, double number);
  void value(std::string_view key, std::int64_t number);
  void value(std::string_view key, int number) { value(key, std::int64_t{number}); }
  void value(std::string_view key, bool flag);
  void value(std::string_view key, const std::vector<std::string>& texts);
  void value(std::string_view key, const std::vector<double>& numbers);
  /// An option's value as toml_value() spells it.
  void value(std::string_view key, const OptionValue& option);

  /// A comment line ("# text") with a blank line before it, as a table's header has.
  void comment(std::string_view text);
  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  void header(std::string_view line);
  std::string text_;
};

/// A TOML basic string: quoted, with quotes, backslashes and control characters escaped.
std::string toml_quote(std::string_view text);
/// A TOML float that reads back to the same double: shortest form, always with '.' or an
/// exponent ("1.0", "1e-10"), and inf/nan spelt the TOML way.
std::string toml_float(double number);
/// An option's value as TOML that reads back to it: "auto" (a NumberOrAuto without a number) is
/// the string "auto", a point or vector an array of floats.
std::string toml_value_text(const OptionValue& value);

}  // namespace signorini

#include "signorini/input/toml_emitter.hpp"

#include <fmt/format.h>

#include <cmath>

namespace signorini {

std::string toml_quote(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
          out += fmt::format("\\u{:04X}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        else
          out += c;
    }
  }
  return out + "\"";
}

std::string toml_float(double number) {
  if (std::isnan(number)) return "nan";
  if (std::isinf(number)) return number > 0 ? "inf" : "-inf";
  std::string s = fmt::format("{}", number);  // shortest round-trip representation
  // TOML reads "100" as an integer: keep the value a float.
  if (s.find_first_of(".eE") == std::string::npos) s += ".0";
  return s;
}

std::string toml_value_text(const OptionValue& value) {
  if (const auto* x = std::get_if<double>(&value)) return toml_float(*x);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* s = std::get_if<std::string>(&value)) return toml_quote(*s);
  if (const auto* v = std::get_if<std::vector<double>>(&value)) {
    std::string items;
    for (const double x : *v) items += (items.empty() ? "" : ", ") + toml_float(x);
    return "[" + items + "]";
  }
  return toml_quote("auto");
}

void TomlEmitter::header(std::string_view line) {
  if (!text_.empty()) text_ += '\n';
  text_ += line;
  text_ += '\n';
}

void TomlEmitter::comment(std::string_view text) {
  header(fmt::format("# {}", text));
}

void TomlEmitter::table(std::string_view name) {
  header(fmt::format("[{}]", name));
}

void TomlEmitter::array_table(std::string_view name) {
  header(fmt::format("[[{}]]", name));
}

void TomlEmitter::value(std::string_view key, std::string_view text) {
  text_ += fmt::format("{} = {}\n", key, toml_quote(text));
}

void TomlEmitter::value(std::string_view key, const OptionValue& option) {
  text_ += fmt::format("{} = {}\n", key, toml_value_text(option));
}

void TomlEmitter::value(std::string_view key, double number) {
  text_ += fmt::format("{} = {}\n", key, toml_float(number));
}

void TomlEmitter::value(std::string_view key, std::int64_t number) {
  text_ += fmt::format("{} = {}\n", key, number);
}

void TomlEmitter::value(std::string_view key, bool flag) {
  text_ += fmt::format("{} = {}\n", key, flag ? "true" : "false");
}

void TomlEmitter::value(std::string_view key, const std::vector<std::string>& texts) {
  std::string items;
  for (const std::string& t : texts) items += (items.empty() ? "" : ", ") + toml_quote(t);
  text_ += fmt::format("{} = [{}]\n", key, items);
}

void TomlEmitter::value(std::string_view key, const std::vector<double>& numbers) {
  std::string items;
  for (const double x : numbers) items += (items.empty() ? "" : ", ") + toml_float(x);
  text_ += fmt::format("{} = [{}]\n", key, items);
}

}  // namespace signorini

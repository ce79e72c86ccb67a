#include "signorini/input/syntax_explanations.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <map>
#include <vector>

#include "signorini/input/toml_reader.hpp"

namespace signorini {

namespace {

// The dotted name of the table that line `number` (1-based) of `lines` is in ("traction[1]",
// "solver.linear", ""), from the headers above it.
std::string table_at(const std::vector<std::string>& lines, std::size_t number) {
  std::string table;
  std::map<std::string, int> entries;
  for (std::size_t n = 1; n < number && n <= lines.size(); ++n) {
    const std::string line = trim(lines[n - 1]);
    if (line.rfind("[[", 0) == 0 && line.find("]]") != std::string::npos) {
      const std::string name = trim(line.substr(2, line.find("]]") - 2));
      table = name + "[" + std::to_string(entries[name]++) + "]";
    } else if (line.rfind('[', 0) == 0 && line.find(']') != std::string::npos) {
      table = trim(line.substr(1, line.find(']') - 1));
    }
  }
  return table;
}

// The value part of "key = value # comment", without the comment (outside quotes).
std::string value_text(const std::string& after_equals) {
  bool quoted = false;
  for (std::size_t i = 0; i < after_equals.size(); ++i) {
    if (after_equals[i] == '"') quoted = !quoted;
    if (after_equals[i] == '#' && !quoted) return trim(after_equals.substr(0, i));
  }
  return trim(after_equals);
}

bool is_number(const std::string& s) {
  if (s.empty()) return false;
  char* end = nullptr;
  (void)std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}

// The entries of "[a, b(c, d), e]" split at the commas outside parentheses.
std::vector<std::string> array_entries(const std::string& array) {
  std::vector<std::string> out;
  std::string current;
  int depth = 0;
  for (std::size_t i = 1; i + 1 < array.size(); ++i) {
    const char c = array[i];
    if (c == '(') ++depth;
    if (c == ')') --depth;
    if (c == ',' && depth == 0) {
      out.push_back(trim(current));
      current.clear();
    } else {
      current += c;
    }
  }
  out.push_back(trim(current));
  return out;
}

}  // namespace

std::string explain_syntax_error(const std::string& text, std::size_t number) {
  const std::vector<std::string> lines = split(text, '\n');
  if (number < 1 || number > lines.size()) return {};
  const std::string line = lines[number - 1];
  const auto eq = line.find('=');
  if (eq == std::string::npos) return {};
  const std::string key = trim(line.substr(0, eq));
  const std::string value = value_text(line.substr(eq + 1));
  if (key.empty() || value.empty() || value[0] == '"' || value[0] == '\'') return {};
  // Only plain ASCII text is guessed at; anything else keeps the parser's own message.
  for (const char c : line)
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7e)
      if (c != '\t' && c != '\r') return {};
  const std::string table = table_at(lines, number);
  const std::string full = table.empty() ? key : table + "." + key;
  // A number and a word after it: a unit.
  const auto space = value.find_first_of(" \t");
  if (space != std::string::npos && is_number(value.substr(0, space))) {
    const std::string number_part = value.substr(0, space);
    return fmt::format(
        "key '{}' = {}: a number cannot carry a unit; write {} = {} (the numbers of a problem "
        "are in one consistent set of units, which the top-level key units = \"m-MPa\" (or "
        "\"mm-N\", \"m-Pa\", ...) names for the labels)",
        full, value, key, number_part);
  }
  if (value[0] == '[' && value.back() == ']') {
    std::string quoted;
    bool any = false;
    for (const std::string& e : array_entries(value)) {
      const bool plain = e.empty() || e[0] == '"' || is_number(e);
      any = any || !plain;
      quoted += (quoted.empty() ? "" : ", ") + (plain ? e : "\"" + e + "\"");
    }
    if (any)
      return fmt::format("key '{}' = {}: formulas in an array must be quoted strings, as {} = [{}]",
                         full, value, key, quoted);
    return {};
  }
  // A formula: the characters of one, and a letter or an operator among them.
  const bool formula_characters =
      value.find_first_not_of(
          "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_ "
          ".+-*/^()<>?:!&|,") == std::string::npos &&
      value.find_first_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ*/^(") !=
          std::string::npos;
  if (formula_characters && !is_number(value) && value != "true" && value != "false")
    return fmt::format("key '{}' = {}: a formula or a name must be a quoted string, as {} = \"{}\"",
                       full, value, key, value);
  return {};
}

}  // namespace signorini

#include "signorini/input/option_docs.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/input/problem_schema.hpp"
#include "signorini/input/toml_emitter.hpp"

namespace signorini {

namespace {

constexpr std::string_view kBegin = "<!-- BEGIN GENERATED: option table ";
constexpr std::string_view kEnd = "<!-- END GENERATED: option table ";

// A number as a person writes it in a table, the shorter of the plain and the exponent form that
// read back to it: "1e-4", "0.5", "10", "200000".
std::string doc_number(double x) {
  const std::string plain = fmt::format("{}", x);
  std::string exponent_form;
  for (int digits = 0; digits <= 17; ++digits) {
    exponent_form = fmt::format("{:.{}e}", x, digits);
    if (std::strtod(exponent_form.c_str(), nullptr) == x) break;
  }
  // "1e-04" -> "1e-4", "2e+05" -> "2e5".
  const auto e = exponent_form.find('e');
  std::string exponent = exponent_form.substr(e + 1);
  const bool negative = exponent[0] == '-';
  exponent.erase(0, 1);
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  exponent_form = exponent_form.substr(0, e) + "e" + (negative ? "-" : "") + exponent;
  return exponent_form.size() < plain.size() ? exponent_form : plain;
}

std::string default_words(const OptionInfo& o) {
  if (o.required) return "required";
  if (!o.default_text.empty()) return o.default_text;
  if (!o.default_value) return "";
  if (const auto* x = std::get_if<double>(&*o.default_value))
    return fmt::format("`{}`", doc_number(*x));
  return fmt::format("`{}`", toml_value_text(*o.default_value));
}

// A table cell: '|' would end it.
std::string cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') out += '\\';
    out += c;
  }
  return out;
}

std::string marker(std::string_view start, const OptionTableInfo& table) {
  return std::string(start) + section_title(table) + " -->";
}

}  // namespace

std::string section_title(const OptionTableInfo& table) {
  if (table.path.empty()) return "top level";
  return table.array_of_tables ? "[[" + table.path + "]]" : "[" + table.path + "]";
}

std::string option_table_markdown(const OptionTableInfo& table) {
  const bool units = std::any_of(table.options.begin(), table.options.end(),
                                 [](const OptionInfo& o) { return !o.unit.empty(); });
  std::string out = units ? "| key | type | unit | default | meaning |\n|---|---|---|---|---|\n"
                          : "| key | type | default | meaning |\n|---|---|---|---|\n";
  for (const OptionInfo& o : table.options) {
    std::vector<std::string> cells = {fmt::format("`{}`", o.key), type_words(o, true)};
    if (units) cells.push_back(o.unit);
    cells.push_back(default_words(o));
    cells.push_back(o.doc);
    out += "|";
    // An empty cell as "| |", as a person writes it.
    for (const std::string& c : cells)
      out += c.empty() ? std::string(" |") : fmt::format(" {} |", cell(c));
    out += "\n";
  }
  return out;
}

std::string with_generated_option_tables(const std::string& markdown) {
  std::string out = markdown;
  for (const OptionTableInfo* table : problem_schema()) {
    const std::string begin = marker(kBegin, *table);
    const std::string end = marker(kEnd, *table);
    const auto b = out.find(begin);
    const auto e = b == std::string::npos ? std::string::npos : out.find(end, b);
    if (e == std::string::npos)
      throw InputError("the option table " + section_title(*table) + " has no markers '" + begin +
                       "' ... '" + end + "'");
    const auto from = b + begin.size() + 1;  // after the marker's line
    out.replace(from, e - from, option_table_markdown(*table));
  }
  // A marker of a table that is gone would keep its stale rows. (Markers start a line; the prose
  // may quote one.)
  for (auto at = out.find(kBegin); at != std::string::npos; at = out.find(kBegin, at + 1)) {
    if (at > 0 && out[at - 1] != '\n') continue;
    const auto line_end = out.find('\n', at);
    const std::string line = out.substr(at, line_end - at);
    const auto& schema = problem_schema();
    if (std::none_of(schema.begin(), schema.end(),
                     [&](const OptionTableInfo* t) { return marker(kBegin, *t) == line; }))
      throw InputError("'" + line + "' names no option table");
  }
  return out;
}

}  // namespace signorini

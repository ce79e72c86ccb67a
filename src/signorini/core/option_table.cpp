#include "signorini/core/option_table.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>

namespace signorini {

namespace {

std::string number_text(double x) {
  return fmt::format("{:g}", x);
}

// "> 0", "in (0, 1)", ">= 1", "in [1, 50]": the bounds of a range, after the kind's noun.
std::string bounds_words(const OptionRange& r) {
  if (r.lower && r.upper)
    return fmt::format("in {}{}, {}{}", r.lower_open ? '(' : '[', number_text(*r.lower),
                       number_text(*r.upper), r.upper_open ? ')' : ']');
  if (r.lower) return fmt::format("{} {}", r.lower_open ? ">" : ">=", number_text(*r.lower));
  if (r.upper) return fmt::format("{} {}", r.upper_open ? "<" : "<=", number_text(*r.upper));
  return {};
}

// "\"a\", \"b\" or \"c\"", with each name in backticks for Markdown.
std::string choices_words(const std::vector<std::string>& choices, bool markdown) {
  std::string out;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) out += (i + 1 == choices.size()) ? " or " : ", ";
    out += markdown ? "`\"" + choices[i] + "\"`" : "\"" + choices[i] + "\"";
  }
  return out;
}

bool is_positive(const OptionRange& r) {
  return r.lower && *r.lower == 0.0 && r.lower_open && !r.upper;
}

// "a positive number", "a number in (0, 1)", "an integer >= 1".
std::string range_words(const OptionInfo& o, const char* noun, const char* article) {
  std::string out;
  if (is_positive(o.range))
    out = fmt::format("a positive {}", noun);
  else if (const std::string bounds = bounds_words(o.range); !bounds.empty())
    out = fmt::format("{} {} {}", article, noun, bounds);
  else
    out = fmt::format("a finite {}", noun);
  if (!o.range_note.empty()) out += " " + o.range_note;
  return out;
}

}  // namespace

bool OptionRange::contains(double x) const {
  if (!std::isfinite(x)) return false;
  if (lower && (lower_open ? !(x > *lower) : !(x >= *lower))) return false;
  if (upper && (upper_open ? !(x < *upper) : !(x <= *upper))) return false;
  return true;
}

std::string expected_words(const OptionInfo& o) {
  switch (o.kind) {
    case OptionKind::Number:
      return range_words(o, "number", "a");
    case OptionKind::Integer:
      return range_words(o, "integer", "an");
    case OptionKind::NumberOrAuto:
      return range_words(o, "number", "a") + " or \"auto\"";
    case OptionKind::Boolean:
      return "true or false";
    case OptionKind::Choice:
      return choices_words(o.choices, false);
    case OptionKind::Text:
      return "a string";
    case OptionKind::Coordinates:
      return "an " + o.type_text;
    case OptionKind::Custom:
      break;
  }
  return o.type_text;
}

std::string type_words(const OptionInfo& o, bool markdown) {
  const auto with_bounds = [&](const char* noun) {
    const std::string bounds = bounds_words(o.range);
    return bounds.empty() ? std::string(noun) : std::string(noun) + " " + bounds;
  };
  switch (o.kind) {
    case OptionKind::Number:
      return with_bounds("number");
    case OptionKind::Integer:
      return with_bounds("integer");
    case OptionKind::NumberOrAuto:
      return with_bounds("number") + (markdown ? " or `\"auto\"`" : " or \"auto\"");
    case OptionKind::Boolean:
      return "boolean";
    case OptionKind::Choice:
      return choices_words(o.choices, markdown);
    case OptionKind::Text:
      return "string";
    case OptionKind::Coordinates:
      return o.type_text;
    case OptionKind::Custom:
      break;
  }
  return o.type_text;
}

bool integer_fits(const OptionInfo& o, std::int64_t value) {
  if (o.integer_bits >= 64) return true;
  const std::int64_t limit = std::int64_t{1} << (o.integer_bits - 1);
  return value >= -limit && value < limit;
}

bool in_range(const OptionInfo& o, const OptionValue& value) {
  if (const auto* x = std::get_if<double>(&value)) return o.range.contains(*x);
  if (const auto* i = std::get_if<std::int64_t>(&value))
    return integer_fits(o, *i) && o.range.contains(static_cast<double>(*i));
  if (const auto* v = std::get_if<std::vector<double>>(&value))
    return std::all_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); });
  return true;  // "auto", flags, names and text: the reader checks names against the choices
}

bool is_synonym(const OptionInfo& o, std::string_view key) {
  std::string k;
  for (const char c : key) k += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string& s : o.synonyms) {
    if (!s.empty() && s[0] == '*') {
      if (k.find(s.substr(1)) != std::string::npos) return true;
    } else if (k == s) {
      return true;
    }
  }
  return false;
}

std::string plain_value_text(const OptionValue& value) {
  if (const auto* x = std::get_if<double>(&value)) return number_text(*x);
  if (const auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  if (const auto* b = std::get_if<bool>(&value)) return *b ? "true" : "false";
  if (const auto* s = std::get_if<std::string>(&value)) return "\"" + *s + "\"";
  if (const auto* v = std::get_if<std::vector<double>>(&value)) {
    std::string out;
    for (const double x : *v) out += (out.empty() ? "" : ", ") + number_text(x);
    return "[" + out + "]";
  }
  return "\"auto\"";
}

}  // namespace signorini

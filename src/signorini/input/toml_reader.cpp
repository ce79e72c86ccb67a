#include "signorini/input/toml_reader.hpp"

#include <algorithm>
#include <cmath>

#include "signorini/input/suggestion.hpp"
#include "signorini/input/toml_emitter.hpp"

namespace signorini {

std::string one_line(std::string text) {
  std::replace(text.begin(), text.end(), '\n', ' ');
  std::replace(text.begin(), text.end(), '\r', ' ');
  return text;
}

std::string join(const std::string& path, std::string_view key) {
  return path.empty() ? std::string(key) : path + "." + std::string(key);
}

std::string element(const std::string& path, std::size_t i) {
  return path + "[" + std::to_string(i) + "]";
}

const char* type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::table:
      return "table";
    case toml::node_type::array:
      return "array";
    case toml::node_type::string:
      return "string";
    case toml::node_type::integer:
      return "integer";
    case toml::node_type::floating_point:
      return "float";
    case toml::node_type::boolean:
      return "boolean";
    case toml::node_type::date:
      return "date";
    case toml::node_type::time:
      return "time";
    case toml::node_type::date_time:
      return "date-time";
    case toml::node_type::none:
      break;
  }
  return "nothing";
}

std::string trim(std::string_view s) {
  const auto first = s.find_first_not_of(" \t");
  if (first == std::string_view::npos) return {};
  const auto last = s.find_last_not_of(" \t");
  return std::string(s.substr(first, last - first + 1));
}

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto pos = s.find(sep, start);
    parts.push_back(s.substr(start, pos == std::string::npos ? std::string::npos : pos - start));
    if (pos == std::string::npos) break;
    start = pos + 1;
  }
  return parts;
}

std::optional<std::string> expression_text(const toml::node& n) {
  if (const auto* s = n.as_string()) return s->get();
  if (const auto* i = n.as_integer()) return std::to_string(i->get());
  if (const auto* f = n.as_floating_point()) return toml_float(f->get());
  return std::nullopt;
}

namespace {

// "clamp[2]" -> "clamp": the schema's name of a table path.
std::string schema_path(const std::string& path) {
  const auto bracket = path.find('[');
  return bracket == std::string::npos ? path : path.substr(0, bracket);
}

// "solver.linear" -> "solver"; "mesh" -> "".
std::string parent_path(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? std::string() : path.substr(0, dot);
}

// "<file>:<line>: " where the node came from the file (not from --set), else "<file>: ".
std::string where(const std::string& file, const toml::source_region& source) {
  if (source.begin.line == 0 || !source.path || *source.path != file) return file + ": ";
  return file + ":" + std::to_string(source.begin.line) + ": ";
}

}  // namespace

void Reader::fail(const std::string& message) const {
  throw InputError(file_ + ": " + one_line(message));
}

void Reader::fail_at(const toml::source_region& source, const std::string& message) const {
  throw InputError(where(file_, source) + one_line(message));
}

// The options of the table at `path`, then its subtables ("linear" in "solver"), in the order
// of problem_schema(): the candidates of a suggestion, ties going to the first.
std::vector<std::string> Reader::known_keys(const std::string& path) const {
  const std::string name = schema_path(path);
  std::vector<std::string> keys;
  for (const OptionTableInfo* table : *schema_)
    if (table->path == name)
      for (const OptionInfo& o : table->options) keys.push_back(o.key);
  for (const OptionTableInfo* table : *schema_)
    if (!table->path.empty() && parent_path(table->path) == name)
      keys.push_back(table->path.substr(name.empty() ? 0 : name.size() + 1));
  return keys;
}

void Reader::check_keys(const toml::table& t, const std::string& path) const {
  const std::vector<std::string> known = known_keys(path);
  for (auto&& [k, v] : t) {
    const std::string key(k.str());
    if (std::find(known.begin(), known.end(), key) != known.end()) continue;
    std::string message = "unknown key '" + join(path, key) + "'";
    std::string guess = closest_match(key, known);
    if (guess.empty())
      for (const OptionTableInfo* table : *schema_)
        if (table->path == schema_path(path))
          for (const OptionInfo& o : table->options)
            if (guess.empty() && is_synonym(o, key)) guess = o.key;
    if (!guess.empty()) {
      message += " (did you mean '" + join(path, guess) + "'?)";
    } else {
      // A key of another table, as "nx" at the top level: name the table it belongs in.
      for (const OptionTableInfo* table : *schema_) {
        if (table->path == schema_path(path) || table->path.empty()) continue;
        const std::vector<std::string> keys = known_keys(table->path);
        if (std::find(keys.begin(), keys.end(), key) == keys.end()) continue;
        message += " (did you mean '" + table->path + "." + key + "'? it belongs in the " +
                   (table->array_of_tables ? "[[" + table->path + "]]" : "[" + table->path + "]") +
                   " section)";
        break;
      }
    }
    if (overridden_.contains(join(path, key))) message += ", given by --set";
    fail_at(k.source(), message);
  }
}

void Reader::wrong_type(const std::string& key, const std::string& expected,
                        const toml::node& n) const {
  fail_at(n.source(), "key '" + key + "' must be " + expected + ", got " + type_name(n));
}

void Reader::missing(const std::string& key, const std::string& what) const {
  fail("missing required key '" + key + "' (" + what + ")");
}

void Reader::wrong_size(const std::string& key, const OptionInfo& o, std::size_t size,
                        std::size_t given, const toml::node& n) const {
  std::string names;
  for (std::size_t k = 0; k < size && k < o.entry_names.size(); ++k)
    names += (k > 0 ? ", " : "") + o.entry_names[k];
  fail_at(n.source(), "key '" + key + "' must have " + std::to_string(size) + " entries (" + names +
                          "), got " + std::to_string(given));
}

void Reader::out_of_range(const std::string& key, const std::string& value,
                          const std::string& expected, const toml::node* n) const {
  const std::string message = "key '" + key + "' = " + value + ": expected " + expected;
  if (n != nullptr) fail_at(n->source(), message);
  fail(message);
}

std::optional<double> Reader::number(const toml::table& t, const std::string& path,
                                     std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  // TOML keeps 1 and 1.0 apart; where a float is expected, "E = 210000" is meant as a number.
  if (const auto* i = n->as_integer()) return static_cast<double>(i->get());
  if (const auto* f = n->as_floating_point()) return f->get();
  wrong_type(join(path, key), "a number", *n);
}

std::optional<std::int64_t> Reader::integer(const toml::table& t, const std::string& path,
                                            std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* i = n->as_integer()) return i->get();
  wrong_type(join(path, key), "an integer", *n);
}

std::optional<bool> Reader::boolean(const toml::table& t, const std::string& path,
                                    std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* b = n->as_boolean()) return b->get();
  wrong_type(join(path, key), "true or false", *n);
}

std::optional<std::string> Reader::string(const toml::table& t, const std::string& path,
                                          std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  if (const auto* s = n->as_string()) return s->get();
  wrong_type(join(path, key), "a string", *n);
}

std::optional<std::string> Reader::expression(const toml::table& t, const std::string& path,
                                              std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  auto text = expression_text(*n);
  if (!text) wrong_type(join(path, key), "an expression (a string or a number)", *n);
  return text;
}

namespace {

// "2", "3", or "2 or 3" (count 0: a point or vector whose dimension the mesh decides).
std::string count_words(std::size_t count) {
  return count == 0 ? std::string("2 or 3") : std::to_string(count);
}

bool count_fits(std::size_t count, std::size_t size) {
  return count == 0 ? (size == 2 || size == 3) : size == count;
}

}  // namespace

std::optional<std::vector<std::string>> Reader::expressions(const toml::table& t,
                                                            const std::string& path,
                                                            std::string_view key,
                                                            std::size_t count) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return std::nullopt;
  const std::string full = join(path, key);
  const auto* a = n->as_array();
  const std::string expected =
      "an array of " + count_words(count) + " expressions (strings or numbers)";
  if (a == nullptr) wrong_type(full, expected, *n);
  if (!count_fits(count, a->size()))
    fail("key '" + full + "' must have " + count_words(count) + " entries (" +
         (count == 2   ? "x and y"
          : count == 3 ? "x, y and z"
                       : "x, y and, in 3D, z") +
         " components), got " + std::to_string(a->size()));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    auto text = expression_text(*a->get(i));
    if (!text) wrong_type(element(full, i), "an expression (a string or a number)", *a->get(i));
    out.push_back(*text);
  }
  return out;
}

std::vector<double> Reader::numbers(const toml::node& n, const std::string& key, std::size_t count,
                                    const std::string& entries) const {
  const auto* a = n.as_array();
  if (a == nullptr) wrong_type(key, "an array of " + count_words(count) + " numbers", n);
  if (!count_fits(count, a->size()))
    fail_at(n.source(), "key '" + key + "' must have " + count_words(count) + " entries (" +
                            entries + "), got " + std::to_string(a->size()));
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& e = *a->get(i);
    double v = 0.0;
    if (const auto* iv = e.as_integer())
      v = static_cast<double>(iv->get());
    else if (const auto* fv = e.as_floating_point())
      v = fv->get();
    else
      wrong_type(element(key, i), "a number", e);
    if (!std::isfinite(v)) out_of_range(element(key, i), toml_float(v), "a finite number");
    out.push_back(v);
  }
  return out;
}

const toml::table* Reader::table(const toml::table& t, const std::string& path,
                                 std::string_view key) const {
  const toml::node* n = t.get(key);
  if (n == nullptr) return nullptr;
  if (const auto* tt = n->as_table()) return tt;
  wrong_type(join(path, key), "a table ([" + join(path, key) + "])", *n);
}

std::vector<const toml::table*> Reader::array_of_tables(const toml::table& t,
                                                        std::string_view key) const {
  std::vector<const toml::table*> out;
  const toml::node* n = t.get(key);
  if (n == nullptr) return out;
  const std::string expected = "an array of tables ([[" + std::string(key) + "]] sections)";
  const auto* a = n->as_array();
  if (a == nullptr) wrong_type(std::string(key), expected, *n);
  for (std::size_t i = 0; i < a->size(); ++i) {
    const auto* e = a->get(i)->as_table();
    if (e == nullptr) wrong_type(element(std::string(key), i), "a table", *a->get(i));
    out.push_back(e);
  }
  return out;
}

std::optional<OptionValue> Reader::option(const toml::table& t, const std::string& path,
                                          const OptionInfo& o) const {
  const toml::node* n = t.get(o.key);
  if (n == nullptr) return std::nullopt;
  const std::string key = join(path, o.key);
  switch (o.kind) {
    case OptionKind::Number:
      return *number(t, path, o.key);
    case OptionKind::Integer: {
      const std::int64_t v = *integer(t, path, o.key);
      if (!integer_fits(o, v))
        out_of_range(key, std::to_string(v),
                     "an integer that fits in " + std::to_string(o.integer_bits) + " bits", n);
      return v;
    }
    case OptionKind::Boolean:
      return *boolean(t, path, o.key);
    case OptionKind::Text:
      return *string(t, path, o.key);
    case OptionKind::Choice: {
      const std::string text = *string(t, path, o.key);
      if (std::find(o.choices.begin(), o.choices.end(), text) != o.choices.end()) return text;
      // A choice of one ("mesh.type") says why there is no other.
      const std::string why = o.choices.size() == 1 ? " (" + o.doc + ")" : "";
      std::string message =
          "key '" + key + "' must be " + expected_words(o) + why + ", got '" + text + "'";
      const std::string guess = closest_match(text, o.choices);
      if (!guess.empty()) message += " (did you mean '" + guess + "'?)";
      fail_at(n->source(), message);
    }
    case OptionKind::NumberOrAuto:
      // A number, or "auto" (the default: chosen from the problem, method.md section 7).
      if (const auto* s = n->as_string()) {
        if (s->get() != "auto")
          fail_at(n->source(),
                  "key '" + key + "' must be " + expected_words(o) + ", got '" + s->get() + "'");
        return OptionValue(std::monostate{});
      }
      return *number(t, path, o.key);
    case OptionKind::Coordinates:
      // As many as the file gives (2 or 3): read_options() checks the count against the struct
      // (a box's origin has 3), naming the entries.
      return numbers(*n, key, 0, "a point or a vector");
    case OptionKind::Custom:
      break;
  }
  return std::nullopt;
}

}  // namespace signorini

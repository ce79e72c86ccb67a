#include "signorini/input/overrides.hpp"

#include <algorithm>
#include <optional>
#include <vector>

namespace signorini {

namespace {

std::optional<std::size_t> array_index(const std::string& s) {
  const auto digit = [](char c) { return c >= '0' && c <= '9'; };
  if (s.empty() || s.size() > 9 || !std::all_of(s.begin(), s.end(), digit)) return std::nullopt;
  return static_cast<std::size_t>(std::stoul(s));
}

}  // namespace

std::string apply_override(const Reader& r, toml::table& root, const std::string& text) {
  const auto eq = text.find('=');
  const std::string key = eq == std::string::npos ? std::string() : trim(text.substr(0, eq));
  if (key.empty()) r.fail("--set '" + text + "': expected key=value, e.g. --set mesh.nx=480");
  const std::string value = trim(text.substr(eq + 1));
  const std::vector<std::string> segments = split(key, '.');
  if (std::any_of(segments.begin(), segments.end(), [](const auto& s) { return trim(s).empty(); }))
    r.fail("--set '" + text + "': empty part in key '" + key + "'");

  toml::table* table = &root;
  std::string path;
  for (std::size_t i = 0; i + 1 < segments.size(); ++i) {
    const std::string& seg = segments[i];
    path = join(path, seg);
    toml::node* next = table->get(seg);
    if (next == nullptr) next = &table->insert_or_assign(seg, toml::table{}).first->second;
    if (auto* t = next->as_table()) {
      table = t;
    } else if (auto* a = next->as_array()) {
      // clamp.0.boundary: the entry of an array of tables.
      const auto index = i + 2 < segments.size() ? array_index(segments[i + 1]) : std::nullopt;
      if (!index)
        r.fail("--set '" + text + "': '" + path + "' is an array: name an entry, as " + path +
               ".0." + segments.back());
      if (*index >= a->size() || !a->get(*index)->is_table())
        r.fail("--set '" + text + "': '" + path + "' has no table entry " + std::to_string(*index));
      table = a->get(*index)->as_table();
      path = element(path, *index);
      ++i;
    } else {
      const std::string type = type_name(*next);
      const char* article = type.find_first_of("aeiou") == 0 ? "an " : "a ";
      r.fail("--set '" + text + "': '" + path + "' is " + article + type + ", not a table");
    }
  }

  // The value is TOML if it parses as one ("480", "1e8", "[0, 1]", "\"x\""); a bare word such as
  // semismooth_newton or an expression such as 0.5*x is not, and is taken as the string it reads.
  std::optional<toml::table> parsed;
  try {
    parsed = toml::parse("v = " + value, std::string("--set"));
  } catch (const toml::parse_error&) {
  }
  const std::string& last = segments.back();
  if (parsed && parsed->size() == 1 && parsed->get("v") != nullptr) {
    parsed->get("v")->visit([&](auto& node) { table->insert_or_assign(last, std::move(node)); });
  } else {
    table->insert_or_assign(last, value);
  }
  return join(path, last);
}

}  // namespace signorini

#pragma once
// Reading a parsed TOML file for the problem-file reader: typed values with one-line messages
// that name the file, the line and the key ("paper.toml:21: key 'mesh.nx' must be an integer,
// got string"), the unknown-key check with its suggestions, and the generic reading of an option
// table (core/option_table.hpp) into its struct.

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "signorini/core/error.hpp"
#include "signorini/core/option_table.hpp"
#include "signorini/input/toml_emitter.hpp"

namespace signorini {

// Text helpers shared by the readers of problem files and of --set overrides.

/// Messages from other libraries (toml++, muParser) may span lines; ours are one line each.
std::string one_line(std::string text);
/// "solver" + "linear" -> "solver.linear"; "" + "name" -> "name".
std::string join(const std::string& path, std::string_view key);
/// "traction" + 1 -> "traction[1]".
std::string element(const std::string& path, std::size_t i);
/// The names a user sees in "must be an integer, got string".
const char* type_name(const toml::node& n);
/// Without leading and trailing blanks and tabs.
std::string trim(std::string_view s);
/// The parts of `s` between the separators (empty parts kept).
std::vector<std::string> split(const std::string& s, char sep);
/// An expression given as a string or a number ("p = [0, 1]"): the text muParser gets.
std::optional<std::string> expression_text(const toml::node& n);

/// How a file is read: its name for messages, which keys came from --set (an unknown key says
/// so, since the user would otherwise look for it in the file), and the tables of keys it may
/// have (problem_schema()).
class Reader {
 public:
  Reader(std::string file, std::set<std::string> overridden,
         const std::vector<const OptionTableInfo*>& schema)
      : file_(std::move(file)), overridden_(std::move(overridden)), schema_(&schema) {}

  [[noreturn]] void fail(const std::string& message) const;
  /// With the line of the file where the offending key or value is (none for a --set value).
  [[noreturn]] void fail_at(const toml::source_region& source, const std::string& message) const;

  /// Unknown keys are checked before the values of a table are read, so that a misspelt required
  /// key reports "unknown key 'mesh.nxx' (did you mean 'mesh.nx'?)", not "missing 'mesh.nx'".
  void check_keys(const toml::table& t, const std::string& path) const;

  [[noreturn]] void wrong_type(const std::string& key, const std::string& expected,
                               const toml::node& n) const;
  [[noreturn]] void missing(const std::string& key, const std::string& what) const;
  /// "key 'mesh.origin' must have 3 entries (x0, y0, z0), got 2".
  [[noreturn]] void wrong_size(const std::string& key, const OptionInfo& o, std::size_t size,
                               std::size_t given, const toml::node& n) const;
  /// "key 'mesh.nx' = 0: expected an integer >= 1", at the line of `n` if there is one.
  [[noreturn]] void out_of_range(const std::string& key, const std::string& value,
                                 const std::string& expected, const toml::node* n = nullptr) const;

  std::optional<double> number(const toml::table& t, const std::string& path,
                               std::string_view key) const;
  std::optional<std::int64_t> integer(const toml::table& t, const std::string& path,
                                      std::string_view key) const;
  std::optional<bool> boolean(const toml::table& t, const std::string& path,
                              std::string_view key) const;
  std::optional<std::string> string(const toml::table& t, const std::string& path,
                                    std::string_view key) const;
  std::optional<std::string> expression(const toml::table& t, const std::string& path,
                                        std::string_view key) const;
  /// An array of `count` expressions ("traction[0].p"); count 0: 2 or 3 (the components of a
  /// vector whose dimension the mesh decides).
  std::optional<std::vector<std::string>> expressions(const toml::table& t, const std::string& path,
                                                      std::string_view key,
                                                      std::size_t count) const;
  /// An array of exactly `count` finite numbers ("mesh.origin", "traction[0].x_range"), or of 2
  /// or 3 with count 0; `entries` says what they are, for the message.
  std::vector<double> numbers(const toml::node& n, const std::string& key, std::size_t count,
                              const std::string& entries) const;
  const toml::table* table(const toml::table& t, const std::string& path,
                           std::string_view key) const;
  /// The entries of an array of tables ([[clamp]]); empty if the key is absent.
  std::vector<const toml::table*> array_of_tables(const toml::table& t, std::string_view key) const;

  /// The value of option `o` in table `t` (at `path`), read and type-checked as its kind says;
  /// empty if the key is absent. Ranges are left to check_options().
  std::optional<OptionValue> option(const toml::table& t, const std::string& path,
                                    const OptionInfo& o) const;

  /// Calls a library validate() and names the file in its message.
  template <class Options>
  void validated(const Options& options) const {
    try {
      validate(options);
    } catch (const InputError& e) {
      fail(e.what());
    }
  }

  [[nodiscard]] const std::string& file() const { return file_; }

 private:
  [[nodiscard]] std::vector<std::string> known_keys(const std::string& path) const;

  std::string file_;
  std::set<std::string> overridden_;
  const std::vector<const OptionTableInfo*>* schema_;
};

/// Reads every option of `table` that is in `t` into `target`, checking its type; a missing
/// required one is an error. Custom options are left to the section's own reader.
template <class S>
void read_options(const Reader& r, const toml::table& t, const OptionTable<S>& table, S& target) {
  for (std::size_t i = 0; i < table.options.size(); ++i) {
    const OptionInfo& o = table.options[i];
    if (!table.setter(i)) continue;
    if (const std::optional<OptionValue> v = r.option(t, table.path, o)) {
      // A point's entries: as many as the struct takes (the options before it, such as
      // mesh.type, are set already); where the option does not apply, check_options() says so.
      if (const auto* xs = std::get_if<std::vector<double>>(&*v); xs && table.applies(i, target))
        if (const std::size_t size = table.vector_size(i, target); xs->size() != size)
          r.wrong_size(table.full_key(o.key), o, size, xs->size(), *t.get(o.key));
      table.setter(i)(target, *v);
    } else if (o.required) {
      r.missing(table.full_key(o.key), type_words(o));
    }
  }
}

/// The ranges of the options of `table` in `s`, as the file gives them: "paper.toml:21: key
/// 'mesh.nx' = 0: expected an integer >= 1" (the line if the value came from the file).
template <class S>
void check_options(const Reader& r, const toml::table* t, const OptionTable<S>& table, const S& s) {
  for (std::size_t i = 0; i < table.options.size(); ++i) {
    if (!table.getter(i)) continue;
    const OptionInfo& o = table.options[i];
    if (!table.applies(i, s)) {
      // Given where it means nothing: say when it applies ("mesh.nx applies with type =
      // \"rectangle\" only").
      if (t != nullptr && t->contains(o.key))
        r.fail_at(t->get(o.key)->source(),
                  table.full_key(o.key) + " applies with " + o.condition + " only; remove it");
      continue;
    }
    const OptionValue v = table.getter(i)(s);
    if (!in_range(o, v))
      r.out_of_range(table.full_key(o.key), toml_value_text(v), expected_words(o),
                     t != nullptr ? t->get(o.key) : nullptr);
  }
}

}  // namespace signorini

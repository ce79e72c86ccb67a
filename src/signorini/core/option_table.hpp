#pragma once
// Options declared once (issue 11): one table per options struct names each key as a problem
// file spells it, with its kind, its range, its default (read from a default-constructed struct,
// never written twice) and its doc. The problem-file reader, the --set overrides, the effective
// settings, the summary.json echo, the unknown-key check with its suggestions and the generated
// tables of docs/problem-format.md all walk these tables, and validate() takes its key names and
// ranges from them (as deal.II's ParameterHandler::declare_entry and MFEM's OptionsParser do), so
// that adding an option means its member, its entry here and its use.
//
// Private to the library: no file format here (input/ reads and writes TOML through the tables),
// only what an option is.

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "signorini/core/enum_names.hpp"
#include "signorini/core/error.hpp"

namespace signorini {

/// How an option is written, which decides how it is read, checked, printed and documented.
enum class OptionKind {
  Number,        ///< a float (an integer is accepted: "E = 210000")
  Integer,       ///< an integer (a float is not: "nx = 60.0" is an error)
  Boolean,       ///< true or false
  Choice,        ///< one of OptionInfo::choices (an enumeration's name table)
  Text,          ///< any string
  NumberOrAuto,  ///< a number, or "auto" (a std::optional<double>, empty meaning automatic)
  Coordinates,   ///< an array of finite numbers, as many as its table says for the struct
                 ///< (mesh.origin: 2 for a rectangle, 3 for a box)
  Custom,        ///< read by its section's own reader (formulas, names of components): key and
                 ///< doc only, so that the unknown-key check and the docs still know it
};

/// A value as a problem file spells it: "auto" (std::monostate, NumberOrAuto only), a flag, an
/// integer, a number, a name or text, a point or vector (2 numbers in 2D, 3 in 3D).
using OptionValue =
    std::variant<std::monostate, bool, std::int64_t, double, std::string, std::vector<double>>;

/// The numbers an option accepts: finite, and within an interval whose ends may be open, closed
/// or absent.
struct OptionRange {
  std::optional<double> lower;
  std::optional<double> upper;
  bool lower_open = false;
  bool upper_open = false;
  [[nodiscard]] bool contains(double x) const;
};

/// (0, inf)
inline OptionRange positive() {
  return {0.0, std::nullopt, true, false};
}
/// [lower, inf)
inline OptionRange at_least(double lower) {
  return {lower, std::nullopt, false, false};
}
/// (lower, upper)
inline OptionRange open_interval(double lower, double upper) {
  return {lower, upper, true, true};
}
/// [lower, upper]
inline OptionRange closed_interval(double lower, double upper) {
  return {lower, upper, false, false};
}

/// Everything about an option but how to reach it in its struct: what the reader, the docs and
/// the unknown-key check need, whatever the struct.
struct OptionInfo {
  std::string key;
  OptionKind kind = OptionKind::Custom;
  /// The meaning, as the docs' table says it (Markdown; '|' is escaped when rendered).
  std::string doc;
  OptionRange range;  ///< Number, Integer, NumberOrAuto
  /// Said after the range in messages: "(0: automatic)".
  std::string range_note;
  /// Choice: the names, as the enumeration's name table spells them.
  std::vector<std::string> choices;
  /// Integer: the width of the field (32 for an int), so that a larger value is refused, never
  /// wrapped.
  int integer_bits = 64;
  bool required = false;
  /// The docs' unit column: "L" (length), "S" (stress), "S L", "S/L" (problem-format.md, Units).
  std::string unit;
  /// Custom and Coordinates: the docs' type column ("array of 2 expressions of x, y").
  std::string type_text;
  /// Coordinates: the names of its entries ("x0", "y0", "z0"), the first as many as it takes, for
  /// messages.
  std::vector<std::string> entry_names;
  /// Where the default is not a value of the option: "the whole part", "none".
  std::string default_text;
  /// Other names people write for the key, which spelling distance does not find ("Young" for
  /// "E"): lower case, matched whole, or anywhere in the key with a leading '*' ("*young").
  std::vector<std::string> synonyms;
  /// The value of a default-constructed struct (empty for Custom options).
  std::optional<OptionValue> default_value;
  /// When the option applies, in words ("type = \"rectangle\""); empty: always.
  std::string condition;
};

/// "a positive number", "an integer in [1, 50]", "\"cpu\" or \"cuda\"": what a message says was
/// expected ("key 'mesh.nx' = 0: expected an integer >= 1").
std::string expected_words(const OptionInfo& option);
/// "number > 0", "integer >= 1", "boolean": the docs' type column and the hint of a missing key
/// ("missing required key 'mesh.nx' (integer >= 1)"). With `markdown`, names are in backticks.
std::string type_words(const OptionInfo& option, bool markdown = false);
/// Whether `value` is within the option's range (numbers finite, integers within the field).
bool in_range(const OptionInfo& option, const OptionValue& value);
/// Whether an integer fits in the option's field.
bool integer_fits(const OptionInfo& option, std::int64_t value);
/// Whether `key` (any case) is one of the option's synonyms.
bool is_synonym(const OptionInfo& option, std::string_view key);
/// A number as the validate() messages print it (%g).
std::string plain_value_text(const OptionValue& value);

/// The options of one table of a problem file, whatever struct they live in.
struct OptionTableInfo {
  /// The dotted name of the table: "solver.linear"; "" is the top level; "clamp" stands for each
  /// [[clamp]] entry.
  std::string path;
  bool array_of_tables = false;
  std::vector<OptionInfo> options;

  /// "solver.linear.type" for "type".
  [[nodiscard]] std::string full_key(std::string_view key) const {
    return path.empty() ? std::string(key) : path + "." + std::string(key);
  }
  /// The option named `key`, or null.
  [[nodiscard]] const OptionInfo* find(std::string_view key) const {
    for (const OptionInfo& o : options)
      if (o.key == key) return &o;
    return nullptr;
  }
};

/// The options of a table that live in struct S, each with how to read and set its value.
/// Built entry by entry, in the order of the file and the docs:
///
///   OptionTable<ContactSolverOptions> t("solver");
///   t.number("uzawa_tolerance", &ContactSolverOptions::uzawa_tolerance, positive(), "...");
///
/// A field is a pointer to member or a projection, [](auto& s) -> auto& { return s.a.b; }.
template <class S>
class OptionTable : public OptionTableInfo {
 public:
  using Getter = std::function<OptionValue(const S&)>;
  using Setter = std::function<void(S&, const OptionValue&)>;

  explicit OptionTable(std::string table_path, bool is_array_of_tables = false) {
    path = std::move(table_path);
    array_of_tables = is_array_of_tables;
  }

  /// How to read option i from a struct; empty for Custom options.
  [[nodiscard]] const Getter& getter(std::size_t i) const { return getters_[i]; }
  /// How to set option i in a struct; empty for Custom options.
  [[nodiscard]] const Setter& setter(std::size_t i) const { return setters_[i]; }
  /// Whether option i means anything for `s` (mesh.nx only for a rectangle mesh): options that
  /// do not apply are neither written to the effective settings nor accepted in a file.
  [[nodiscard]] bool applies(std::size_t i, const S& s) const {
    return !conditions_[i] || conditions_[i](s);
  }
  /// Coordinates option i: how many numbers it takes in `s` (mesh.origin: 3 for a box).
  [[nodiscard]] std::size_t vector_size(std::size_t i, const S& s) const {
    return sizes_[i] ? sizes_[i](s) : 0;
  }
  /// (key, value) of every option that lives in the struct and applies to `s`, in table order:
  /// what the effective settings, summary.json and spec comparisons are made of.
  [[nodiscard]] std::vector<std::pair<std::string, OptionValue>> values(const S& s) const {
    std::vector<std::pair<std::string, OptionValue>> out;
    for (std::size_t i = 0; i < options.size(); ++i)
      if (getters_[i] && applies(i, s)) out.emplace_back(options[i].key, getters_[i](s));
    return out;
  }
  /// The condition of the last option, and the words that say it in messages ("type =
  /// \"rectangle\"").
  OptionTable& applies_when(std::function<bool(const S&)> condition, std::string words) {
    conditions_.back() = std::move(condition);
    last().condition = std::move(words);
    return *this;
  }

  template <class Field>
  OptionTable& number(std::string key, Field field, OptionRange range, std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::Number, std::move(doc));
    o.range = range;
    return add(
        std::move(o),
        [field](const S& s) { return OptionValue(static_cast<double>(std::invoke(field, s))); },
        [field](S& s, const OptionValue& v) { std::invoke(field, s) = std::get<double>(v); });
  }

  template <class Field>
  OptionTable& integer(std::string key, Field field, OptionRange range, std::string doc) {
    using T = std::remove_cvref_t<decltype(std::invoke(field, std::declval<S&>()))>;
    OptionInfo o = info(std::move(key), OptionKind::Integer, std::move(doc));
    o.range = range;
    o.integer_bits = static_cast<int>(8 * sizeof(T));
    return add(
        std::move(o),
        [field](const S& s) {
          return OptionValue(static_cast<std::int64_t>(std::invoke(field, s)));
        },
        [field](S& s, const OptionValue& v) {
          std::invoke(field, s) = static_cast<T>(std::get<std::int64_t>(v));
        });
  }

  template <class Field>
  OptionTable& boolean(std::string key, Field field, std::string doc) {
    return add(
        info(std::move(key), OptionKind::Boolean, std::move(doc)),
        [field](const S& s) { return OptionValue(static_cast<bool>(std::invoke(field, s))); },
        [field](S& s, const OptionValue& v) { std::invoke(field, s) = std::get<bool>(v); });
  }

  /// An enumeration, spelt as its name table (core/enum_names.hpp) spells it.
  template <class Field, class Enum, std::size_t N>
  OptionTable& choice(std::string key, Field field, const EnumNames<Enum, N>& names,
                      std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::Choice, std::move(doc));
    for (const auto& [e, name] : names) o.choices.emplace_back(name);
    return add(
        std::move(o),
        [field, &names](const S& s) {
          return OptionValue(std::string(enum_to_string(names, std::invoke(field, s))));
        },
        [field, &names](S& s, const OptionValue& v) {
          // The reader has checked the name against the choices.
          if (const auto e = enum_from_string(names, std::get<std::string>(v)))
            std::invoke(field, s) = *e;
        });
  }

  /// A choice of one name that nothing stores (mesh.type = "rectangle": the only mesh so far).
  OptionTable& fixed(std::string key, std::string value, std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::Choice, std::move(doc));
    o.choices = {value};
    return add(
        std::move(o), [value](const S&) { return OptionValue(value); },
        [](S&, const OptionValue&) {});
  }

  template <class Field>
  OptionTable& text(std::string key, Field field, std::string doc) {
    return add(
        info(std::move(key), OptionKind::Text, std::move(doc)),
        [field](const S& s) { return OptionValue(std::string(std::invoke(field, s))); },
        [field](S& s, const OptionValue& v) { std::invoke(field, s) = std::get<std::string>(v); });
  }

  /// A std::optional<double>: a number, or "auto" for none.
  template <class Field>
  OptionTable& number_or_auto(std::string key, Field field, OptionRange range, std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::NumberOrAuto, std::move(doc));
    o.range = range;
    return add(
        std::move(o),
        [field](const S& s) {
          const std::optional<double>& v = std::invoke(field, s);
          return v ? OptionValue(*v) : OptionValue(std::monostate{});
        },
        [field](S& s, const OptionValue& v) {
          std::optional<double>& target = std::invoke(field, s);
          if (const double* x = std::get_if<double>(&v))
            target = *x;
          else
            target.reset();
        });
  }

  /// Numbers kept in fields of the struct, as many as `size(s)` says (mesh.origin = [x0, y0] for
  /// a rectangle, [x0, y0, z0] for a box): `get` returns them, `set` takes exactly that many
  /// (the reader checks the count first, naming the key). `entry_names` name the entries for
  /// messages, `type_text` is the docs' type column.
  template <class Get, class Set, class Size>
  OptionTable& vector(std::string key, Get get, Set set, Size size,
                      std::vector<std::string> entry_names, std::string type_text,
                      std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::Coordinates, std::move(doc));
    o.entry_names = std::move(entry_names);
    o.type_text = std::move(type_text);
    add(
        std::move(o), [get](const S& s) { return OptionValue(std::vector<double>(get(s))); },
        [set](S& s, const OptionValue& v) { set(s, std::get<std::vector<double>>(v)); });
    sizes_.back() = [size](const S& s) { return static_cast<std::size_t>(size(s)); };
    return *this;
  }

  /// A key that its section's own reader reads: `type_text` for the docs' type column.
  OptionTable& custom(std::string key, std::string type_text, std::string doc) {
    OptionInfo o = info(std::move(key), OptionKind::Custom, std::move(doc));
    o.type_text = std::move(type_text);
    return add(std::move(o), nullptr, nullptr);
  }

  // Modifiers of the option added last.
  OptionTable& required() {
    last().required = true;
    return *this;
  }
  OptionTable& unit(std::string text) {
    last().unit = std::move(text);
    return *this;
  }
  OptionTable& range_note(std::string text) {
    last().range_note = std::move(text);
    return *this;
  }
  OptionTable& default_text(std::string text) {
    last().default_text = std::move(text);
    return *this;
  }
  OptionTable& synonyms(std::vector<std::string> names) {
    last().synonyms = std::move(names);
    return *this;
  }

 private:
  static OptionInfo info(std::string key, OptionKind kind, std::string doc) {
    OptionInfo o;
    o.key = std::move(key);
    o.kind = kind;
    o.doc = std::move(doc);
    return o;
  }

  OptionTable& add(OptionInfo o, Getter get, Setter set) {
    // The default is what a default-constructed struct holds: stated once, in the struct.
    if (get) o.default_value = get(S{});
    options.push_back(std::move(o));
    getters_.push_back(std::move(get));
    setters_.push_back(std::move(set));
    conditions_.emplace_back();
    sizes_.emplace_back();
    return *this;
  }

  OptionInfo& last() { return options.back(); }

  std::vector<Getter> getters_;
  std::vector<Setter> setters_;
  std::vector<std::function<bool(const S&)>> conditions_;    // empty: always applies
  std::vector<std::function<std::size_t(const S&)>> sizes_;  // Coordinates options only
};

/// Throws InputError naming the first option of `table` whose value in `s` is out of its range,
/// by its key as the file spells it: "solver.r = -1: expected a positive number or "auto"" (the
/// messages of the library's validate() functions).
template <class S>
void check_ranges(const OptionTable<S>& table, const S& s) {
  for (std::size_t i = 0; i < table.options.size(); ++i) {
    if (!table.getter(i)) continue;
    const OptionInfo& o = table.options[i];
    const OptionValue v = table.getter(i)(s);
    if (!in_range(o, v))
      throw InputError(table.full_key(o.key) + " = " + plain_value_text(v) + ": expected " +
                       expected_words(o));
  }
}

}  // namespace signorini

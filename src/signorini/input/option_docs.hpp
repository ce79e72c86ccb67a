#pragma once
// The key tables of docs/problem-format.md, rendered from the option tables
// (input/problem_schema.hpp), so that the docs list exactly the keys the reader knows, with their
// types, ranges and defaults. Each table sits between two markers in the docs,
//
//   <!-- BEGIN GENERATED: option table [solver] -->
//   <!-- END GENERATED: option table [solver] -->
//
// and tests/input/option_table_test.cpp fails when the docs differ from the rendering (with
// SIGNORINI_UPDATE_DOCS=1 it writes the rendering into the docs instead).

#include <string>

#include "signorini/core/option_table.hpp"

namespace signorini {

/// How the docs name a table: "top level", "[mesh]", "[[clamp]]".
std::string section_title(const OptionTableInfo& table);

/// | key | type | (unit |) default | meaning |, one row per option; the unit column only where
/// some option has a unit.
std::string option_table_markdown(const OptionTableInfo& table);

/// `markdown` with the text between the markers of every table of problem_schema() replaced by
/// its option_table_markdown(). Throws InputError naming a table whose markers are missing, or a
/// marker that names no table.
std::string with_generated_option_tables(const std::string& markdown);

}  // namespace signorini

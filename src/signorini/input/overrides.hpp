#pragma once
// --set KEY=VALUE (docs/problem-format.md, "Overrides on the command line"): a change to the parsed
// TOML tree, made before any key is read, so that an override is checked exactly as the same key
// in the file would be (the same option tables, the same messages).

#include <toml++/toml.h>

#include <string>

#include "signorini/input/toml_reader.hpp"

namespace signorini {

/// Applies "dotted.key=value" to the parsed file; returns the key as check_keys() names it
/// ("clamp[0].boundary"). The value is TOML if it parses as one, else the string it reads;
/// missing tables on the way are created; "clamp.0.boundary" indexes an array of tables.
std::string apply_override(const Reader& r, toml::table& root, const std::string& text);

}  // namespace signorini

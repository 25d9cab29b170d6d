// The TOML files --config reads (config_file.hpp): key = value lines of strings (TOML's escapes
// decoded), bare numbers (digits grouped by underscores) and booleans, and one-line arrays of
// them; tables, inline tables and nested arrays are refused, as is anything TOML does not allow
// that would otherwise run other settings than the file meant.
#pragma once

#include <iosfwd>
#include <map>
#include <string>

#include "config_file.hpp"

namespace molchaos::app {

/// The items of a TOML file, in file order, each value as its option reads it (strings without
/// quotes); throws UsageError("--config", ...) naming `path` and the line of a syntax error.
/// `quoted_literals` receives each key whose value (or an element of it) is a string that reads
/// as a number ("100"; not one beyond TOML's integers) or a boolean ("true"), with its place
/// ("path line N"): TOML's types are lost in the items, and an option that takes numbers or a
/// flag refuses such a string (apply_config_file).
ConfigItems read_toml(std::istream& in, const std::string& path,
                      std::map<std::string, std::string>& quoted_literals);

/// Whether `text` is an unsigned integer beyond 2^63 − 1, which TOML's signed 64-bit integers
/// cannot hold: written in quotes (half of all seeds), a string of digits that is no mistaken
/// type, so read_toml does not count it among the quoted numbers. Digits beyond 2^64 − 1 too:
/// the option's own range refuses them (written bare, they would be refused all the same).
bool beyond_toml_integers(const std::string& text);

/// `text` without the spaces, tabs and carriage returns around it.
std::string trim(const std::string& text);

}  // namespace molchaos::app

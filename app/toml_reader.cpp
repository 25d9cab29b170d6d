// The TOML reader of --config files (toml_reader.hpp).
#include "toml_reader.hpp"

#include <cctype>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <istream>
#include <limits>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "cli_support.hpp"

namespace molchaos::app {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

namespace {

// UTF-8 of a code point (TOML's escapes of four or eight hexadecimal digits); throws for a
// surrogate or beyond U+10FFFF, which name no character.
std::string utf8(unsigned long code, const std::string& where) {
  if (code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF))
    throw UsageError("--config", where + ": a \\u escape that names no character");
  std::string out;
  if (code < 0x80) {
    out += static_cast<char>(code);
  } else if (code < 0x800) {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else if (code < 0x10000) {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
  return out;
}

// A TOML string: "basic" with TOML's escapes decoded, or 'literal' as written. An escape TOML
// does not define, or text after the closing quote, is refused: dropping a backslash would name
// another file ("sub\run.csv" read as subrun.csv).
std::string toml_string(const std::string& text, const std::string& where) {
  const char quote = text.front();
  std::string value;
  std::size_t k = 1;
  for (; k < text.size() && text[k] != quote; ++k) {
    if (quote == '\'' || text[k] != '\\') {
      value += text[k];
      continue;
    }
    if (++k == text.size()) break;
    const char e = text[k];
    const std::string_view plain = "btnfr\"\\", meant = "\b\t\n\f\r\"\\";
    if (const auto at = plain.find(e); at != std::string_view::npos) {
      value += meant[at];
    } else if (e == 'u' || e == 'U') {
      const std::size_t digits = e == 'u' ? 4 : 8;
      const std::string hex = text.substr(k + 1, digits);
      if (hex.size() != digits ||
          hex.find_first_not_of("0123456789abcdefABCDEF") != std::string::npos)
        throw UsageError("--config", where + ": \\" + e + " takes " + std::to_string(digits) +
                                         " hexadecimal digits");
      value += utf8(std::stoul(hex, nullptr, 16), where);
      k += digits;
    } else {
      throw UsageError("--config",
                       where + ": unknown escape '\\" + std::string(1, e) +
                           "' in a string (TOML's: \\b \\t \\n \\f \\r \\\" \\\\ "
                           "\\uXXXX \\UXXXXXXXX; or write the path in 'single quotes')");
    }
  }
  if (k >= text.size()) throw UsageError("--config", where + ": unterminated string");
  if (k + 1 != text.size())
    throw UsageError("--config", where + ": text after the closing quote of a string");
  // TOML's control escapes name characters no option takes: "C:\runs\new.csv" holds a
  // carriage return and a line feed where a Windows path was meant.
  if (std::any_of(value.begin(), value.end(),
                  [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7F; }))
    throw UsageError("--config", where +
                                     ": a control character in a string (an escape such as \\r "
                                     "or \\n; a Windows path? write it with / or in 'single "
                                     "quotes')");
  return value;
}

// A bare number as the options read it: TOML groups digits with underscores (1_000_000), each
// between two digits; anything else with an underscore is left for the option to refuse.
std::string number_without_underscores(const std::string& text, const std::string& where) {
  const auto digit = [&](std::size_t k) {
    return k < text.size() && std::isdigit(static_cast<unsigned char>(text[k])) != 0;
  };
  const bool signed_number = (text[0] == '+' || text[0] == '-') && digit(1);
  if (text.find('_') == std::string::npos || !(digit(0) || signed_number)) return text;
  std::string number;
  for (std::size_t k = 0; k < text.size(); ++k) {
    if (text[k] != '_') {
      number += text[k];
    } else if (k == 0 || !digit(k - 1) || !digit(k + 1)) {
      throw UsageError("--config", where + ": '" + text +
                                       "': an underscore in a number stands between two digits "
                                       "(1_000_000)");
    }
  }
  return number;
}

// TOML's hexadecimal, octal and binary integers (0x10, 0o20, 0b10000) in decimal, as the options
// read them; any other text as it is.
std::string decimal_integer(const std::string& text, const std::string& where) {
  if (text.size() < 2 || text[0] != '0' || (text[1] != 'x' && text[1] != 'o' && text[1] != 'b'))
    return text;
  const int base = text[1] == 'x' ? 16 : text[1] == 'o' ? 8 : 2;
  std::uint64_t value = 0;
  const char* first = text.data() + 2;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(first, last, value, base);
  if (first == last || end != last || ec != std::errc())
    throw UsageError("--config", where + ": '" + text + "' is no integer of base " +
                                     std::to_string(base) + " within 64 bits");
  return std::to_string(value);
}

// Whether a string reads in full as a number ("100", "0.5"): written in quotes, it is a TOML
// string, which an option that takes numbers refuses (apply_config_file).
bool reads_as_number(const std::string& text) {
  if (text.empty() || std::isspace(static_cast<unsigned char>(text.front())) != 0) return false;
  char* end = nullptr;
  std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size();
}

// One TOML value: a string (toml_string), or a bare number/boolean. A bare word is no TOML value
// (randomize = paper): refused, naming the key, where quotes are meant. `quoted_literal` is set
// where the value is a string that reads as a number or a boolean.
std::string toml_scalar(const std::string& text, const std::string& where, const std::string& key,
                        bool& quoted_literal) {
  if (text.empty()) throw UsageError("--config", where + ": missing value");
  if (text.front() == '{')
    throw UsageError("--config", where + ": inline tables are not used; write key = value lines");
  if (text.front() == '"' || text.front() == '\'') {
    std::string value = toml_string(text, where);
    quoted_literal = quoted_literal || value == "true" || value == "false" ||
                     (reads_as_number(value) && !beyond_toml_integers(value));
    return value;
  }
  if (text.front() == '[')
    throw UsageError("--config", where + ": arrays inside arrays are not used; give one list");
  // TOML's bare values start with a digit or a sign, or are true, false, inf and nan.
  if (std::isalpha(static_cast<unsigned char>(text.front())) != 0 && text != "true" &&
      text != "false" && text != "inf" && text != "nan")
    throw UsageError("--config", where + ": key '" + key + "': '" + text +
                                     "' is no TOML value: a string is written in quotes (" + key +
                                     " = \"" + text +
                                     "\"), a boolean as true or false, a number bare");
  return decimal_integer(number_without_underscores(text, where), where);
}

// Where a string of the line opens and closes: quote is the open string's quote (0 outside one);
// c the next character, escaped whether it follows a backslash inside a "basic" string.
void track_quote(char& quote, bool& escaped, char c) {
  if (escaped) {
    escaped = false;
  } else if (quote == '"' && c == '\\') {
    escaped = true;
  } else if (quote == 0 && (c == '"' || c == '\'')) {
    quote = c;
  } else if (c == quote) {
    quote = 0;
  }
}

// Splits at the top-level commas of an array's inside (commas inside strings are kept).
std::vector<std::string> toml_array(const std::string& inside, const std::string& where,
                                    const std::string& key, bool& quoted_literal) {
  std::vector<std::string> values;
  std::string item;
  char quote = 0;
  bool escaped = false;
  for (const char c : inside) {
    if (quote == 0 && c == ',') {
      // An empty element ([1,, 2]) is no TOML: dropping it would run the list without a word.
      if (trim(item).empty())
        throw UsageError("--config", where + ": an empty element in an array");
      values.push_back(toml_scalar(trim(item), where, key, quoted_literal));
      item.clear();
      continue;
    }
    track_quote(quote, escaped, c);
    item += c;
  }
  // A trailing comma is TOML ([1, 2,]); an empty array ([]) holds no element.
  if (!trim(item).empty()) values.push_back(toml_scalar(trim(item), where, key, quoted_literal));
  return values;
}

// The text before a comment: '#' outside quotes.
std::string strip_comment(const std::string& line) {
  char quote = 0;
  bool escaped = false;
  for (std::size_t k = 0; k < line.size(); ++k) {
    if (quote == 0 && line[k] == '#') return line.substr(0, k);
    track_quote(quote, escaped, line[k]);
  }
  return line;
}

}  // namespace

bool beyond_toml_integers(const std::string& text) {
  std::uint64_t value = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (end != text.data() + text.size()) return false;
  return ec == std::errc::result_out_of_range ||
         (ec == std::errc() &&
          value > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max()));
}

ConfigItems read_toml(std::istream& in, const std::string& path,
                      std::map<std::string, std::string>& quoted_literals) {
  ConfigItems items;
  std::string line;
  for (int number = 1; std::getline(in, line); ++number) {
    const std::string where = path + " line " + std::to_string(number);
    const std::string text = trim(strip_comment(line));
    if (text.empty()) continue;
    if (text.front() == '[')
      throw UsageError("--config", where + ": tables are not used; write key = value lines");
    const auto eq = text.find('=');
    if (eq == std::string::npos)
      throw UsageError("--config", where + ": expected key = value" +
                                       (text.front() == '{'
                                            ? " (a config file is TOML, key = value lines; JSON "
                                              "is not read)"
                                            : ""));
    std::string key = trim(text.substr(0, eq));
    // A quoted key, "t_end" or 't_end' (TOML's basic and literal strings), is the bare key.
    if (key.size() >= 2 && (key.front() == '"' || key.front() == '\'') &&
        key.back() == key.front())
      key = key.substr(1, key.size() - 2);
    const std::string value = trim(text.substr(eq + 1));
    bool quoted_literal = false;
    if (!value.empty() && value.front() == '[') {
      if (value.back() != ']')
        throw UsageError("--config", where + ": an array must close on its line");
      items.emplace_back(key,
                         toml_array(value.substr(1, value.size() - 2), where, key, quoted_literal));
    } else {
      items.emplace_back(key,
                         std::vector<std::string>{toml_scalar(value, where, key, quoted_literal)});
    }
    if (quoted_literal) quoted_literals.emplace(key, where);
  }
  return items;
}

}  // namespace molchaos::app

// Shared pieces of the command-line front end: range validators whose messages name the allowed
// range, and the usage-error type that main() turns into exit status 2 with one line on stderr.
#pragma once

#include <CLI/CLI.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace molchaos::app {

/// Bad input found after parsing (for example a combination of flags). main() prints
/// "molchaos: error: <argument>: <what>" and exits with status 2.
class UsageError : public std::runtime_error {
 public:
  UsageError(const std::string& argument, const std::string& what)
      : std::runtime_error(argument + ": " + what) {}
};

inline std::string format_interval(double lo, bool lo_closed, double hi, bool hi_closed) {
  auto num = [](double x) {
    if (std::isinf(x)) return std::string(x > 0 ? "inf" : "-inf");
    std::string s = std::to_string(x);
    s.erase(s.find_last_not_of('0') + 1);
    if (!s.empty() && s.back() == '.') s.pop_back();
    return s;
  };
  return std::string(lo_closed ? "[" : "(") + num(lo) + ", " + num(hi) + (hi_closed ? "]" : ")");
}

/// A validator for a real number in an interval; the message names the allowed range.
inline CLI::Validator real_in(double lo, bool lo_closed, double hi, bool hi_closed) {
  const std::string range = format_interval(lo, lo_closed, hi, hi_closed);
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        double x = 0.0;
        std::size_t used = 0;
        try {
          x = std::stod(text, &used);
        } catch (...) {
          used = 0;
        }
        if (used == 0 || used != text.size() || !std::isfinite(x))
          return "'" + text + "' is not a number; allowed range " + range;
        const bool ok_lo = lo_closed ? x >= lo : x > lo;
        const bool ok_hi = hi_closed ? x <= hi : x < hi;
        if (!ok_lo || !ok_hi) return "value " + text + " is outside the allowed range " + range;
        return {};
      },
      "in " + range);
}

/// A validator for an integer in the closed interval [lo, hi].
inline CLI::Validator integer_in(long long lo, long long hi) {
  const std::string range = "[" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
  return CLI::Validator(
      [=](std::string& text) -> std::string {
        long long x = 0;
        std::size_t used = 0;
        try {
          x = std::stoll(text, &used);
        } catch (...) {
          used = 0;
        }
        if (used == 0 || used != text.size())
          return "'" + text + "' is not an integer; allowed range " + range;
        if (x < lo || x > hi) return "value " + text + " is outside the allowed range " + range;
        return {};
      },
      "integer in " + range);
}

}  // namespace molchaos::app

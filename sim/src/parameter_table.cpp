// Text form, parsing and range checks of the rows of the parameter table.
#include "molchaos/sim/parameter_table.hpp"

#include <charconv>
#include <cmath>
#include <stdexcept>
#include <type_traits>

namespace molchaos::sim {
namespace {

template <class T>
bool parse_number(std::string_view text, T& out) {
  const char* first = text.data();
  const char* last = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(first, last, out);
  return !text.empty() && ec == std::errc() && ptr == last;
}

template <class T>
constexpr bool is_integer_v = std::is_integral_v<T> && !std::is_same_v<T, bool>;

bool inside(double x, const ParameterRange& r) {
  const bool ok_lo = r.lo_closed ? x >= r.lo : x > r.lo;
  const bool ok_hi = r.hi_closed ? x <= r.hi : x < r.hi;
  return ok_lo && ok_hi;
}

}  // namespace

std::string round_trip_text(double x) {
  char buffer[64];
  const auto [end, ec] = std::to_chars(buffer, buffer + sizeof buffer, x);
  return std::string(buffer, end);
}

// Every digit that tells x from its neighbours: a bound printed shorter reads as a value the check
// refuses (1.11111 for a limit of 1.1111111111111112), or a refused value as an accepted one.
std::string message_number(double x) { return round_trip_text(x); }

const ParameterInfo* find_parameter(std::string_view name) {
  for (const ParameterInfo& info : parameter_table())
    if (info.name == name) return &info;
  return nullptr;
}

std::string range_text(const ParameterInfo& info) {
  const ParameterRange& r = info.range;
  return std::visit(
      [&](auto member) -> std::string {
        using T = std::remove_cvref_t<decltype(Parameters{}.*member)>;
        if constexpr (std::is_same_v<T, std::uint64_t>) {
          return "[0, " + std::to_string(std::numeric_limits<std::uint64_t>::max()) + "]";
        } else if constexpr (is_integer_v<T>) {
          std::string text = "[";
          text += std::to_string(static_cast<long long>(r.lo));
          text += ", ";
          text += std::to_string(static_cast<long long>(r.hi));
          text += ']';
          return text;
        } else if constexpr (std::is_enum_v<T>) {
          std::string text = "{";  // appended piecewise (GCC 12 warns falsely on literal + string)
          text += choice_list(info);
          text += '}';
          return text;
        } else if constexpr (std::is_same_v<T, bool>) {
          return "{false, true}";
        } else {
          std::string text(1, r.lo_closed ? '[' : '(');
          text += message_number(r.lo);
          text += ", ";
          text += message_number(r.hi);
          text += r.hi_closed ? ']' : ')';
          return text;
        }
      },
      info.field);
}

std::size_t choice_index(const Parameters& p, const ParameterInfo& info) {
  return std::visit(
      [&](auto member) -> std::size_t {
        using T = std::remove_cvref_t<decltype(p.*member)>;
        if constexpr (std::is_enum_v<T>) {
          const auto index = static_cast<long long>(p.*member);
          if (index < 0 || index >= static_cast<long long>(info.choices.size()))
            throw std::invalid_argument(std::string(info.name) + ": value " +
                                        std::to_string(index) + " is outside the allowed range {" +
                                        choice_list(info) + "}");
          return static_cast<std::size_t>(index);
        } else {
          return 0;
        }
      },
      info.field);
}

void set_choice_index(Parameters& p, const ParameterInfo& info, std::size_t index) {
  if (index >= info.choices.size())
    throw std::invalid_argument(std::string(info.name) + ": choice " + std::to_string(index) +
                                " is outside the allowed range {" + choice_list(info) + "}");
  std::visit(
      [&](auto member) {
        using T = std::remove_cvref_t<decltype(p.*member)>;
        if constexpr (std::is_enum_v<T>) p.*member = static_cast<T>(index);
      },
      info.field);
}

std::optional<std::size_t> find_choice(const ParameterInfo& info, std::string_view text) {
  for (std::size_t i = 0; i < info.choices.size(); ++i)
    if (info.choices[i] == text) return i;
  return std::nullopt;
}

std::string choice_list(const ParameterInfo& info) {
  std::string list;
  for (std::string_view name : info.choices) {
    if (!list.empty()) list += ", ";
    list += name;
  }
  return list;
}

std::string format_value(const Parameters& p, const ParameterInfo& info) {
  return std::visit(
      [&](auto member) -> std::string {
        const auto& value = p.*member;
        using T = std::remove_cvref_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>) {
          return value ? "true" : "false";
        } else if constexpr (is_integer_v<T>) {
          return std::to_string(value);
        } else if constexpr (std::is_same_v<T, double>) {
          return round_trip_text(value);
        } else if constexpr (std::is_enum_v<T>) {
          return std::string(info.choices[choice_index(p, info)]);
        } else {
          std::string list;
          for (double t : value) {
            if (!list.empty()) list += ' ';
            list += round_trip_text(t);
          }
          return list;
        }
      },
      info.field);
}

bool omitted(const Parameters& p, const ParameterInfo& info) {
  return info.omitted_at_default && format_value(p, info) == format_value(Parameters{}, info);
}

void parse_value(Parameters& p, const ParameterInfo& info, std::string_view text) {
  auto fail = [&] {
    throw std::invalid_argument(std::string(info.name) + ": cannot read '" + std::string(text) +
                                "'");
  };
  std::visit(
      [&](auto member) {
        auto& value = p.*member;
        using T = std::remove_cvref_t<decltype(value)>;
        if constexpr (std::is_same_v<T, bool>) {
          if (text != "true" && text != "false") fail();
          value = text == "true";
        } else if constexpr (std::is_enum_v<T>) {
          const auto index = find_choice(info, text);
          if (!index) fail();
          value = static_cast<T>(*index);
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          value.clear();
          std::size_t at = 0;
          while (at < text.size()) {
            const std::size_t end = std::min(text.find(' ', at), text.size());
            double t = 0;
            if (!parse_number(text.substr(at, end - at), t)) fail();
            value.push_back(t);
            at = end + 1;
          }
        } else {
          T x{};
          if (!parse_number(text, x)) fail();
          value = x;
        }
      },
      info.field);
}

void check_range(const Parameters& p, const ParameterInfo& info) {
  auto out_of_range = [&](const std::string& value) {
    throw std::invalid_argument(std::string(info.name) + ": value " + value +
                                " is outside the allowed range " + range_text(info));
  };
  std::visit(
      [&](auto member) {
        const auto& value = p.*member;
        using T = std::remove_cvref_t<decltype(value)>;
        if constexpr (std::is_same_v<T, std::uint64_t> || std::is_same_v<T, bool>) {
          // every value of the type is allowed
        } else if constexpr (is_integer_v<T>) {
          if (!inside(static_cast<double>(value), info.range)) out_of_range(std::to_string(value));
        } else if constexpr (std::is_same_v<T, double>) {
          if (!inside(value, info.range)) out_of_range(message_number(value));
        } else if constexpr (std::is_same_v<T, std::vector<double>>) {
          for (double x : value)
            if (!inside(x, info.range)) out_of_range(message_number(x));
        } else {  // a choice
          const auto index = static_cast<long long>(value);
          if (index < 0 || index >= static_cast<long long>(info.choices.size()))
            out_of_range(std::to_string(index));
        }
      },
      info.field);
}

}  // namespace molchaos::sim

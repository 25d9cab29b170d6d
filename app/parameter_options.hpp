// Command-line options made from the parameter table: each row gives its flag, its check (the
// row's range), its help line and its default, so every subcommand spells a parameter the same way.
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "cli_support.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::app {

/// Accepts the names of a choice row's values.
inline CLI::Validator choice_name(const sim::ParameterInfo& info) {
  const std::string list = sim::choice_list(info);
  return CLI::Validator(
      [&info, list](std::string& text) -> std::string {
        if (sim::find_choice(info, text)) return {};
        return "unknown value '" + text + "'; allowed: " + list;
      },
      "one of " + list);
}

/// The check of one value (or one list element) of a row.
inline CLI::Validator parameter_check(const sim::ParameterInfo& info) {
  const sim::ParameterRange& r = info.range;
  return std::visit(
      [&](auto member) -> CLI::Validator {
        using T = std::remove_cvref_t<decltype(sim::Parameters{}.*member)>;
        if constexpr (std::is_same_v<T, std::uint64_t>)
          return unsigned_integer();
        else if constexpr (std::is_same_v<T, int> || std::is_same_v<T, std::int64_t>)
          return integer_in(static_cast<long long>(r.lo), static_cast<long long>(r.hi));
        else if constexpr (std::is_enum_v<T>)
          return choice_name(info);
        else
          return real_in(r.lo, r.lo_closed, r.hi, r.hi_closed);  // double, list of doubles
      },
      info.field);
}

inline std::string parameter_help(const sim::ParameterInfo& info) {
  std::string help(info.doc);
  if (!info.unit.empty()) help += " [" + std::string(info.unit) + "]";
  return help;
}

inline const sim::ParameterInfo& parameter_row(std::string_view name) {
  const sim::ParameterInfo* info = sim::find_parameter(name);
  if (!info) throw std::logic_error("no parameter named " + std::string(name));
  return *info;
}

/// Every row of the table as an option of `cmd` writing into `p` (whose values are the defaults).
inline void add_parameter_options(CLI::App* cmd, sim::Parameters& p) {
  for (const sim::ParameterInfo& info : sim::parameter_table()) {
    const std::string flag(info.flag);
    const std::string help = parameter_help(info);
    std::visit(
        [&](auto member) {
          auto& target = p.*member;
          using T = std::remove_cvref_t<decltype(target)>;
          if constexpr (std::is_same_v<T, bool>) {
            cmd->add_flag(flag, target, help);
          } else if constexpr (std::is_enum_v<T>) {
            cmd->add_option_function<std::string>(
                   flag,
                   [&p, &info](const std::string& text) {
                     sim::set_choice_index(p, info, *sim::find_choice(info, text));
                   },
                   help)
                ->transform(parameter_check(info))
                ->default_str(sim::format_value(p, info));
          } else if constexpr (std::is_same_v<T, std::vector<double>>) {
            // Values as several arguments (0 1 10) or comma separated (0,1,10), as a sweep's lists;
            // "" alone for none (the table's lists are empty by default), over a --config file's.
            add_list_option(cmd, flag, target, help + "; \"\" for none (clears a --config file's)",
                            parameter_check(info), /*empty_is_none=*/true);
          } else {
            cmd->add_option(flag, target, help)
                ->transform(parameter_check(info))
                ->capture_default_str();
          }
        },
        info.field);
  }
}

/// The option of row `name` bound to a value of another struct (a sweep's specification).
template <class T>
CLI::Option* add_parameter_option(CLI::App* cmd, std::string_view name, T& target) {
  const sim::ParameterInfo& info = parameter_row(name);
  if constexpr (std::is_enum_v<T>) {  // a choice: by name
    return cmd
        ->add_option_function<std::string>(
            std::string(info.flag),
            [&target, &info](const std::string& text) {
              target = static_cast<T>(*sim::find_choice(info, text));
            },
            parameter_help(info))
        ->transform(parameter_check(info))
        ->default_str(std::string(info.choices[static_cast<std::size_t>(target)]));
  } else {
    return cmd->add_option(std::string(info.flag), target, parameter_help(info))
        ->transform(parameter_check(info))
        ->capture_default_str();
  }
}

/// The option of row `name` taking a comma-separated list (a sweep over that parameter).
template <class T>
CLI::Option* add_parameter_list_option(CLI::App* cmd, std::string_view name,
                                       std::vector<T>& target) {
  const sim::ParameterInfo& info = parameter_row(name);
  std::string shown;  // the default list, as the help shows it
  for (const T& value : target) shown += (shown.empty() ? "" : ",") + fmt::format("{}", value);
  return add_list_option(cmd, std::string(info.flag), target,
                         parameter_help(info) + " (comma separated)", parameter_check(info))
      ->default_str(shown);
}

}  // namespace molchaos::app

// The one declaration of every run parameter: field, name, CLI flag, allowed range, unit and one
// line of documentation. Validation, the CLI of every subcommand, the CSV header (write and read),
// the cache key and the MPI wire format all walk this table; adding a parameter is one row here.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "molchaos/sim/parameters.hpp"

namespace molchaos::sim {

/// The field of Parameters a row describes; the alternative is the field's C++ type. An enum field
/// is a choice: its row lists the names of its values (see ParameterInfo::choices), and every
/// consumer treats it through those names and the value's index, so a new enum parameter is its
/// row plus its member pointer type here.
using ParameterField =
    std::variant<int Parameters::*, std::int64_t Parameters::*, std::uint64_t Parameters::*,
                 double Parameters::*, bool Parameters::*, Randomization Parameters::*,
                 Method Parameters::*, std::vector<double> Parameters::*>;

/// Allowed values of a number, or of each element of a list (static part only: bounds that depend
/// on other fields, such as close packing or snapshot_times <= t_end, are checked by validate()).
struct ParameterRange {
  double lo = -std::numeric_limits<double>::infinity();
  bool lo_closed = false;
  double hi = std::numeric_limits<double>::infinity();
  bool hi_closed = false;
};

struct ParameterInfo {
  std::string_view name;  ///< field name: CSV header key, cache key, validation messages
  std::string_view flag;  ///< command-line flag
  ParameterField field;
  ParameterRange range;
  std::string_view unit;  ///< "" for pure numbers and choices
  std::string_view doc;   ///< one line of help text
  /// A choice (enum field): the name of each value, indexed by the value (0, 1, ...); empty for
  /// every other kind. Text form, help, checks and the MPI message all read the names from here.
  std::span<const std::string_view> choices = {};
  /// A row added after result files and cache entries existed: at its default value it is left
  /// out of the CSV header and the cache key (so both stay byte-identical to those written
  /// before the row), and a header without it reads as the default.
  bool omitted_at_default = false;
};

/// The names of the choices, index = enum value; the one place they are spelled.
inline constexpr std::array<std::string_view, 3> k_randomization_names{"none", "paper", "flux"};
inline constexpr std::array<std::string_view, 2> k_method_names{"edmd", "dsmc"};

namespace detail {
constexpr double k_inf = std::numeric_limits<double>::infinity();
}  // namespace detail

/// Every field of Parameters, in the order of the CSV header and the MPI message. Defaults are
/// the member initializers of Parameters (default_parameters()).
inline const std::array<ParameterInfo, 16>& parameter_table() {
  using detail::k_inf;
  using P = Parameters;
  static const std::array<ParameterInfo, 16> table{{
      {"dimension", "--dim", &P::dimension, {2, true, 3, true}, "", "Dimension d"},
      {"particles",
       "--particles",
       &P::particles,
       {2, true, 1e8, true},
       "",
       "Number of particles N"},
      {"density",
       "--density",
       &P::density,
       {0, false, k_inf, false},
       "sigma^-d",
       "Reduced density n = N sigma^d / V, below close packing (1.1547 for d = 2, 1.41421 for "
       "d = 3), and below the densest start the N particles allow (a lattice, lower for "
       "spheres; a refusal names it)"},
      {"restitution",
       "--restitution",
       &P::restitution,
       {0, false, 1, true},
       "",
       "Coefficient of restitution"},
      {"randomize",
       "--randomize",
       &P::randomize,
       {},
       "",
       "Velocity shuffle: none, paper, flux",
       k_randomization_names},
      {"seed", "--seed", &P::seed, {0, true, 18446744073709551615.0, true}, "", "Random seed"},
      {"t_end",
       "--t-end",
       &P::t_end,
       {0, false, k_inf, false},
       "sigma sqrt(m/T0)",
       "Physical duration of the cooling run"},
      {"relax_collisions_per_particle",
       "--relax",
       &P::relax_collisions_per_particle,
       {0, true, 1e9, true},  // N/2 times this many collisions is counted in 64 bits
       "collisions per particle",
       "Elastic collisions per particle before t = 0"},
      {"tc",
       "--tc",
       &P::tc,
       {0, true, k_inf, false},
       "sigma sqrt(m/T0)",
       "TC model duration (0 = off)"},
      {"samples_per_decade",
       "--samples-per-decade",
       &P::samples_per_decade,
       {1, true, 10000, true},
       "",
       "Samples per decade of time"},
      {"t_first_sample",
       "--t-first-sample",
       &P::t_first_sample,
       {0, false, k_inf, false},
       "sigma sqrt(m/T0)",
       "First log-spaced sample time"},
      {"contact_statistics",
       "--contacts",
       &P::contact_statistics,
       {},
       "",
       "Record contact statistics of collisions"},
      {"snapshot_times",
       "--snapshot-times",
       &P::snapshot_times,
       {0, true, k_inf, false},
       "sigma sqrt(m/T0)",
       "Times of position/velocity snapshots, in [0, t_end]"},
      {"max_collisions",
       "--max-collisions",
       &P::max_collisions,
       {0, true, 18446744073709551615.0, true},
       "",
       "Stop after this many collisions, or after the events they imply (100 times a "
       "homogeneous gas's events per collision; 0 = no limit)"},
      {"min_temperature",
       "--min-temperature",
       &P::min_temperature,
       {0, true, 1, false},
       "T0",
       "Stop when T/T0 falls below (0 = no)"},
      {"method",
       "--method",
       &P::method,
       {},
       "",
       "Simulation method: edmd (event-driven MD), dsmc (DSMC of the Enskog-Boltzmann equation; "
       "velocities only)",
       k_method_names,
       true},
  }};
  return table;
}

/// A number as validation messages print it: round_trip_text() ("inf", "nan" included).
std::string message_number(double x);

/// The shortest text that reads back to the same double, locale independent: how every result
/// file (CSV, XYZ, the parameter values) writes a number.
std::string round_trip_text(double x);

/// The row of a field name, or nullptr.
const ParameterInfo* find_parameter(std::string_view name);

/// "[2, 3]", "(0, inf)", "[0, 1)": the allowed range as validation messages print it.
std::string range_text(const ParameterInfo& info);

/// The index of a choice row's value (0 for other rows).
std::size_t choice_index(const Parameters& p, const ParameterInfo& info);

/// Sets a choice row's value from its index; throws std::invalid_argument("<name>: ...") if the
/// index names no choice.
void set_choice_index(Parameters& p, const ParameterInfo& info, std::size_t index);

/// The index of `text` among the row's choices, or nullopt.
std::optional<std::size_t> find_choice(const ParameterInfo& info, std::string_view text);

/// "none, paper, flux": the row's choices as messages and help print them.
std::string choice_list(const ParameterInfo& info);

/// The field's value as text: shortest round-trip decimals, true/false, mode names, a
/// space-separated list. This is what the CSV header and the cache key print.
std::string format_value(const Parameters& p, const ParameterInfo& info);

/// True if the row is omitted_at_default and p holds its default: the CSV header and the cache key
/// then leave the row out.
bool omitted(const Parameters& p, const ParameterInfo& info);

/// Inverse of format_value; throws std::invalid_argument("<name>: cannot read '<text>'").
void parse_value(Parameters& p, const ParameterInfo& info, std::string_view text);

/// Throws std::invalid_argument("<name>: value X is outside the allowed range R") if the field
/// lies outside its static range.
void check_range(const Parameters& p, const ParameterInfo& info);

}  // namespace molchaos::sim

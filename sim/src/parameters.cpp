// Validation of Parameters (each field's range from the parameter table, then the bounds that join
// fields) and the names of the randomization modes.
#include "molchaos/sim/parameters.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "molchaos/sim/dsmc.hpp"
#include "molchaos/sim/initial_state.hpp"
#include "molchaos/sim/parameter_table.hpp"

namespace molchaos::sim {
namespace {

std::string number(double x) { return message_number(x); }

[[noreturn]] void out_of_range(const std::string& field, const std::string& value,
                               const std::string& range) {
  throw std::invalid_argument(field + ": value " + value + " is outside the allowed range " +
                              range);
}

}  // namespace

// The names live with the row of the parameter table.
std::string_view to_string(Randomization mode) {
  const auto index = static_cast<std::size_t>(mode);
  return index < k_randomization_names.size() ? k_randomization_names[index] : "none";
}

std::optional<Randomization> parse_randomization(std::string_view text) {
  for (std::size_t i = 0; i < k_randomization_names.size(); ++i)
    if (text == k_randomization_names[i]) return static_cast<Randomization>(i);
  return std::nullopt;
}

bool method_runs_mode(Method method, Randomization mode) {
  return method == Method::edmd || mode == Randomization::none;
}

bool method_relaxes(Method method) { return method == Method::edmd; }

void default_relaxation_for_method(Parameters& p) {
  if (!method_relaxes(p.method)) p.relax_collisions_per_particle = 0;
}

double close_packing_density(int dimension) {
  // Hexagonal packing of disks, n = 2/sqrt(3); fcc packing of spheres, n = sqrt(2).
  return dimension == 2 ? 2.0 / std::sqrt(3.0) : std::sqrt(2.0);
}

double box_side(const Parameters& p) {
  return std::pow(static_cast<double>(p.particles) / p.density, 1.0 / p.dimension);
}

void validate(const Parameters& p) {
  // Each field against its own range (the table), then the bounds that join several fields.
  for (const ParameterInfo& info : parameter_table()) check_range(p, info);
  if (p.method == Method::dsmc) validate_dsmc(p);
  if (p.randomize != Randomization::none && p.particles < 4)
    out_of_range("particles", std::to_string(p.particles),
                 "[4, 100000000] with randomize = " + std::string(to_string(p.randomize)) +
                     " (the shuffle needs two particles besides the colliding pair)");
  const double n_max = close_packing_density(p.dimension);
  if (!(p.density < n_max))
    out_of_range("density", number(p.density),
                 "(0, " + number(n_max) + ") (close packing for dimension " +
                     std::to_string(p.dimension) + ")");
  // A first sample after t_end would leave the run with t = 0 and t_end alone, no log-spaced
  // series: refused when asked for; the default is kept in runs shorter than it. (t_first_sample
  // = t_end asks for the two end points alone, as the elastic-limit checks do.)
  if (p.t_first_sample > p.t_end && p.t_first_sample != Parameters{}.t_first_sample)
    out_of_range("t_first_sample", number(p.t_first_sample),
                 "(0, t_end] = (0, " + number(p.t_end) + "] (the log-spaced samples start there)");
  for (double t : p.snapshot_times)
    if (!(t <= p.t_end))
      out_of_range("snapshot_times", number(t), "[0, t_end] = [0, " + number(p.t_end) + "]");
  // Snapshot k (the file <out>.snapshot<k>.csv, the k-th frame of a trajectory) is taken at the
  // k-th time listed: the list must increase, or the files would not match the list's order.
  for (std::size_t k = 1; k < p.snapshot_times.size(); ++k)
    if (!(p.snapshot_times[k] > p.snapshot_times[k - 1]))
      throw std::invalid_argument("snapshot_times: value " + number(p.snapshot_times[k]) +
                                  " follows " + number(p.snapshot_times[k - 1]) +
                                  "; the times must increase (each snapshot once)");
  const double side = box_side(p);
  if (!std::isfinite(side)) {
    // N / n overflows: the smallest density with a finite box for this N, rounded up.
    const double n_min =
        std::nextafter(static_cast<double>(p.particles) / std::numeric_limits<double>::max(),
                       std::numeric_limits<double>::infinity());
    out_of_range("density", number(p.density),
                 "[" + number(n_min) + ", " + number(n_max) + ") for N = " +
                     std::to_string(p.particles) + " (a finite box side (N / n)^(1/d))");
  }
  // The limits below are the MD engine's (its cells, its initial configuration); DSMC keeps
  // velocities only, and its density enters through the contact value g2 alone.
  if (p.method == Method::dsmc) return;
  // The cell lists need at least 4 cells of width >= sigma per side: with 3, two particles in
  // neighbouring cells can be more than half a box apart and the minimum image flips while they
  // approach, so a collision is missed (found with two disks in a box of side 10).
  if (side < 4.0)
    throw std::invalid_argument("particles: value " + std::to_string(p.particles) +
                                " gives a box side " + number(side) +
                                " below 4 sigma at this density; the allowed range is N >= " +
                                number(std::ceil(p.density * std::pow(4.0, p.dimension))));
  // Below close packing but above what the initial state can reach for this N: refused here, as
  // a usage error, rather than after the work has started.
  // (Dilute starts, packing below 0.2, always fit; the lattice search is then not needed.)
  const double packing =
      (p.dimension == 2 ? std::numbers::pi / 4.0 : std::numbers::pi / 6.0) * p.density;
  if (packing >= 0.2 && !start_lattice(p.dimension, p.particles, side).fits())
    out_of_range("density", number(p.density),
                 "(0, " + number(densest_start(p.dimension, p.particles, side)) + ") for N = " +
                     std::to_string(p.particles) +
                     (p.dimension == 2
                          ? " disks: the densest initial state, a staggered lattice with vacancies,"
                          : " spheres: the densest initial state, a simple cubic lattice with "
                            "vacancies,") +
                     " reaches no further (close packing is " + number(n_max) + ")");
}

}  // namespace molchaos::sim

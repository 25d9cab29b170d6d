// The collisions a run will take, estimated before it starts: what lets a run that would go on for
// days be refused at once, naming the longest t_end allowed (Engine::check_run_length, and the
// DSMC run's check), instead of running without a word.
#pragma once

#include <functional>
#include <string>

namespace molchaos::sim {

/// The most events (MD: collisions, crossings, stale predictions) or collision candidates (DSMC)
/// a run or a relaxation may be estimated to take, hours at a few million per second: beyond it
/// the request is refused instead of running for days.
inline constexpr double k_max_run_events = 1e11;

/// The homogeneous gas from T = 1, as the estimate sees it.
struct RunLengthGas {
  int dimension = 2;
  double collision_frequency = 0;  ///< per particle at T = 1 (Enskog's, ω_E)
  double restitution = 1;
  double tc = 0;                ///< the TC model's duration (0: none)
  double stop_temperature = 0;  ///< the run ends where T reaches it
};

/// Estimated collisions per particle from time 0 to t: ω_E t at restitution 1; Haff's law below it
/// (to the stop temperature); with the TC model, Haff's cooling slowed by the fraction of
/// collisions that stay inelastic (run_length.cpp). An estimate: within about 10 % where measured.
double estimated_collisions_per_particle(const RunLengthGas& gas, double t);

/// An estimated count as a refusal names it: "about 6.2e+11 events" (two digits), or "more events
/// than a double holds" where the estimate overflowed (a t_end near the largest double).
std::string estimated_count(double expected, const std::string& unit);

/// The longest time in (0, t_end] whose cost(t) (increasing in t) stays within `budget`, by
/// bisection in log t, to three digits rounded down; t_end itself when cost(t_end) is within.
double longest_time_within(const std::function<double(double)>& cost, double t_end, double budget);

}  // namespace molchaos::sim

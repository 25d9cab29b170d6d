// What a run produces: the time series of samples (temperature, a2, collision counts, break-down
// indicators of the homogeneous cooling state, contact statistics), optional snapshots.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/stop_reason.hpp"

namespace molchaos::sim {

/// Sums over the collisions in one sample interval of pre-collision reduced velocities
/// c = v / sqrt(2T) (T the temperature at the collision), e the unit vector from j to i at contact.
struct ContactMoments {
  std::uint64_t count = 0;
  double sum_c1e_c2e = 0;    // (c1.e)(c2.e)
  double sum_c1_dot_c2 = 0;  // c1.c2
  double sum_gn2 = 0;        // (c12.e)^2
  double sum_abs_gn = 0;     // |c12.e|
  double sum_g2 = 0;         // |c12|^2
  /// Impact parameter s = (1 − (ĝ·e)²)^((d−1)/2) (|sin θ| in 2D, sin²θ in 3D; uniform on [0, 1)
  /// under molecular chaos) in equal bins; filled by accumulate() of contact_statistics.hpp.
  static constexpr int k_impact_bins = 10;
  std::array<std::uint64_t, k_impact_bins> impact_histogram{};

  /// Whether these sums can come from collisions: finite, the sums of squares and moduli not
  /// negative, and one histogram entry per collision (a restored checkpoint's check).
  bool well_formed() const {
    std::uint64_t binned = 0;
    for (const std::uint64_t b : impact_histogram) binned += b;
    using std::isfinite;
    return binned == count && isfinite(sum_c1e_c2e) && isfinite(sum_c1_dot_c2) && sum_gn2 >= 0 &&
           isfinite(sum_gn2) && sum_abs_gn >= 0 && isfinite(sum_abs_gn) && sum_g2 >= 0 &&
           isfinite(sum_g2);
  }
};

struct Sample {
  double t = 0;                  // physical time
  double temperature = 0;        // T = <v^2>/d
  double a2 = 0;                 // Sonine coefficient d/(d+2) <v^4>/<v^2>^2 - 1
  std::uint64_t collisions = 0;  // since t = 0
  std::uint64_t events = 0;      // since t = 0 (collisions, cell crossings, stale events)
  double velocity_mode = 0;      // <|sum_i v_i exp(ik.r_i)|^2> / (N d T) over k = 2 pi / L e_a
  double density_mode = 0;       // <|sum_i exp(ik.r_i)|^2> / N over the same k
  ContactMoments contacts;  // collisions since the previous sample (only with contact_statistics)
};

struct Snapshot {
  double t = 0;
  double box = 0;
  std::uint64_t collisions = 0;    // since t = 0 (an event-driven run's step counter)
  std::vector<double> positions;   // d*N, particle-major, in [0, box)
  std::vector<double> velocities;  // d*N, particle-major
};

struct RunResult {
  Parameters parameters;
  std::vector<Sample> samples;
  std::vector<Snapshot> snapshots;
  std::uint64_t collisions = 0;
  std::uint64_t events = 0;
  double wall_seconds = 0;
  StopReason stop_reason = StopReason::t_end;  // the time it names: samples.back().t
  std::string version;      // molchaos version that produced it
};

/// The stop reason's text, as in the CSV header (its time is that of the last sample).
inline std::string stop_message(const RunResult& r) {
  return describe(r.stop_reason, r.samples.empty() ? 0.0 : r.samples.back().t, r.parameters.tc);
}

}  // namespace molchaos::sim

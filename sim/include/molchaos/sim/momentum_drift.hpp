// Collisions conserve momentum only up to rounding, and the centre of mass keeps its velocity
// while the gas cools: after some 30 decades of cooling this drift would carry most of the
// kinetic energy (T frozen at the drift's: in MD the gas drifts across cells without colliding,
// in DSMC the drift sets the bound on relative speeds and nearly every candidate is rejected).
// The total momentum is zero by construction, so the drift is removed once its energy exceeds
// k_drift_fraction of the total; before that (every run that cools by fewer than about 20
// decades) no velocity is touched.
#pragma once

#include <cstddef>

namespace molchaos::sim {

inline constexpr double k_drift_fraction = 1e-10;

/// Removes the mean velocity from every record when its energy exceeds k_drift_fraction of
/// sum_u2 (the records' sum of squared velocities); returns whether it did. velocity(record):
/// the record's D velocity components (double*).
template <int D, class Records, class Velocity>
bool remove_momentum_drift(Records&& records, double sum_u2, Velocity&& velocity) {
  double mean[D] = {};
  std::size_t n = 0;
  for (auto& record : records) {
    const double* u = velocity(record);
    for (int a = 0; a < D; ++a) mean[a] += u[a];
    ++n;
  }
  double drift_u2 = 0;
  for (int a = 0; a < D; ++a) {
    mean[a] /= static_cast<double>(n);
    drift_u2 += static_cast<double>(n) * mean[a] * mean[a];
  }
  if (!(drift_u2 > k_drift_fraction * sum_u2)) return false;
  for (auto& record : records) {
    double* u = velocity(record);
    for (int a = 0; a < D; ++a) u[a] -= mean[a];
  }
  return true;
}

}  // namespace molchaos::sim

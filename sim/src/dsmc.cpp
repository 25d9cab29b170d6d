// DSMC of the homogeneous Enskog–Boltzmann equation: the candidate loop (majorant, thinning,
// exponential clock), the collision, the bookkeeping of units and bounds, and run_dsmc.
#include "molchaos/sim/dsmc.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "molchaos/sim/collision.hpp"
#include "molchaos/sim/contact_statistics.hpp"
#include "molchaos/sim/dsmc_contact.hpp"
#include "molchaos/sim/momentum_drift.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/sim/run_length.hpp"
#include "molchaos/version.hpp"

namespace molchaos::sim {
namespace {

// Velocities are rescaled to internal T = 1 when the internal temperature falls below this.
constexpr double k_rescale_temperature = 0.25;
// The product of the candidates' uniforms is turned into time before it can underflow (a
// uniform in (0, 1] is at least 2^-53, so the product stays above 1e-216).
constexpr double k_underflow = 1e-200;
// B = max|u| (1 + 1e-12): a bound even after the rounding of the square root.
constexpr double k_bound_margin = 1.0 + 1e-12;

}  // namespace

void validate_dsmc(const Parameters& p) {
  if (!method_runs_mode(Method::dsmc, p.randomize))
    throw std::invalid_argument(
        "randomize: value " + std::string(to_string(p.randomize)) +
        " is not allowed with method = dsmc (a shuffle only permutes velocities, which leaves the "
        "DSMC state unchanged); allowed value none");
  if (p.tc != 0)
    throw std::invalid_argument("tc: value " + message_number(p.tc) +
                                " is not allowed with method = dsmc; allowed value 0");
  // A relaxation written in the header that did not happen would be a false record of the run.
  if (p.relax_collisions_per_particle != 0)
    throw std::invalid_argument(
        "relax_collisions_per_particle: value " + message_number(p.relax_collisions_per_particle) +
        " is not allowed with method = dsmc (it starts from the homogeneous Maxwellian state and "
        "does no relaxation; relaxation applies to method = edmd only); allowed value 0");
  if (!p.snapshot_times.empty())
    throw std::invalid_argument(
        "snapshot_times: not allowed with method = dsmc (it has no positions); allowed: none");
}

template <int D>
DsmcGas<D>::DsmcGas(const Parameters& p, double contact_value_g2)
    : rng_(p.seed ^ 0xb7e151628aed2a6bULL) {
  validate(p);
  validate_dsmc(p);
  if (p.dimension != D) throw std::invalid_argument("dimension: DSMC instantiated for another d");
  if (!(contact_value_g2 > 0 && std::isfinite(contact_value_g2)))
    throw std::invalid_argument("contact_value_g2: value " + std::to_string(contact_value_g2) +
                                " is outside the allowed range (0, inf)");
  n_ = static_cast<std::uint32_t>(p.particles);
  rule_ = ConstantRestitution{p.restitution};
  contacts_on_ = p.contact_statistics;
  collision_limit_ = p.max_collisions;
  const double n = static_cast<double>(n_);
  // Λ = k (2B/s) N(N − 1)/2 with k = g2 β_d / V = n g2 β_d / N.
  rate_per_bound_ = p.density * contact_value_g2 * k_cross_section<D> * (n - 1.0) / 2.0;
  min_sum_u2_ = p.min_temperature * n * D;
  velocity_.resize(n_);
  Rng initial(p.seed);
  draw_maxwell_velocities(initial);
  bookkeeping();
  update_rate();
  for (auto& pair : ahead_) pair = draw_pair(rng_);
}

// As the MD: independent normals, the mean removed, scaled to T = 1 exactly.
template <int D>
void DsmcGas<D>::draw_maxwell_velocities(Rng& rng) {
  double mean[D] = {};
  for (auto& v : velocity_)
    for (int a = 0; a < D; ++a) {
      v.u[a] = rng.normal();
      mean[a] += v.u[a];
    }
  for (int a = 0; a < D; ++a) mean[a] /= n_;
  double sum = 0;
  for (auto& v : velocity_)
    for (int a = 0; a < D; ++a) {
      v.u[a] -= mean[a];
      sum += v.u[a] * v.u[a];
    }
  const double factor = std::sqrt(static_cast<double>(n_) * D / sum);
  for (auto& v : velocity_)
    for (int a = 0; a < D; ++a) v.u[a] *= factor;
}

// Every N/4 collisions: Σu² recomputed exactly (the per-collision updates round), the momentum
// drift of rounding removed once it matters (momentum_drift.hpp), the internal units reset when
// the gas has cooled, the temperature floor checked, and B tightened to the current max |u| (a
// cooling gas leaves it loose, which costs rejections, not accuracy).
template <int D>
void DsmcGas<D>::bookkeeping() {
  auto sums = [this](double& sum, double& max_u2) {
    sum = 0;
    max_u2 = 0;
    for (const auto& v : velocity_) {
      double u2 = 0;
      for (int a = 0; a < D; ++a) u2 += v.u[a] * v.u[a];
      sum += u2;
      max_u2 = std::max(max_u2, u2);
    }
  };
  double sum, max_u2;
  sums(sum, max_u2);
  if (remove_momentum_drift<D>(velocity_, sum, [](Velocity& v) { return v.u; })) sums(sum, max_u2);
  const double internal_temperature = sum / (static_cast<double>(n_) * D);
  if (internal_temperature < k_rescale_temperature && internal_temperature > 0) {
    const double factor = 1.0 / std::sqrt(internal_temperature);
    for (auto& v : velocity_)
      for (int a = 0; a < D; ++a) v.u[a] *= factor;
    scale_ *= factor;
    min_sum_u2_ *= factor * factor;
    sums(sum, max_u2);
  }
  sum_u2_ = sum;
  // Physical T = T_internal / s², divided twice: s² overflows once s passes 1e154. At the floor
  // of double precision the run stops, as the MD engine does (the samples would print T = 0).
  if (sum / (static_cast<double>(n_) * D) / scale_ / scale_ < k_temperature_floor)
    stop_reason_ = StopReason::temperature_floor;
  bound_ = std::sqrt(max_u2) * k_bound_margin;
  pair_bound2_ = 4.0 * bound_ * bound_;
  next_bookkeeping_ = collisions_ + std::max<std::uint64_t>(n_ / 4, 1);
  if (collision_limit_ > 0) next_bookkeeping_ = std::min(next_bookkeeping_, collision_limit_);
}

template <int D>
void DsmcGas<D>::update_rate() {
  rate_ = rate_per_bound_ * 2.0 * bound_ / scale_;
}

// The next candidate lies beyond target_ iff −ln(Π u)/Λ > target_ − clock_.
template <int D>
void DsmcGas<D>::set_threshold() {
  threshold_ = std::exp(-(target_ - clock_) * rate_);
}

namespace {

// Uniform in [0, n) without bias (Lemire, "Fast random integer generation in an interval", ACM
// TOMACS 2019): the 64-bit product's low word below 2^32 mod n is redrawn.
inline std::uint32_t uniform_index(std::uint32_t random, std::uint32_t n, Rng& rng) {
  std::uint64_t product = static_cast<std::uint64_t>(random) * n;
  auto low = static_cast<std::uint32_t>(product);
  if (low < n) {
    const std::uint32_t reject_below = (0u - n) % n;
    while (low < reject_below) {
      random = static_cast<std::uint32_t>(rng.next() >> 32);
      product = static_cast<std::uint64_t>(random) * n;
      low = static_cast<std::uint32_t>(product);
    }
  }
  return static_cast<std::uint32_t>(product >> 32);
}

}  // namespace

template <int D>
inline typename DsmcGas<D>::Pair DsmcGas<D>::draw_pair(Rng& rng) {
  const std::uint64_t random = rng.next();
  Pair pair;
  pair.i = uniform_index(static_cast<std::uint32_t>(random >> 32), n_, rng);
  pair.j = uniform_index(static_cast<std::uint32_t>(random), n_ - 1, rng);
  pair.j += pair.j >= pair.i ? 1u : 0u;  // a distinct pair, uniform over the N(N − 1) ordered
  __builtin_prefetch(&velocity_[pair.i]);
  __builtin_prefetch(&velocity_[pair.j]);
  return pair;
}

// The candidate loop. The generator, the product of the waiting-time uniforms (the candidates
// since the last flush waited −ln(Π u_k)/Λ in total) and the look-ahead position are locals, so
// that they stay in registers; the state is stored at every exit. The clock is flushed (one
// logarithm) only where the run's own course asks for it (a raised bound, bookkeeping, a stop
// condition, the product near underflow), never at a stop time: a run sampled at other times
// flushes at the same candidates and computes the same numbers.
template <int D>
typename DsmcGas<D>::Status DsmcGas<D>::advance_to(double t) {
  if (stop_reason_) return Status::stopped;
  if (time_ >= t) return Status::reached;
  target_ = t;
  set_threshold();
  Rng rng = rng_;
  double survival = survival_;
  std::uint64_t candidates = 0;
  unsigned ahead = next_ahead_;
  Status status = Status::reached;
  bool resume = pending_;  // the candidate that passed the last stop time comes first
  for (;;) {
    Pair pair;
    std::uint64_t uniforms;
    if (resume) {
      resume = false;
      pair = pending_pair_;
      uniforms = pending_uniforms_;  // its waiting time is in the product already
    } else {
      pair = ahead_[ahead];
      ahead_[ahead] = draw_pair(rng);
      ahead = (ahead + 1) % k_lookahead;
      ++candidates;
      // One 64-bit draw gives the candidate's two uniforms, 32 bits each: the waiting time's
      // (k + 1/2)/2^32 in (0, 1) and the acceptance's k/2^32 in [0, 1). Their resolution 2^-32
      // shifts an acceptance probability or the exponential's distribution function by at most
      // 2.3e-10, far below anything a run can resolve, and saves a third of the generator calls.
      uniforms = rng.next();
      survival *= (static_cast<double>(uniforms >> 32) + 0.5) * 0x1.0p-32;
    }
    pending_ = survival < threshold_;
    if (pending_) {  // this candidate comes after t: it waits for the next advance_to
      pending_pair_ = pair;
      pending_uniforms_ = uniforms;
      time_ = target_;
      break;
    }
    if (survival < k_underflow) {  // the product nears underflow: flush it into the clock
      clock_ -= std::log(survival) / rate_;
      survival = 1.0;
      set_threshold();
    }
    double g[D], g2 = 0;
    for (int a = 0; a < D; ++a) {
      g[a] = velocity_[pair.i].u[a] - velocity_[pair.j].u[a];
      g2 += g[a] * g[a];
    }
    const double accept = static_cast<double>(uniforms & 0xffffffffu) * 0x1.0p-32;
    if (accept * accept * pair_bound2_ >= g2) continue;  // accepted iff accept·2B < |g|
    const bool bound_raised = collide(pair.i, pair.j, g, g2, rng);
    if (bound_raised || collisions_ == next_bookkeeping_ || sum_u2_ < min_sum_u2_) {
      clock_ -= std::log(survival) / rate_;  // the clock at this collision
      survival = 1.0;
      if (sum_u2_ < min_sum_u2_) {
        stop_reason_ = StopReason::min_temperature;
        status = Status::stopped;
        break;
      }
      if (collisions_ == collision_limit_) {
        stop_reason_ = StopReason::max_collisions;
        status = Status::stopped;
        break;
      }
      if (collisions_ == next_bookkeeping_) bookkeeping();
      if (stop_reason_) {  // the temperature floor (bookkeeping())
        status = Status::stopped;
        break;
      }
      update_rate();
      set_threshold();
    }
  }
  if (status == Status::stopped) time_ = clock_;
  rng_ = rng;
  survival_ = survival;
  candidates_ += candidates;
  next_ahead_ = ahead;
  return status;
}

// Returns whether B had to be raised.
template <int D>
bool DsmcGas<D>::collide(std::uint32_t i, std::uint32_t j, const double* g, double g2, Rng& rng) {
  double* ui = velocity_[i].u;
  double* uj = velocity_[j].u;
  double e[D];
  draw_contact_direction<D>(g, std::sqrt(g2), rng, e);
  double before = 0;
  for (int a = 0; a < D; ++a) before += ui[a] * ui[a] + uj[a] * uj[a];
  if (contacts_on_) accumulate<D>(contacts_, ui, uj, e, sum_u2_ / (static_cast<double>(n_) * D));
  double normal_velocity = 0;
  for (int a = 0; a < D; ++a) normal_velocity += g[a] * e[a];
  rule_.apply<D>(ui, uj, e, normal_velocity, /*elastic=*/false);
  double after_i = 0, after_j = 0;
  for (int a = 0; a < D; ++a) {
    after_i += ui[a] * ui[a];
    after_j += uj[a] * uj[a];
  }
  sum_u2_ += after_i + after_j - before;
  ++collisions_;
  const double fastest = std::max(after_i, after_j);
  if (fastest <= bound_ * bound_) return false;
  bound_ = std::sqrt(fastest) * k_bound_margin;
  pair_bound2_ = 4.0 * bound_ * bound_;
  return true;
}

template <int D>
Sample DsmcGas<D>::sample() {
  double m2 = 0, m4 = 0;
  for (const auto& v : velocity_) {
    double u2 = 0;
    for (int a = 0; a < D; ++a) u2 += v.u[a] * v.u[a];
    m2 += u2;
    m4 += u2 * u2;
  }
  const double n = static_cast<double>(n_);
  Sample s;
  s.t = time_;
  s.temperature = m2 / (n * D) / (scale_ * scale_);
  s.a2 = m2 > 0 ? static_cast<double>(D) / (D + 2) * (m4 / n) / ((m2 / n) * (m2 / n)) - 1.0 : 0.0;
  s.collisions = collisions_;
  s.events = collisions_;
  s.velocity_mode = std::numeric_limits<double>::quiet_NaN();
  s.density_mode = std::numeric_limits<double>::quiet_NaN();
  s.contacts = contacts_;
  contacts_ = {};
  return s;
}

template <int D>
double DsmcGas<D>::temperature() const {
  return sum_u2_ / (static_cast<double>(n_) * D) / (scale_ * scale_);
}

template <int D>
std::vector<double> DsmcGas<D>::velocities() const {
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(n_) * D);
  for (const auto& v : velocity_)
    for (int a = 0; a < D; ++a) out.push_back(v.u[a] / scale_);
  return out;
}

template class DsmcGas<2>;
template class DsmcGas<3>;

namespace {

// Refuses (std::invalid_argument naming t_end and its range) a run estimated to draw more than
// k_max_run_events candidates, as the MD engine refuses one of too many events (run_length.hpp):
// an elastic or nearly elastic gas collides at its initial rate for ever. The candidates per
// collision are the majorant's at T = 1, which follows the temperature down.
template <int D>
void check_run_length(const Parameters& p, const DsmcGas<D>& gas) {
  const double omega = enskog_collision_frequency(D, p.density, 1.0);
  const RunLengthGas estimate{D, omega, p.restitution, 0.0,
                              std::max(p.min_temperature, k_temperature_floor)};
  const double n = static_cast<double>(p.particles);
  const double per_collision = gas.candidate_rate() / (0.5 * n * omega);
  const double limit = p.max_collisions > 0 ? static_cast<double>(p.max_collisions)
                                            : std::numeric_limits<double>::infinity();
  const auto candidates_to = [&](double t) {
    return std::min(estimated_collisions_per_particle(estimate, t) * n / 2.0, limit) *
           per_collision;
  };
  const double expected = candidates_to(p.t_end);
  if (!(expected > k_max_run_events)) return;
  char text[200];
  std::snprintf(text, sizeof text, " would take %s (an estimated %.2g per collision)",
                estimated_count(expected, "candidates").c_str(), per_collision);
  throw std::invalid_argument(
      "t_end: " + message_number(p.t_end) + text + "; allowed range (0, " +
      message_number(longest_time_within(candidates_to, p.t_end, k_max_run_events)) +
      "] here: a shorter run, or a lower restitution");
}

template <int D>
RunResult run_dsmc_d(const Parameters& p, const ProgressCallback& progress) {
  const auto start = std::chrono::steady_clock::now();
  DsmcGas<D> gas(p, contact_value_g2(p.dimension, p.density));
  check_run_length(p, gas);
  RunResult result;
  result.parameters = p;
  result.version = k_version;
  result.stop_reason = StopReason::t_end;
  // Progress (and the Python module's Ctrl-C watch, which runs in it) about every
  // k_progress_collisions collisions, not only at the sample times, which a cooling run spaces
  // ever wider: the gas goes on in steps whose length follows the collisions of the step before,
  // at most doubling. Where it stops does not change the realisation (DsmcGas).
  constexpr double k_progress_collisions = 1 << 20;
  double step = k_progress_collisions / gas.candidate_rate();  // at most that many collisions
  for (double t : sample_times(p)) {
    auto status = DsmcGas<D>::Status::reached;
    for (;;) {
      const double from = gas.time();
      const double to = std::min(t, from + step);
      const std::uint64_t before = gas.collisions();
      status = gas.advance_to(to);
      if (status == DsmcGas<D>::Status::stopped || to >= t) break;
      const auto done = static_cast<double>(gas.collisions() - before);
      step = (to - from) * std::min(2.0, k_progress_collisions / std::max(done, 1.0));
      if (progress) progress(to / p.t_end);
    }
    if (status == DsmcGas<D>::Status::stopped) {
      result.stop_reason = *gas.stop_reason();
      result.samples.push_back(gas.sample());  // the state where the run stopped
      break;
    }
    Sample s = gas.sample();
    s.t = t;
    result.samples.push_back(s);
    if (progress) progress(t / p.t_end);
  }
  result.collisions = gas.collisions();
  result.events = gas.collisions();
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace

RunResult run_dsmc(const Parameters& p, const ProgressCallback& progress) {
  validate(p);
  validate_dsmc(p);
  return p.dimension == 2 ? run_dsmc_d<2>(p, progress) : run_dsmc_d<3>(p, progress);
}

}  // namespace molchaos::sim

// The event-driven engine: initial state, event loop, cell lists, event calendar, observables.
// See engine.hpp for the design; the event loop is Engine<D, Observer>::run_events.
#include "molchaos/sim/engine.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "molchaos/sim/cell_grid.hpp"
#include "molchaos/sim/initial_state.hpp"
#include "molchaos/sim/run.hpp"

namespace molchaos::sim {
namespace {

constexpr double k_inf = std::numeric_limits<double>::infinity();
// Internal temperature below which velocities are rescaled back to T_internal = 1.
constexpr double k_rescale_temperature = 1.0 / 16.0;
// Internal time after which the clock is rebased to 0 (keeps time differences exact).
constexpr double k_rebase_time = 1000.0;
// Collapse: k_collapse_collisions (stop_reason.hpp) consecutive collisions, each within
// k_micro_fraction mean free times of a previous collision of one of its particles.
constexpr double k_micro_fraction = 1e-10;
// Dead-lock guard: k_stall_events (stop_reason.hpp) consecutive events at one and the same time
// without any collision can only be a numerical dead-lock (a cell crossing or a rejected contact
// re-predicted at now): the run stops with a reason instead of looping for ever.
// Mean number of particles per cell aimed at when choosing the cell width (cells >= sigma): in
// dilute disks wider cells mean fewer cell crossings per collision but more pairs per prediction
// (instruction counts at n = 0.05: best near 0.5 per cell); in d = 3 (memory-bound at N = 1e5)
// 0.4 per cell beat 0.2, 0.3 and 0.5 at packing 0.1 (fewer crossings, fewer cells to touch).
template <int D>
constexpr double k_cell_occupancy = D == 2 ? 0.5 : 0.4;
constexpr double k_overlap_tolerance = 1e-10;
// Software prefetches (of the next event's and of the candidates' records) only pay when the
// engine's data outgrow a core's L2 cache (2 MB here); below, they are extra instructions
// (8 % of them for the paper's case, N = 5000, 1 MB).
constexpr std::size_t k_prefetch_min_bytes = std::size_t{2} << 20;
// Cells with at most this many slots are gathered by fixed-size copies of 8 or 16 slots (see
// gather()); 16 covers the neighbour-list cells of dense spheres (~2.6 members, 15 slots).
constexpr int k_gather_block = 16;
// Dense spheres use neighbour lists instead of cell crossings (Smallenburg's scheme): a particle
// lists every particle whose shell centre lies within sigma + 2 * shell of its own, and gets a
// bookkeeping event when it leaves its shell of radius `shell` around its centre.
constexpr double k_neighbour_list_packing = 0.25;
// Measured at packing 0.4, N = 1e5: 0.25 .. 0.35 equally fast (5% above 0.2, 0.15 and 0.4
// slower); the smallest of them keeps the lists shortest.
constexpr double k_shell = 0.25;

// std::min(a, b) for doubles without a branch (GCC branches on it; the order is random here).
[[gnu::always_inline]] inline double earlier_of(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_min_sd(_mm_set_sd(b), _mm_set_sd(a)));  // b < a ? b : a
#else
  return std::min(a, b);
#endif
}

}  // namespace

// ---------------------------------------------------------------------------------------------
// Construction and initial state.

template <int D, class Observer>
Engine<D, Observer>::Engine(const Parameters& p)
    : model_(CollisionModel::from(p)), shuffle_rng_(p.seed ^ 0x243f6a8885a308d3ULL) {
  validate(p);
  if (p.dimension != D) throw std::invalid_argument("dimension: engine instantiated for another d");
  n_ = static_cast<std::int32_t>(p.particles);
  box_ = box_side(p);
  half_box_ = 0.5 * box_;
  const double packing_fraction =
      (D == 2 ? std::numbers::pi / 4.0 : std::numbers::pi / 6.0) * p.density;
  neighbour_lists_ = D == 3 && packing_fraction >= k_neighbour_list_packing &&
                     box_ >= 3.0 * (1.0 + 2.0 * k_shell);  // 3 cells of the list cutoff
  shell_ = neighbour_lists_ ? k_shell : 0.0;
  const double width_target =
      neighbour_lists_
          ? 1.0 + 2.0 * shell_
          : std::max(1.0, std::pow(k_cell_occupancy<D> / p.density, 1.0 / static_cast<double>(D)));
  cells_per_side_ = static_cast<int>(std::floor(box_ / width_target));
  if (!neighbour_lists_)
    cells_per_side_ = std::max(cells_per_side_, std::min(4, static_cast<int>(std::floor(box_))));
  // Cells: two particles in neighbouring cells are less than two cell widths apart along each
  // axis, which must stay below half the box (4 cells or more), or the minimum image may flip
  // between them while they approach and the collision would be missed. Neighbour lists: the
  // list cutoff 1 + 2 shell is below half the box (box >= 3 cutoffs).
  if (cells_per_side_ < (neighbour_lists_ ? 3 : 4))
    throw std::invalid_argument("particles: box side " + std::to_string(box_) +
                                " is below 4 sigma; use more particles or a higher density");
  cell_width_ = box_ / cells_per_side_;
  wall_.resize(static_cast<std::size_t>(cells_per_side_) + 1);
  for (int k = 0; k < cells_per_side_; ++k) wall_[k] = k * cell_width_;
  wall_[cells_per_side_] = box_;
  for (int a = 0, stride = 1; a < D; ++a, stride *= cells_per_side_) stride_[a] = stride;
  {
    int middle[D];
    for (int a = 0; a < D; ++a) middle[a] = 1;
    int around[stencil_size<D>()];
    neighbour_cells<D>(middle, cells_per_side_, around);
    for (int s = 0; s < stencil_size<D>(); ++s)
      stencil_offset_[s] = around[s] - cell_index<D>(middle, cells_per_side_);
    for (int axis = 0; axis < D; ++axis)
      for (int up = 0; up < 2; ++up) {
        int slab[stencil_size<D>()];
        slab_cells<D>(middle, cells_per_side_, axis, up ? 1 : -1, slab);
        for (int s = 0; s < slab_size<D>(); ++s)
          slab_offset_[2 * axis + up][s] = slab[s] - cell_index<D>(middle, cells_per_side_);
      }
  }

  collision_limit_ = p.max_collisions;
  min_temperature_ = p.min_temperature;
  micro_interval_ = k_micro_fraction / enskog_collision_frequency(D, p.density, 1.0);

  const std::size_t n = static_cast<std::size_t>(n_);
  part_.assign(n, Particle{});
  cell_xyz_.resize(n);
  id_.resize(n);
  for (std::int32_t i = 0; i < n_; ++i) id_[i] = i;
  ev_.assign(n, EventData{});
  last_collision_time_.assign(n, -k_inf);
  slot_.assign(n, -1);
  std::size_t cells = 1;
  for (int a = 0; a < D; ++a) cells *= static_cast<std::size_t>(cells_per_side_);
  cells_ = cells;
  // Initial slots per cell: room for well above the mean occupancy (blocks of 8, 16, ... ints
  // with the count); grows on overflow.
  const double mean = static_cast<double>(n_) / static_cast<double>(cells);
  capacity_ = 8 * static_cast<int>(std::ceil((3 * mean + 5) / 8)) - 1;
  allocate_cells();

  Rng rng(p.seed);
  const std::vector<double> positions = place_particles<D>(n_, box_, rng);
  const std::vector<double> velocities = maxwell_velocities<D>(n_, rng);
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) {
      part_[i].r[a] = positions[D * i + a];
      part_[i].v[a] = velocities[D * i + a];
    }
  sum_u2_ = sum_velocity_squared();
  build_cells();
  rebuild_events();
}

template <int D, class Observer>
void Engine<D, Observer>::set_state(const std::vector<double>& positions,
                          const std::vector<double>& velocities) {
  const std::size_t size = static_cast<std::size_t>(n_) * D;
  if (positions.size() != size || velocities.size() != size)
    throw std::invalid_argument("set_state: wrong array sizes");
  for (std::int32_t i = 0; i < n_; ++i) {
    for (int a = 0; a < D; ++a) {
      part_[i].r[a] = positions[D * i + a];
      part_[i].v[a] = velocities[D * i + a];
    }
    part_[i].t = 0;
    part_[i].counter = 0;
    id_[i] = i;
  }
  sum_u2_ = sum_velocity_squared();
  clock_ = InternalClock{};
  std::fill(last_collision_time_.begin(), last_collision_time_.end(), -k_inf);
  collisions_ = events_ = 0;
  micro_run_ = 0;
  stalled_events_ = 0;
  stop_ = false;
  build_cells();
  rebuild_events();
}

template <int D, class Observer>
void Engine<D, Observer>::relax(double collisions_per_particle) {
  const std::uint64_t limit = collision_limit_;
  const double t_min = min_temperature_;
  min_temperature_ = 0;
  const auto target = static_cast<std::uint64_t>(
      std::ceil(collisions_per_particle * static_cast<double>(n_) / 2.0));
  if (target > 0) {
    collision_limit_ = collisions_ + target;
    for (;;) {
      const Outcome outcome =
          dispatch(k_inf, std::numeric_limits<std::uint64_t>::max(), CollisionModel::elastic());
      if (outcome == Outcome::resync) {
        resync();
        continue;
      }
      if (outcome != Outcome::paused) break;
    }
  }
  collision_limit_ = limit;
  min_temperature_ = t_min;
  stop_ = false;

  // Back to T = 1 exactly, zero momentum, t = 0.
  for (std::int32_t i = 0; i < n_; ++i) advance_particle(i);
  double mean[D] = {};
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) mean[a] += part_[i].v[a];
  double sum = 0;
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) {
      part_[i].v[a] -= mean[a] / n_;
      sum += part_[i].v[a] * part_[i].v[a];
    }
  scale_velocities(std::sqrt(static_cast<double>(n_) * D / sum));
  clock_ = InternalClock{};
  for (auto& particle : part_) particle.t = 0;
  std::fill(last_collision_time_.begin(), last_collision_time_.end(), -k_inf);
  collisions_ = events_ = 0;
  micro_run_ = 0;
  stalled_events_ = 0;
  observer_ = Observer{};
  rebuild_events();
}

// ---------------------------------------------------------------------------------------------
// The event loop.

template <int D, class Observer>
template <class Shuffle>
auto Engine<D, Observer>::run_events(double tau_stop, std::uint64_t event_limit, const CollisionModel& model,
                           const Shuffle& shuffle) -> Outcome {
  const double rescale_below = k_rescale_temperature * n_ * D;  // in units of sum u^2
  for (;;) {
    const auto [t, i] = calendar_.top();  // the earliest pending event
    if (!(t < tau_stop)) return Outcome::reached;
    // Likely the next event's particle: its records load while this event is processed.
    if (const std::int32_t g = prefetch_ ? calendar_.guess_next(i) : -1; g >= 0) {
      __builtin_prefetch(&part_[g]);
      __builtin_prefetch(&ev_[g]);
      __builtin_prefetch(&cell_xyz_[g]);
      calendar_.prefetch(g);
    }
    if (events_ >= event_limit) return Outcome::paused;
    if (t != clock_.now)
      stalled_events_ = 0;
    else if (++stalled_events_ >= k_stall_events) {
      request_stop(StopReason::stalled);
      return Outcome::stopped;
    }
    clock_.now = t;
    ++events_;
    if (ev_[i].cross_time < ev_[i].coll_time) {
      if (neighbour_lists_)
        rebuild_neighbours(i);  // left its shell: new centre, new neighbour list
      else
        cross_cell(i);  // moves i to its next cell, looks at the cells that came into range
    } else {
      const std::int32_t j = ev_[i].partner;
      if (part_[j].counter != ev_[i].partner_counter) {  // partner's velocity changed since: stale
        predict(i);
        continue;
      }
      const std::uint64_t before = collisions_;
      collide(i, j, model, shuffle);  // rule, shuffle, re-predict every particle whose velocity changed
      if (collisions_ != before) stalled_events_ = 0;
      if (stop_) return Outcome::stopped;
      if (sum_u2_ < rescale_below || clock_.now > k_rebase_time) return Outcome::resync;
    }
    if (debug_check_every_ != 0 && events_ % debug_check_every_ == 0) check_overlaps();
  }
}

template <int D, class Observer>
auto Engine<D, Observer>::dispatch(double tau_stop, std::uint64_t event_limit, const CollisionModel& model)
    -> Outcome {
  switch (model.shuffle) {
    case Randomization::paper:
      return run_events(tau_stop, event_limit, model, PaperShuffle{});
    case Randomization::flux:
      return run_events(tau_stop, event_limit, model, FluxShuffle{});
    case Randomization::none:
      break;
  }
  return run_events(tau_stop, event_limit, model, NoShuffle{});
}

template <int D, class Observer>
auto Engine<D, Observer>::advance_to(double t, std::uint64_t max_events) -> Status {
  if (stop_) return Status::stopped;
  const std::uint64_t limit =
      max_events == std::numeric_limits<std::uint64_t>::max() ? max_events : events_ + max_events;
  for (;;) {
    const double tau_stop = clock_.internal_time(t);
    switch (dispatch(tau_stop, limit, model_)) {
      case Outcome::reached:
        clock_.now = std::max(clock_.now, tau_stop);
        return Status::reached;
      case Outcome::resync:
        resync();
        continue;
      case Outcome::paused:
        return Status::paused;
      case Outcome::stopped:
        return Status::stopped;
    }
  }
}

template <int D, class Observer>
auto Engine<D, Observer>::step() -> Status {
  if (stop_) return Status::stopped;
  const Outcome outcome = dispatch(k_inf, events_ + 1, model_);
  if (outcome == Outcome::resync) resync();
  return outcome == Outcome::stopped ? Status::stopped : Status::paused;
}

template <int D, class Observer>
template <class Shuffle>
void Engine<D, Observer>::collide(std::int32_t i, std::int32_t j, const CollisionModel& model,
                        const Shuffle& shuffle) {
  advance_particle(i);
  advance_particle(j);
  double* vi = part_[i].v;
  double* vj = part_[j].v;
  // b = dr.dv with exactly the arithmetic of pair_time() (j is at clock_.now here, so its position
  // term is exact): the approach test below and the prediction that scheduled this event then
  // agree bit for bit. Were gn computed as dv.e instead, rounding could make a pair with a
  // vanishing normal velocity "approaching" for pair_time() (event at clock_.now) and "separating" here
  // (nothing done), an endless loop at a frozen time, as happened near inelastic collapse.
  double e[D], dist2 = 0, b = 0;
  for (int a = 0; a < D; ++a) {
    double d = part_[i].r[a] - part_[j].r[a];
    if (d > half_box_) d -= box_;
    if (d < -half_box_) d += box_;
    e[a] = d;
    b += d * (vi[a] - vj[a]);
    dist2 += d * d;
  }
  if (!(b < 0)) {  // not approaching after all: no collision, and pair_time() agrees
    predict(i);
    predict(j);
    return;
  }
  const double inv_dist = 1.0 / std::sqrt(dist2);
  for (int a = 0; a < D; ++a) e[a] *= inv_dist;
  const double gn = b * inv_dist;  // (v_i - v_j).e, < 0, same sign as b

  // TC model (Luding & McNamara): elastic if either particle collided less than tc ago.
  const double since = clock_.now - std::max(last_collision_time_[i], last_collision_time_[j]);
  const bool elastic = model.tc.apply(clock_.physical_interval(since));
  // Inelastic collapse: an unbroken run of collisions ever closer in time.
  micro_run_ = since < micro_interval_ ? micro_run_ + 1 : 0;

  const CollisionView<D> contact{
      i, j, e, vi, vj, gn, sum_u2_ / (static_cast<double>(n_) * D), clock_.theta};
  observer_.before(contact);
  const double energy_lost = model.rule.template apply<D>(vi, vj, e, gn, elastic);
  sum_u2_ -= 2.0 * energy_lost;  // sum u^2 is twice the kinetic energy
  observer_.after(contact, CollisionOutcome{energy_lost, elastic});
  ++part_[i].counter;
  ++part_[j].counter;
  last_collision_time_[i] = last_collision_time_[j] = clock_.now;
  ++collisions_;

  if constexpr (Shuffle::active) {
    const double temperature = sum_u2_ / (static_cast<double>(n_) * D);
    const auto [k, l] = apply_shuffle<D>(
        shuffle, [this](std::int32_t m) { return part_[m].v; }, n_, i, j, e, temperature,
        shuffle_rng_, [this](std::int32_t donor_k, std::int32_t donor_l) {
          advance_particle(donor_k);
          advance_particle(donor_l);
        });
    ++part_[k].counter;
    ++part_[l].counter;
    predict(k);
    predict(l);
  }
  predict(i);
  predict(j);

  if (micro_run_ >= k_collapse_collisions) request_stop(StopReason::collapse);
  if (collision_limit_ != 0 && collisions_ >= collision_limit_)
    request_stop(StopReason::max_collisions);
  if (min_temperature_ > 0 && sum_u2_ * (1.0 / (clock_.theta * clock_.theta)) < min_temperature_ * n_ * D)
    request_stop(StopReason::min_temperature);
}

template <int D, class Observer>
void Engine<D, Observer>::request_stop(StopReason reason) {
  if (stop_) return;
  stop_ = true;
  stop_reason_ = reason;
}

// ---------------------------------------------------------------------------------------------
// Prediction.

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::advance_particle(std::int32_t i) {
  const double dt = clock_.now - part_[i].t;
  if (dt != 0) {
    for (int a = 0; a < D; ++a) part_[i].r[a] += part_[i].v[a] * dt;
    part_[i].t = clock_.now;
  }
}

template <int D, class Observer>
void Engine<D, Observer>::position_now(std::int32_t i, double* r) const {
  const double dt = clock_.now - part_[i].t;
  for (int a = 0; a < D; ++a) r[a] = part_[i].r[a] + part_[i].v[a] * dt;
}

// Time of contact of i (at clock_.now) and j (at its local time), or +inf: the smaller root of
// |dr + dv t|^2 = 1 in the cancellation-free form t = c / (-b + sqrt(b^2 - v^2 c)). The reference
// arithmetic; with SSE2 the engine uses pair_times() below, which does the same operations.
template <int D, class Observer>
[[gnu::always_inline]] inline double Engine<D, Observer>::pair_time(std::int32_t i, std::int32_t j) const {
  const Particle& pi = part_[i];
  const Particle& pj = part_[j];
  const double dtj = clock_.now - pj.t;
  double b = 0, dr2 = 0, dv2 = 0;
  for (int a = 0; a < D; ++a) {
    double d = pi.r[a] - (pj.r[a] + pj.v[a] * dtj);
    if (d > half_box_) d -= box_;
    if (d < -half_box_) d += box_;
    const double dv = pi.v[a] - pj.v[a];
    b += d * dv;
    dr2 += d * d;
    dv2 += dv * dv;
  }
  if (b >= 0) return k_inf;
  const double c = dr2 - 1.0;
  const double disc = b * b - dv2 * c;
  if (disc < 0) return k_inf;
  const double dt = c / (-b + std::sqrt(disc));
  return dt > 0 ? clock_.now + dt : clock_.now;  // c < 0: overlapping by rounding and approaching: now
}

#if defined(__SSE2__)
// pair_time() for two partners at once: (time with j1, time with j2). Each half of the registers
// does pair_time()'s operations in the same order; the components of the two partners are
// regrouped (x1 x2), (y1 y2), (z1 z2) so that the sums and the root are shared. Branch-free (the
// approach test b < 0 and the discriminant test are coin flips for the branch predictor): the
// root is computed for every pair and replaced by +inf unless b < 0 and disc >= 0; the periodic
// wrap adds or subtracts a masked box length instead of branching, which can only change the sign
// of a zero component. collide() recomputes b with the scalar loop; the two can then differ at
// most in the sign of a zero b, which both treat as "not approaching".
template <int D, class Observer>
[[gnu::always_inline]] inline __m128d Engine<D, Observer>::pair_times(std::int32_t i, std::int32_t j1,
                                                            std::int32_t j2) const {
  const Particle& pi = part_[i];
  const Particle& p1 = part_[j1];
  const Particle& p2 = part_[j2];
  const __m128d zero = _mm_setzero_pd();
  const __m128d now = _mm_set1_pd(clock_.now);
  const __m128d half = _mm_set1_pd(half_box_), minus_half = _mm_set1_pd(-half_box_);
  const __m128d box = _mm_set1_pd(box_);
  const __m128d dtj = _mm_sub_pd(now, _mm_loadh_pd(_mm_load_sd(&p1.t), &p2.t));
  __m128d b = zero, dr2 = zero, dv2 = zero;
  for (int a = 0; a < D; ++a) {
    const __m128d rj = _mm_loadh_pd(_mm_load_sd(&p1.r[a]), &p2.r[a]);
    const __m128d vj = _mm_loadh_pd(_mm_load_sd(&p1.v[a]), &p2.v[a]);
    __m128d d = _mm_sub_pd(_mm_set1_pd(pi.r[a]), _mm_add_pd(rj, _mm_mul_pd(vj, dtj)));
    d = _mm_sub_pd(d, _mm_and_pd(_mm_cmpgt_pd(d, half), box));
    d = _mm_add_pd(d, _mm_and_pd(_mm_cmplt_pd(d, minus_half), box));
    const __m128d dv = _mm_sub_pd(_mm_set1_pd(pi.v[a]), vj);
    if (a == 0) {  // the scalar sums start with the x terms
      b = _mm_mul_pd(d, dv);
      dr2 = _mm_mul_pd(d, d);
      dv2 = _mm_mul_pd(dv, dv);
    } else {
      b = _mm_add_pd(b, _mm_mul_pd(d, dv));
      dr2 = _mm_add_pd(dr2, _mm_mul_pd(d, d));
      dv2 = _mm_add_pd(dv2, _mm_mul_pd(dv, dv));
    }
  }
  const __m128d c = _mm_sub_pd(dr2, _mm_set1_pd(1.0));
  const __m128d disc = _mm_sub_pd(_mm_mul_pd(b, b), _mm_mul_pd(dv2, c));
  const __m128d root = _mm_sqrt_pd(_mm_max_pd(disc, zero));
  const __m128d dt = _mm_div_pd(c, _mm_sub_pd(root, b));
  const __m128d t = _mm_add_pd(now, _mm_max_pd(dt, zero));
  const __m128d valid = _mm_and_pd(_mm_cmplt_pd(b, zero), _mm_cmpge_pd(disc, zero));
  return _mm_or_pd(_mm_and_pd(valid, t), _mm_andnot_pd(valid, _mm_set1_pd(k_inf)));
}
#endif

// The members of the Count given cells, gathered into candidates_: each cell's slot block is
// copied whole (fixed-size copies, unrolled: no branch) and the write position advanced by the
// member count. Returns the number of candidates.
template <int D, class Observer>
template <int Count>
[[gnu::always_inline]] inline std::int32_t Engine<D, Observer>::gather(const int* cells) {
  std::int32_t* out = candidates_.data();
  const std::int32_t* blocks = slots_.data() + slots_origin_;
  const std::size_t stride = static_cast<std::size_t>(capacity_) + 1;
  std::int32_t k = 0;
  // Fixed-size copies of whole blocks, unrolled (slots_ and candidates_ are padded for them): no
  // branch on the member counts, which are coin flips for the branch predictor.
  auto copy_blocks = [&]<int Block>() {
#pragma GCC unroll 27
    for (int s = 0; s < Count; ++s) {
      const std::int32_t* block = blocks + static_cast<std::size_t>(cells[s]) * stride;
      std::memcpy(out + k, block + 1, Block * sizeof(std::int32_t));
      k += block[0];
    }
  };
  if (capacity_ <= 8) {
    copy_blocks.template operator()<8>();
  } else if (capacity_ <= k_gather_block) {
    copy_blocks.template operator()<k_gather_block>();
  } else {  // crowded cells (clusters): copy the members only
    for (int s = 0; s < Count; ++s) {
      const std::int32_t* block = blocks + static_cast<std::size_t>(cells[s]) * stride;
      const std::int32_t members = block[0];
      for (int m = 0; m < members; ++m) out[k + m] = block[1 + m];
      k += members;
    }
  }
  return k;
}

// The earliest collision of i (at clock_.now) with the listed candidates after `best`: updates best and
// partner. Branch-free selection; candidates in list order, the first of equal times wins.
// list[count] must be writable: an odd list is padded there with i itself (its pair time with
// itself is +inf), so that one loop of pairs does all, without a remainder loop whose trip count
// the branch predictor would have to guess.
template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::earliest(std::int32_t i, std::int32_t* list,
                                                       std::int32_t count, double& best,
                                                       std::int32_t& partner) const {
  double b = best;
  std::int32_t p = partner;
  if (prefetch_)
    for (std::int32_t k = 0; k < count; ++k) __builtin_prefetch(&part_[list[k]]);
#if defined(__SSE2__)
  list[count] = i;
  for (std::int32_t k = 0; k < count; k += 2) {  // two partners per pass, one in each half
    const std::int32_t j1 = list[k], j2 = list[k + 1];
    double t[2];
    _mm_storeu_pd(t, pair_times(i, j1, j2));
    p = t[0] < b ? j1 : p;
    b = t[0] < b ? t[0] : b;
    p = t[1] < b ? j2 : p;
    b = t[1] < b ? t[1] : b;
  }
#else
  for (std::int32_t k = 0; k < count; ++k) {
    const std::int32_t j = list[k];
    const double t = pair_time(i, j);
    p = t < b ? j : p;
    b = t < b ? t : b;
  }
#endif
  best = b;
  partner = p;
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::crossing(std::int32_t i) {
  const int* x = cell_xyz_[i].data();
  const Particle& p = part_[i];
  double best = k_inf;
  int axis = 0;
  for (int a = 0; a < D; ++a) {  // branch-free selects: the direction is random
    const double u = p.v[a];
    // wall_[k] = k * cell_width_ (k < cells_per_side_), wall_[cells_per_side_] = box_.
    double dt = (wall_[x[a] + (u > 0)] - p.r[a]) / u;
    dt = u == 0 ? k_inf : dt;  // never crosses along a
    const int earlier = dt < best;  // the first axis wins a tie
    axis += earlier * (a - axis);
    best = earlier_of(best, dt);
  }
  ev_[i].cross_time = clock_.now + std::max(best, 0.0);
  ev_[i].cross_axis = axis;
}

// True when the cell with coordinates x is not on the box boundary: its stencil needs no
// periodic wrap and is given by fixed index offsets.
template <int D, class Observer>
[[gnu::always_inline]] inline bool Engine<D, Observer>::interior_cell(const int* x) const {
  bool interior = true;
  for (int a = 0; a < D; ++a)
    interior = interior && static_cast<unsigned>(x[a] - 1) < static_cast<unsigned>(cells_per_side_ - 2);
  return interior;
}

// The 3^D cells around i's cell (i's cell included).
template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::stencil_of(std::int32_t i, int* stencil) const {
  const int* x = cell_xyz_[i].data();
  if (interior_cell(x)) {
    for (int s = 0; s < stencil_size<D>(); ++s) stencil[s] = part_[i].cell + stencil_offset_[s];
  } else {
    neighbour_cells<D>(x, cells_per_side_, stencil);
  }
}

template <int D, class Observer>
void Engine<D, Observer>::predict(std::int32_t i) {
  advance_particle(i);
  double best = k_inf;
  std::int32_t partner = -1;
  if (neighbour_lists_) {
    earliest(i, lists_.slots(i), lists_.count(i), best, partner);
  } else {
    int stencil[stencil_size<D>()];
    stencil_of(i, stencil);
    // i itself is among the candidates: its pair time is +inf (b = 0).
    const std::int32_t count = gather<stencil_size<D>()>(stencil);
    earliest(i, candidates_.data(), count, best, partner);
  }
  ev_[i].coll_time = best;
  ev_[i].partner = partner;
  // Without a partner (-1) the counter is never read: particle 0's is taken (no branch).
  ev_[i].partner_counter = part_[std::max(partner, 0)].counter;
  if (neighbour_lists_)
    shell_exit(i);
  else
    crossing(i);
  calendar_.update(i, earlier_of(best, ev_[i].cross_time));
}

// Time at which i (at clock_.now) leaves the sphere of radius shell_ around its list centre.
template <int D, class Observer>
void Engine<D, Observer>::shell_exit(std::int32_t i) {
  double b = 0, c = -shell_ * shell_, a = 0;
  for (int k = 0; k < D; ++k) {
    const double d = part_[i].r[k] - center_[D * i + k];
    const double v = part_[i].v[k];
    a += v * v;
    b += d * v;
    c += d * d;
  }
  if (!(a > 0)) {
    ev_[i].cross_time = k_inf;
    return;
  }
  const double dt = (-b + std::sqrt(std::max(b * b - a * c, 0.0))) / a;
  ev_[i].cross_time = clock_.now + std::max(dt, 0.0);
}

// Adds every particle of the neighbouring cells whose centre lies within the list cutoff of i's
// centre to i's list, and i to theirs (only j > i when `only_higher`, for the initial build).
template <int D, class Observer>
void Engine<D, Observer>::collect_neighbours(std::int32_t i, bool only_higher) {
  const double cutoff = 1.0 + 2.0 * shell_ + 1e-9;  // slack for rounding at the shell boundary
  const double cutoff2 = cutoff * cutoff;
  int stencil[stencil_size<D>()];
  stencil_of(i, stencil);
  const std::int32_t count = gather<stencil_size<D>()>(stencil);
  std::int32_t* cand = candidates_.data();
  for (std::int32_t k = 0; k < count; ++k) __builtin_prefetch(&center_[D * cand[k]]);
  // Branch-free filter (about one candidate in six is a neighbour): the neighbours are compacted
  // to the front of the candidates, in candidate order.
  const double* ci = &center_[D * i];
  std::int32_t found = 0;
  for (std::int32_t k = 0; k < count; ++k) {
    const std::int32_t j = cand[k];
    double d2 = 0;
    for (int a = 0; a < D; ++a) {
      double d = ci[a] - center_[D * j + a];
      d -= d > half_box_ ? box_ : 0.0;
      d += d < -half_box_ ? box_ : 0.0;
      d2 += d * d;
    }
    cand[found] = j;
    found += static_cast<int>((d2 < cutoff2) & (j != i) & (!only_higher | (j > i)));
  }
  for (std::int32_t k = 0; k < found; ++k) lists_.prefetch(cand[k]);
  for (std::int32_t k = 0; k < found; ++k) {
    lists_.add(i, cand[k]);
    lists_.add(cand[k], i);
  }
}

template <int D, class Observer>
void Engine<D, Observer>::rebuild_neighbours(std::int32_t i) {
  advance_particle(i);
  for (int a = 0; a < D; ++a) {
    double& x = part_[i].r[a];
    if (x < 0) x += box_;
    if (x >= box_) x -= box_;
    center_[D * i + a] = x;
  }
  const auto old = lists_.neighbours(i);
  // Their lists, where i is struck out.
  for (const std::int32_t k : old) lists_.prefetch(k);
  for (const std::int32_t k : old) lists_.remove(k, i);
  lists_.clear(i);
  cell_remove(i);
  cell_insert(i, cell_of_position(part_[i].r));
  collect_neighbours(i, false);
  predict(i);
}

template <int D, class Observer>
void Engine<D, Observer>::build_neighbour_lists() {
  center_.resize(static_cast<std::size_t>(n_) * D);
  int capacity = 0;  // 0: keep the capacity the lists grew to
  if (lists_.capacity() == 0) {
    const double cutoff = 1.0 + 2.0 * shell_;
    const double expected = 4.0 / 3.0 * std::numbers::pi * cutoff * cutoff * cutoff *
                            static_cast<double>(n_) / std::pow(box_, 3);
    capacity = static_cast<int>(std::ceil(2 * expected + 8));
  }
  lists_.reset(n_, capacity);
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) center_[D * i + a] = part_[i].r[a];
  for (std::int32_t i = 0; i < n_; ++i) collect_neighbours(i, true);
}

// After a cell crossing only the cells that came into range can hold new partners: pairs with
// the other cells were predicted before, by i or by the partner (whichever changed last).
// A cell crossing: i moves to its next cell (exactly onto the wall), and only the cells that came
// into range can hold new partners: pairs with the other cells were predicted before, by i or by
// the partner (whichever changed last). One function for the whole event (the hot path of dilute
// systems: most events are crossings).
template <int D, class Observer>
void Engine<D, Observer>::cross_cell(std::int32_t i) {
  advance_particle(i);
  Particle& p = part_[i];
  const int axis = ev_[i].cross_axis;
  const bool up = p.v[axis] > 0;
  int* x = cell_xyz_[i].data();
  const int old_cell = p.cell;
  // The wall crossed: the old cell's upper wall (up) or lower wall; the wrap is the rare case.
  const int from = x[axis];
  const int sign = 2 * static_cast<int>(up) - 1;
  int to = from + sign;
  p.r[axis] = wall_[from + static_cast<int>(up)];
  int step = sign * stride_[axis];  // change of the cell index
  if (static_cast<unsigned>(to) >= static_cast<unsigned>(cells_per_side_)) [[unlikely]] {
    to = up ? 0 : cells_per_side_ - 1;
    p.r[axis] = up ? 0.0 : box_;
    step = (up ? -1 : 1) * (cells_per_side_ - 1) * stride_[axis];
  }
  x[axis] = to;  // x is i's cell_xyz_ entry: now the new cell's coordinates
  const int c = old_cell + step;
  cell_remove(i);
  file_in_cell(i, c);

  int slab[slab_size<D>()];
  if (interior_cell(x)) {  // no periodic wrap: fixed offsets
    const int* offset = slab_offset_[2 * axis + up].data();
    for (int s = 0; s < slab_size<D>(); ++s) slab[s] = c + offset[s];
  } else {
    slab_cells<D>(x, cells_per_side_, axis, up ? 1 : -1, slab);
  }
  double best = ev_[i].coll_time;
  std::int32_t partner = -1;
  const std::int32_t count = gather<slab_size<D>()>(slab);
  earliest(i, candidates_.data(), count, best, partner);
  // best is the old collision time unless a new partner was found (selects, no branch).
  ev_[i].coll_time = best;
  // Masks instead of selects, which the compiler turned into (mispredicted) branches.
  EventData& e = ev_[i];
  const std::uint32_t keep = static_cast<std::uint32_t>(partner >> 31);  // ones: none found
  const std::uint32_t counter = part_[std::max(partner, 0)].counter;
  e.partner = static_cast<std::int32_t>((static_cast<std::uint32_t>(partner) & ~keep) |
                                        (static_cast<std::uint32_t>(e.partner) & keep));
  e.partner_counter = (counter & ~keep) | (e.partner_counter & keep);
  crossing(i);
  calendar_.update(i, earlier_of(best, ev_[i].cross_time));
}

// ---------------------------------------------------------------------------------------------
// Units, cells, calendar.

template <int D, class Observer>
void Engine<D, Observer>::resync() {
  for (std::int32_t i = 0; i < n_; ++i) advance_particle(i);
  sum_u2_ = sum_velocity_squared();
  const double temperature = sum_u2_ / (static_cast<double>(n_) * D);
  double factor = 1.0;
  if (temperature < k_rescale_temperature && temperature > 0) {
    factor = 1.0 / std::sqrt(temperature);
    scale_velocities(factor);
  }
  for (auto& t : last_collision_time_) t = clock_.restarted(t, factor);
  for (auto& particle : part_) particle.t = 0;
  clock_.restart(factor);
  rebuild_events();
}

// Renumbers the particles in cell order so that neighbours sit close in memory (a prediction then
// reads partners from a few cache lines instead of random ones); rebuilds the cell lists.
// Only called with every particle at clock_.now and all predictions about to be redone.
template <int D, class Observer>
void Engine<D, Observer>::sort_by_cell() {
  std::vector<std::int32_t> start(cells_ + 1, 0);
  for (const auto& particle : part_) ++start[particle.cell + 1];
  for (std::size_t c = 1; c < start.size(); ++c) start[c] += start[c - 1];
  std::vector<Particle> sorted(part_.size());
  std::vector<double> last(part_.size());
  std::vector<std::int32_t> ids(part_.size());
  for (std::int32_t i = 0; i < n_; ++i) {
    const std::int32_t to = start[part_[i].cell]++;
    sorted[to] = part_[i];
    last[to] = last_collision_time_[i];
    ids[to] = id_[i];
  }
  part_.swap(sorted);
  last_collision_time_.swap(last);
  id_.swap(ids);
  allocate_cells();
  std::fill(slot_.begin(), slot_.end(), -1);
  for (std::int32_t i = 0; i < n_; ++i) cell_insert(i, part_[i].cell);
}

template <int D, class Observer>
void Engine<D, Observer>::rebuild_events() {
  if (neighbour_lists_)  // cells by list centre = current position
    for (std::int32_t i = 0; i < n_; ++i) {
      for (int a = 0; a < D; ++a) {
        double& x = part_[i].r[a];
        if (x < 0) x += box_;
        if (x >= box_) x -= box_;
      }
      part_[i].cell = cell_of_position(part_[i].r);
    }
  sort_by_cell();
  if (neighbour_lists_) build_neighbour_lists();
  prefetch_ = memory_bytes() > k_prefetch_min_bytes;
  // Calendar buckets: about one event per bucket. The bucket width comes from the mean time to
  // the particles' next events (measured after predicting with a provisional width).
  const std::int64_t buckets = 4 * static_cast<std::int64_t>(n_);  // window ~ 4 mean waits
  double width = calendar_.bucket_width();
  for (int pass = 0; pass < 2; ++pass) {
    calendar_.reset(n_, clock_.now, width, buckets);
    for (std::int32_t i = 0; i < n_; ++i) predict(i);
    double sum = 0;
    std::int32_t finite = 0;
    for (std::int32_t i = 0; i < n_; ++i) {
      const double wait = calendar_.time(i) - clock_.now;
      if (wait < k_inf) {
        sum += wait;
        ++finite;
      }
    }
    if (finite == 0 || !(sum > 0)) break;
    const double ideal = sum / finite / n_;  // events arrive at rate ~ n / mean wait
    if (ideal > 0.5 * width && ideal < 2 * width) break;
    width = ideal;
  }
}

template <int D, class Observer>
int Engine<D, Observer>::cell_of_position(const double* r) const {
  int x[D];
  for (int a = 0; a < D; ++a)
    x[a] = std::clamp(static_cast<int>(std::floor(r[a] / cell_width_)), 0, cells_per_side_ - 1);
  return cell_index<D>(x, cells_per_side_);
}

template <int D, class Observer>
void Engine<D, Observer>::build_cells() {
  allocate_cells();
  std::fill(slot_.begin(), slot_.end(), -1);
  for (std::int32_t i = 0; i < n_; ++i) {
    for (int a = 0; a < D; ++a) {
      double& x = part_[i].r[a];
      if (x < 0) x += box_;
      if (x >= box_) x -= box_;
    }
    cell_insert(i, cell_of_position(part_[i].r));
  }
}

template <int D, class Observer>
void Engine<D, Observer>::cell_insert(std::int32_t i, int c) {
  cell_coords<D>(c, cells_per_side_, cell_xyz_[i].data());
  file_in_cell(i, c);
}

// Files i in the slots of cell c; cell_xyz_[i] must already hold c's coordinates (the hot path,
// a cell crossing, knows them without divisions).
template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::file_in_cell(std::int32_t i, int c) {
  if (cell_block(c)[0] == capacity_) [[unlikely]] grow_cells();  // i is not filed: skipped
  std::int32_t* block = cell_block(c);
  part_[i].cell = c;
  const std::int32_t k = block[0]++;
  block[1 + k] = i;
  slot_[i] = k;
}

template <int D, class Observer>
void Engine<D, Observer>::allocate_cells() {
  const std::size_t stride = static_cast<std::size_t>(capacity_) + 1;
  // Room to align block 0 to 32 bytes (8 ints), and padding for gather()'s fixed-size copies.
  slots_.assign(cells_ * stride + 8 + k_gather_block + 1, 0);
  const auto address = reinterpret_cast<std::uintptr_t>(slots_.data());
  slots_origin_ = ((32 - address % 32) % 32) / sizeof(std::int32_t);
  candidates_.resize(static_cast<std::size_t>(stencil_size<D>()) * capacity_ + k_gather_block);
}

// More slots per cell (a cluster formed): doubles the block size and re-files every particle.
template <int D, class Observer>
void Engine<D, Observer>::grow_cells() {
  capacity_ = 2 * (capacity_ + 1) - 1;
  allocate_cells();
  for (std::int32_t k = 0; k < n_; ++k)
    if (slot_[k] >= 0) {
      std::int32_t* block = cell_block(part_[k].cell);
      const std::int32_t m = block[0]++;
      block[1 + m] = k;
      slot_[k] = m;
    }
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::cell_remove(std::int32_t i) {
  // Swap-remove: the cell's last member takes i's slot.
  std::int32_t* block = cell_block(part_[i].cell);
  const std::int32_t last = block[block[0]--];
  block[1 + slot_[i]] = last;
  slot_[last] = slot_[i];
  slot_[i] = -1;
}

template <int D, class Observer>
double Engine<D, Observer>::sum_velocity_squared() const {
  double sum = 0;
  for (const auto& particle : part_)
    for (double v : particle.v) sum += v * v;
  return sum;
}

template <int D, class Observer>
void Engine<D, Observer>::scale_velocities(double factor) {
  for (auto& particle : part_)
    for (double& v : particle.v) v *= factor;
  sum_u2_ = sum_velocity_squared();
}

template <int D, class Observer>
double Engine<D, Observer>::time() const {
  return clock_.time();
}

template <int D, class Observer>
double Engine<D, Observer>::temperature() const {
  const double sum = sum_velocity_squared();
  return sum / (static_cast<double>(n_) * D * clock_.theta * clock_.theta);
}

template <int D, class Observer>
double Engine<D, Observer>::kinetic_energy() const {
  const double sum = sum_velocity_squared();
  return 0.5 * sum / (clock_.theta * clock_.theta);
}

template <int D, class Observer>
std::array<double, D> Engine<D, Observer>::momentum() const {
  std::array<double, D> p{};
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) p[a] += clock_.physical_velocity(part_[i].v[a]);
  return p;
}

template <int D, class Observer>
double Engine<D, Observer>::min_pair_distance() const {
  std::vector<double> r(static_cast<std::size_t>(n_) * D);
  for (std::int32_t i = 0; i < n_; ++i) position_now(i, &r[D * i]);
  double best = k_inf;
  int stencil[stencil_size<D>()];
  for (std::int32_t i = 0; i < n_; ++i) {
    neighbour_cells<D>(cell_xyz_[i].data(), cells_per_side_, stencil);
    for (int s = 0; s < stencil_size<D>(); ++s)
      for (const std::int32_t j : cell_members(stencil[s])) {
        if (j <= i) continue;
        double d2 = 0;
        for (int a = 0; a < D; ++a) {
          double d = r[D * i + a] - r[D * j + a];
          if (d > half_box_) d -= box_;
          if (d < -half_box_) d += box_;
          d2 += d * d;
        }
        best = std::min(best, d2);
      }
  }
  return std::sqrt(best);
}

template <int D, class Observer>
void Engine<D, Observer>::check_overlaps() const {
  const double d = min_pair_distance();
  if (d < 1.0 - k_overlap_tolerance)
    throw std::logic_error("overlap: closest pair at distance " + std::to_string(d) + " after " +
                           std::to_string(events_) + " events");
}

template <int D, class Observer>
std::size_t Engine<D, Observer>::memory_bytes() const {
  auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
  return bytes(part_) + bytes(id_) + bytes(ev_) + bytes(last_collision_time_) + bytes(cell_xyz_) +
         bytes(slot_) + bytes(slots_) + bytes(center_) + lists_.memory_bytes() +
         calendar_.memory_bytes();
}

// The engines in use (add one line per dimension for a new collision observer).
template class Engine<2, NoObserver>;
template class Engine<3, NoObserver>;
template class Engine<2, ContactStatistics>;
template class Engine<3, ContactStatistics>;
template class Engine<2, LastCollision>;
template class Engine<3, LastCollision>;

}  // namespace molchaos::sim

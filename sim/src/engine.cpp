// The event-driven engine's event processing: the event loop (Engine::run_events), a collision
// (rule, shuffle, observers, stop conditions), predictions, cell crossings and shell exits. The
// pair search is in engine_pair_search.ipp, the state outside the loop in engine_state.ipp
// (both included below, one translation unit). See engine.hpp for the design.
#include "molchaos/sim/engine.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "molchaos/sim/cell_grid.hpp"
#include "molchaos/sim/hilbert_curve.hpp"
#include "molchaos/sim/huge_pages.hpp"
#include "molchaos/sim/initial_state.hpp"
#include "molchaos/sim/momentum_drift.hpp"
#include "molchaos/sim/parameter_table.hpp"
#include "molchaos/sim/run.hpp"
#include "molchaos/sim/run_length.hpp"

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
// Disks whose data outgrow the cache (k_cache_bytes) are memory-bound: each event costs cache
// misses, so fewer events (wider cells: 4 instead of 6.5 events per collision at n = 0.05) pay
// more than the extra pair predictions cost (paired wall-clock rates at N = 1e6, n = 0.05:
// occupancy 2 ran 1.09, 1.23 and 1.37 times as fast as 0.5).
template <int D>
constexpr double k_cell_occupancy_beyond_cache = D == 2 ? 2.0 : k_cell_occupancy<D>;
// Where the cells' links lie (CellMembers): in the particle records while a cell holds less than
// one particle on average, so that a walk mostly ends at its first member, whose record the pair
// search reads at once (callgrind, L2 misses per collision: 3D at packing 0.1 62.5 -> 54.7;
// paired rates 1.05 there, 1.03 for the paper's case); in an array of their own in fuller cells
// (disks beyond the cache, neighbour-list cells), where a walk through the records would wait for
// each member's record in turn, while the array's links come from the cache and the records'
// misses overlap (2D at N = 1e6 with the links in the records: 0.77 to 0.84 of the rate).
template <int D, bool BeyondCache>
constexpr bool k_links_in_records = (BeyondCache ? k_cell_occupancy_beyond_cache<D>
                                                 : k_cell_occupancy<D>) < 1.0;
// Members of a cell copied without a branch in a stencil's gather (CellMembers::gather), the loop
// taking only the rest: whether a cell holds one member more is a coin flip for the branch
// predictor, each unrolled copy one more dependent load. One for the spheres' cells of 0.4; for
// disks two in the cache (cells of 0.5: paired against one, the paper's case ran 1.01 to 1.05
// times as fast, 0.99 to 1.04 and 1.01 to 1.03 with the shuffles) and three beyond it (cells of
// 2: at N = 1e5 one ran at 0.8 to 0.95 of the rate of the earlier blocks of slots, three as
// fast); four for the neighbour-list cells of dense spheres (~2.6 members; paired rates,
// doc/benchmarks.md).
template <int D, bool BeyondCache>
constexpr int k_branch_free_members = D == 2 ? (BeyondCache ? 3 : 2) : 1;
constexpr int k_branch_free_list_members = 4;
// Engine data above 2 MB: beyond a core's L2 cache (0.5 to 2 MB on current processors), where
// the misses go to the shared last level or to memory. Software prefetches (of the next event's
// and of the candidates' records) only pay then; below, they are extra instructions (8 % of them
// for the paper's case, N = 5000, 1 MB, which ran no faster with them). The particles are then
// also numbered along a Hilbert curve at every rebuild, and disks get wider cells
// (k_cell_occupancy_beyond_cache).
constexpr std::size_t k_cache_bytes = std::size_t{2} << 20;
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
template <class Shuffle, bool Prefetch>
auto Engine<D, Observer>::run_events(double tau_stop, std::uint64_t event_limit,
                                     const CollisionModel& model, const Shuffle& shuffle)
    -> Outcome {
  const double rescale_below = k_rescale_temperature * n_ * D;  // in units of sum u^2
  for (;;) {
    const auto [t, i] = calendar_.top();  // the earliest pending event
    if (!(t < tau_stop)) return Outcome::reached;
    // Likely the next event's particle: its records (and its list, which a collision reads at
    // once for its partners' records) load while this event is processed.
    if (const std::int32_t g = Prefetch ? calendar_.guess_next(i) : -1; g >= 0) {
      __builtin_prefetch(&part_[g]);
      __builtin_prefetch(&ev_[g]);
      calendar_.prefetch(g);
      if (neighbour_lists_) lists_.prefetch(g);
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
        rebuild_neighbours<Prefetch>(i);  // left its shell: new centre, new neighbour list
      else
        cross_cell<Prefetch>(i);  // moves i to its next cell, looks at the cells that came into range
    } else {
      const std::int32_t j = ev_[i].partner;
      if (part_[j].counter != ev_[i].partner_counter) {  // partner's velocity changed since: stale
        predict<Prefetch>(i);
        continue;
      }
      const std::uint64_t before = collisions_;
      collide<Prefetch>(i, j, model, shuffle);  // rule, shuffle, re-predict every particle whose velocity changed
      if (collisions_ != before) stalled_events_ = 0;
      if (stop_) return Outcome::stopped;
      if (sum_u2_ < rescale_below || clock_.now > k_rebase_time) return Outcome::resync;
    }
  }
}

template <int D, class Observer>
template <class Shuffle>
auto Engine<D, Observer>::run_events_for(double tau_stop, std::uint64_t event_limit,
                                         const CollisionModel& model, const Shuffle& shuffle)
    -> Outcome {
  return outgrows_cache_ ? run_events<Shuffle, true>(tau_stop, event_limit, model, shuffle)
                         : run_events<Shuffle, false>(tau_stop, event_limit, model, shuffle);
}

// The debug overlap check runs between event loops: the loop pauses at every multiple of
// debug_check_every_ events (its event limit), so that it carries no test for it.
template <int D, class Observer>
auto Engine<D, Observer>::dispatch(double tau_stop, std::uint64_t event_limit, const CollisionModel& model)
    -> Outcome {
  if (debug_check_every_ == 0) return dispatch_shuffle(tau_stop, event_limit, model);
  for (;;) {
    const std::uint64_t check_at = (events_ / debug_check_every_ + 1) * debug_check_every_;
    const Outcome outcome = dispatch_shuffle(tau_stop, std::min(event_limit, check_at), model);
    if (events_ == check_at) check_overlaps();
    if (outcome != Outcome::paused || events_ >= event_limit) return outcome;
  }
}

template <int D, class Observer>
auto Engine<D, Observer>::dispatch_shuffle(double tau_stop, std::uint64_t event_limit,
                                           const CollisionModel& model) -> Outcome {
  switch (model.shuffle) {
    case Randomization::paper:
      return run_events_for(tau_stop, event_limit, model, PaperShuffle{});
    case Randomization::flux:
      return run_events_for(tau_stop, event_limit, model, FluxShuffle{});
    case Randomization::none:
      break;
  }
  return run_events_for(tau_stop, event_limit, model, NoShuffle{});
}

template <int D, class Observer>
auto Engine<D, Observer>::advance_to(double t, std::uint64_t max_events) -> Status {
  if (stop_) return Status::stopped;
  std::uint64_t limit =
      max_events == std::numeric_limits<std::uint64_t>::max() ? max_events : events_ + max_events;
  if (event_limit_ != 0) limit = std::min(limit, event_limit_);
  for (;;) {
    const double tau_stop = clock_.internal_time(t);
    switch (dispatch(tau_stop, limit, model_)) {
      case Outcome::reached:
        clock_.now = std::max(clock_.now, tau_stop);
        return Status::reached;
      case Outcome::resync:
        resync();
        if (stop_) return Status::stopped;
        continue;
      case Outcome::paused:
        if (event_limit_ != 0 && events_ >= event_limit_) {
          request_stop(StopReason::max_events);
          return Status::stopped;
        }
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
  return outcome == Outcome::stopped || stop_ ? Status::stopped : Status::paused;
}

// Beyond the cache, with neighbour lists: at the start of a collision, the records of i's listed
// partners, which the prediction that ends it reads, so that their misses overlap the collision
// rule and the other particle's (paired rates at packing 0.4, N = 1e5: ×1.09). The same for the
// stencil's cells, with cells, gained nothing measurable (doc/benchmarks.md).
template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::prefetch_listed_partners(
    std::int32_t i) const {
  const std::int32_t* list = lists_.slots(i);
  for (std::int32_t k = 0, count = lists_.count(i); k < count; ++k)
    __builtin_prefetch(&part_[list[k]]);
}

template <int D, class Observer>
template <bool Prefetch, class Shuffle>
void Engine<D, Observer>::collide(std::int32_t i, std::int32_t j, const CollisionModel& model,
                        const Shuffle& shuffle) {
  if (Prefetch && neighbour_lists_) {
    prefetch_listed_partners(i);
    prefetch_listed_partners(j);
  }
  // j's pending-event record holds its cell, where its prediction starts: its miss overlaps i's.
  if (Prefetch) __builtin_prefetch(&ev_[j]);
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
    predict_pair<Prefetch>(i, j);
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
    predict<Prefetch>(k);
    predict<Prefetch>(l);
  }
  predict_pair<Prefetch>(i, j);

  if (micro_run_ >= k_collapse_collisions) request_stop(StopReason::collapse);
  if (collision_limit_ != 0 && collisions_ >= collision_limit_)
    request_stop(StopReason::max_collisions);
  // The floor of double precision is checked here too, not only at a rescaling: those come when
  // the internal T has fallen 16-fold, so the physical T could fall 16 times below the floor
  // before the run noticed (a maximum and a product per collision).
  const double stop_temperature = std::max(min_temperature_, k_temperature_floor);
  if (sum_u2_ * (1.0 / (clock_.theta * clock_.theta)) < stop_temperature * n_ * D)
    request_stop(min_temperature_ >= k_temperature_floor ? StopReason::min_temperature
                                                         : StopReason::temperature_floor);
}

template <int D, class Observer>
void Engine<D, Observer>::request_stop(StopReason reason) {
  if (stop_) return;
  stop_ = true;
  stop_reason_ = reason;
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::advance_particle(std::int32_t i) {
  const double dt = clock_.now - part_[i].t;
  if (dt != 0) {
    for (int a = 0; a < D; ++a) part_[i].r[a] += part_[i].v[a] * dt;
    part_[i].t = clock_.now;
  }
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::crossing(std::int32_t i, const int* x) {
  const Particle& p = part_[i];
  double best = k_inf;
  int axis = 0;
#if defined(__SSE2__)
  if constexpr (D == 2) {
    // Both axes in one SSE2 pass, each lane with the operations of the loop below (the loop's
    // selects came out as branches on u == 0, and each axis as a scalar division).
    const __m128d zero = _mm_setzero_pd();
    const __m128d u = _mm_loadu_pd(p.v);
    const int up = _mm_movemask_pd(_mm_cmpgt_pd(u, zero));  // bit a: u_a > 0
    const __m128d wall =
        _mm_loadh_pd(_mm_load_sd(&wall_[x[0] + (up & 1)]), &wall_[x[1] + (up >> 1)]);
    const __m128d ahead = _mm_div_pd(_mm_sub_pd(wall, _mm_loadu_pd(p.r)), u);
    const __m128d still = _mm_cmpeq_pd(u, zero);  // never crosses along a
    const __m128d dt =
        _mm_or_pd(_mm_andnot_pd(still, ahead), _mm_and_pd(still, _mm_set1_pd(k_inf)));
    const double dt0 = _mm_cvtsd_f64(dt), dt1 = _mm_cvtsd_f64(_mm_unpackhi_pd(dt, dt));
    axis = dt1 < dt0;  // the first axis wins a tie
    best = earlier_of(dt0, dt1);
    ev_[i].cross_time = clock_.now + std::max(best, 0.0);
    ev_[i].cross_axis = axis;
    return;
  }
#endif
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

template <int D, class Observer>
template <bool Prefetch>
void Engine<D, Observer>::predict(std::int32_t i) {
  advance_particle(i);
  double best = k_inf;
  std::int32_t partner = -1;
  int x[D] = {};  // i's cell coordinates (cells only)
  assert((neighbour_lists_ || links_in_records_ == k_links_in_records<D, Prefetch>));
  if (neighbour_lists_) {
    search<Prefetch>(list_needs_wrap(i), i, lists_.slots(i), lists_.count(i), best, partner);
  } else {
    coords_(ev_[i].cell, x);
    int stencil[stencil_size<D>()];
    stencil_of(i, x, stencil);
    // i itself is among the candidates: its pair time is +inf (b = 0).
    const std::int32_t count = gather<stencil_size<D>(), k_branch_free_members<D, Prefetch>,
                                      k_links_in_records<D, Prefetch>>(stencil);
    search<Prefetch>(!interior_cell(x), i, candidates_.data(), count, best, partner);
  }
  schedule(i, best, partner, x);
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::schedule(std::int32_t i, double best,
                                                                 std::int32_t partner,
                                                                 const int* x) {
  ev_[i].coll_time = best;
  ev_[i].partner = partner;
  // Without a partner (-1) the counter is never read: particle 0's is taken (no branch).
  ev_[i].partner_counter = part_[std::max(partner, 0)].counter;
  if (neighbour_lists_)
    shell_exit(i);
  else
    crossing(i, x);
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
  int x[D];
  coords_(ev_[i].cell, x);
  int stencil[stencil_size<D>()];
  stencil_of(i, x, stencil);
  const std::int32_t count = gather<stencil_size<D>(), k_branch_free_list_members, false>(stencil);
  std::int32_t* cand = candidates_.data();
  for (std::int32_t k = 0; k < count; ++k) __builtin_prefetch(&center_[D * cand[k]]);
  const std::int32_t lower = only_higher ? i : -1;
  const std::int32_t found = cells_per_side_ >= 4 && interior_cell(x)
                                 ? keep_neighbours<false>(i, cand, count, lower)
                                 : keep_neighbours<true>(i, cand, count, lower);
  // Their lists take i, and the prediction that follows a shell exit reads their records.
  for (std::int32_t k = 0; k < found; ++k) {
    lists_.prefetch(cand[k]);
    __builtin_prefetch(&part_[cand[k]]);
  }
  for (std::int32_t k = 0; k < found; ++k) {
    lists_.add(i, cand[k]);
    lists_.add(cand[k], i);
  }
}

template <int D, class Observer>
template <bool Prefetch>
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
  file_in_cell(i, cell_of_position(part_[i].r));
  collect_neighbours(i, false);
  predict<Prefetch>(i);
}

// A cell crossing: i moves to its next cell (exactly onto the wall), and only the cells that came
// into range can hold new partners: pairs with the other cells were predicted before, by i or by
// the partner (whichever changed last). One function for the whole event (the hot path of dilute
// systems: most events are crossings).
template <int D, class Observer>
template <bool Prefetch>
inline void Engine<D, Observer>::cross_cell(std::int32_t i) {
  advance_particle(i);
  Particle& p = part_[i];
  const int axis = ev_[i].cross_axis;
  const bool up = p.v[axis] > 0;
  const int old_cell = ev_[i].cell;
  int x[D];
  coords_(old_cell, x);
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
  x[axis] = to;  // now the new cell's coordinates
  const int c = old_cell + step;
  cell_remove(i);
  file_in_cell(i, c);

  int slab[slab_size<D>()];
  const bool interior = interior_cell(x);
  if (interior) {  // no periodic wrap: fixed offsets
    const int* offset = slab_offset_[2 * axis + up].data();
    for (int s = 0; s < slab_size<D>(); ++s) slab[s] = c + offset[s];
  } else {
    slab_cells<D>(x, cells_per_side_, axis, up ? 1 : -1, slab);
  }
  double best = ev_[i].coll_time;
  std::int32_t partner = -1;
  const std::int32_t count =
      gather<slab_size<D>(), k_branch_free_members<D, Prefetch>, k_links_in_records<D, Prefetch>>(
          slab);
  search<Prefetch>(!interior, i, candidates_.data(), count, best, partner);
  // best is the old collision time unless a new partner was found (selects, no branch).
  ev_[i].coll_time = best;
  // Masks instead of selects, which the compiler turned into (mispredicted) branches.
  EventData& e = ev_[i];
  const std::uint32_t keep = static_cast<std::uint32_t>(partner >> 31);  // ones: none found
  const std::uint32_t counter = part_[std::max(partner, 0)].counter;
  e.partner = static_cast<std::int32_t>((static_cast<std::uint32_t>(partner) & ~keep) |
                                        (static_cast<std::uint32_t>(e.partner) & keep));
  e.partner_counter = (counter & ~keep) | (e.partner_counter & keep);
  crossing(i, x);
  calendar_.update(i, earlier_of(best, ev_[i].cross_time));
}

#include "engine_pair_search.ipp"
#include "engine_state.ipp"

// The engines in use (add one line per dimension for a new collision observer).
template class Engine<2, NoObserver>;
template class Engine<3, NoObserver>;
template class Engine<2, ContactStatistics>;
template class Engine<3, ContactStatistics>;
template class Engine<2, LastCollision>;
template class Engine<3, LastCollision>;

}  // namespace molchaos::sim

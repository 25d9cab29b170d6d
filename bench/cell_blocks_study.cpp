// A design study for the dilute-disk engine, not used by the suite: event-driven hard disks whose
// cells hold their members' positions, velocities and local times in contiguous blocks (a
// structure of arrays per cell) instead of lists through the particle records. A prediction then
// reads its candidates from a few cache lines, two per SSE2 pass, without walking lists, so that
// wider cells (fewer cell crossings per collision) might pay. It answers one question with
// numbers (doc/benchmarks.md, "Cells as contiguous blocks"): how many instructions a collision
// of the paper's case costs in such a layout at each cell width, against the engine's.
//
// Deliberately small: d = 2, constant restitution, no shuffle, no observers, no rescaling (the
// timed phase is short enough for the internal temperature to stay far from underflow). It
// prints its own physics checks beside the counts: the elastic collision frequency against
// Enskog's and the closest pair at the end.
//
// Usage: cell_blocks_study [N density occupancy restitution collisions seed unrolled]
//   (defaults 5000 0.05 2 0.93 200000 1 4). Under callgrind (engine_counts.sh's options) only
//   the timed collisions are counted.
#include <emmintrin.h>
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <random>
#include <vector>

#include "molchaos/sim/event_calendar.hpp"

#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#else
#define CALLGRIND_TOGGLE_COLLECT
#endif

namespace {

constexpr double k_inf = std::numeric_limits<double>::infinity();
constexpr double k_nan = std::numeric_limits<double>::quiet_NaN();

// One cell: slots 0 .. count-1 hold its members; every other slot has a NaN position, which makes
// its pair time +inf (every comparison with NaN is false), so that a search may read past count.
template <int Slots>
struct alignas(64) CellBlock {
  double x[Slots], y[Slots], vx[Slots], vy[Slots], t[Slots];
  std::int32_t id[Slots];
  std::int32_t count;
};

// Unrolled: slots searched in every block without a loop test (the rest take a loop), the
// branch-free share of a search, as the engine's gather copies its first members of a cell.
template <int Slots, int Unrolled>
class BlockGas {
 public:
  BlockGas(int particles, double density, double occupancy, unsigned seed);

  void run(std::uint64_t collisions_to);  // until collisions_ reaches collisions_to
  void restart();  // every particle to now, clock to 0, new predictions
  double temperature() const;
  void scale_velocities(double factor);
  double min_pair_distance() const;

  double restitution = 1.0;
  std::uint64_t collisions_ = 0, events_ = 0, candidates_ = 0;
  double now_ = 0;
  int cells_per_side() const { return cps_; }
  double cell_width() const { return width_; }

 private:
  struct Event {
    double coll_time = k_inf, cross_time = k_inf;
    std::int32_t partner = -1;
    std::uint32_t partner_counter = 0;
    std::int32_t cross_axis = 0;
  };
  CellBlock<Slots>& block_of(int i) { return cell_[cell_of_[i]]; }
  const CellBlock<Slots>& block_of(int i) const { return cell_[cell_of_[i]]; }
  int index(int cx, int cy) const { return cx + cps_ * cy; }
  int wrap(int c) const { return c < 0 ? c + cps_ : (c >= cps_ ? c - cps_ : c); }
  bool interior(int cx, int cy) const {
    return (static_cast<unsigned>(cx - 1) < static_cast<unsigned>(cps_ - 2)) &
           (static_cast<unsigned>(cy - 1) < static_cast<unsigned>(cps_ - 2));
  }
  void file(int i, int c, const double* state);  // state: x, y, vx, vy, t
  void unfile(int i);
  void advance(int i);
  template <bool Wrap>
  void search_block(int i, int c, double& best, std::int32_t& partner);
  void search(int i, const int* cells, int count, bool wrap, double& best, std::int32_t& partner);
  void schedule(int i);
  void predict(int i);
  void cross_cell(int i);
  void collide(int i, int j);

  int n_ = 0, cps_ = 0;
  double box_ = 0, half_box_ = 0, width_ = 0;
  std::vector<CellBlock<Slots>> cell_;
  std::vector<double> wall_;  // k * width_, box_ for the last
  std::vector<std::int32_t> cell_of_, slot_of_;
  std::vector<std::uint32_t> counter_;  // bumped whenever the velocity changes
  std::vector<Event> event_;
  molchaos::sim::EventCalendar calendar_;
};

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::file(int i, int c, const double* state) {
  CellBlock<Slots>& b = cell_[c];
  if (b.count == Slots) {
    std::fprintf(stderr, "cell_blocks_study: a cell holds more than %d disks\n", Slots);
    std::exit(3);
  }
  const int s = b.count++;
  b.x[s] = state[0], b.y[s] = state[1], b.vx[s] = state[2], b.vy[s] = state[3];
  b.t[s] = state[4], b.id[s] = i;
  cell_of_[i] = c, slot_of_[i] = s;
}

// The last member takes i's slot, and the freed slot is made inert again.
template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::unfile(int i) {
  CellBlock<Slots>& b = block_of(i);
  const int s = slot_of_[i], last = --b.count;
  b.x[s] = b.x[last], b.y[s] = b.y[last], b.vx[s] = b.vx[last], b.vy[s] = b.vy[last];
  b.t[s] = b.t[last], b.id[s] = b.id[last];
  slot_of_[b.id[s]] = s;
  b.x[last] = b.y[last] = k_nan;
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::advance(int i) {
  CellBlock<Slots>& b = block_of(i);
  const int s = slot_of_[i];
  const double dt = now_ - b.t[s];
  b.x[s] += b.vx[s] * dt;
  b.y[s] += b.vy[s] * dt;
  b.t[s] = now_;
}

// The earliest contact of i (at now) with the members of block c after `best`: the engine's
// pair time (the smaller root of |dr + dv t| = 1, cancellation-free), two slots per pass.
template <int Slots, int Unrolled>
template <bool Wrap>
void BlockGas<Slots, Unrolled>::search_block(int i, int c, double& best, std::int32_t& partner) {
  const CellBlock<Slots>& b = cell_[c];
  const CellBlock<Slots>& own = block_of(i);
  const int si = slot_of_[i];
  const __m128d xi = _mm_set1_pd(own.x[si]), yi = _mm_set1_pd(own.y[si]);
  const __m128d vxi = _mm_set1_pd(own.vx[si]), vyi = _mm_set1_pd(own.vy[si]);
  const __m128d now = _mm_set1_pd(now_), zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0);
  const __m128d half = _mm_set1_pd(half_box_), minus_half = _mm_set1_pd(-half_box_);
  const __m128d box = _mm_set1_pd(box_);
  candidates_ += static_cast<std::uint64_t>(b.count);
  double earliest = best;
  std::int32_t who = partner;
  const auto pass = [&](int s) {
    const __m128d dtj = _mm_sub_pd(now, _mm_load_pd(&b.t[s]));
    const __m128d vxj = _mm_load_pd(&b.vx[s]), vyj = _mm_load_pd(&b.vy[s]);
    __m128d dx = _mm_sub_pd(xi, _mm_add_pd(_mm_load_pd(&b.x[s]), _mm_mul_pd(vxj, dtj)));
    __m128d dy = _mm_sub_pd(yi, _mm_add_pd(_mm_load_pd(&b.y[s]), _mm_mul_pd(vyj, dtj)));
    if constexpr (Wrap) {
      dx = _mm_sub_pd(dx, _mm_and_pd(_mm_cmpgt_pd(dx, half), box));
      dx = _mm_add_pd(dx, _mm_and_pd(_mm_cmplt_pd(dx, minus_half), box));
      dy = _mm_sub_pd(dy, _mm_and_pd(_mm_cmpgt_pd(dy, half), box));
      dy = _mm_add_pd(dy, _mm_and_pd(_mm_cmplt_pd(dy, minus_half), box));
    }
    const __m128d dvx = _mm_sub_pd(vxi, vxj), dvy = _mm_sub_pd(vyi, vyj);
    const __m128d bdot = _mm_add_pd(_mm_mul_pd(dx, dvx), _mm_mul_pd(dy, dvy));
    const __m128d dr2 = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
    const __m128d dv2 = _mm_add_pd(_mm_mul_pd(dvx, dvx), _mm_mul_pd(dvy, dvy));
    const __m128d cc = _mm_sub_pd(dr2, one);
    const __m128d disc = _mm_sub_pd(_mm_mul_pd(bdot, bdot), _mm_mul_pd(dv2, cc));
    const __m128d valid = _mm_and_pd(_mm_cmplt_pd(bdot, zero), _mm_cmpge_pd(disc, zero));
    const __m128d root = _mm_sqrt_pd(_mm_max_pd(disc, zero));
    const __m128d dt = _mm_div_pd(cc, _mm_sub_pd(root, bdot));
    const __m128d t = _mm_add_pd(now, _mm_max_pd(dt, zero));
    double times[2];
    _mm_storeu_pd(times,
                  _mm_or_pd(_mm_and_pd(valid, t), _mm_andnot_pd(valid, _mm_set1_pd(k_inf))));
    who = times[0] < earliest ? b.id[s] : who;
    earliest = times[0] < earliest ? times[0] : earliest;
    who = times[1] < earliest ? b.id[s + 1] : who;
    earliest = times[1] < earliest ? times[1] : earliest;
  };
#pragma GCC unroll 8
  for (int s = 0; s < Unrolled; s += 2) pass(s);
  for (int s = Unrolled; s < b.count; s += 2) pass(s);
  best = earliest;
  partner = who;
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::search(int i, const int* cells, int count, bool wrap,
                                       double& best, std::int32_t& partner) {
  if (wrap)
    for (int k = 0; k < count; ++k) search_block<true>(i, cells[k], best, partner);
  else
    for (int k = 0; k < count; ++k) search_block<false>(i, cells[k], best, partner);
}

// i's next cell crossing, then its pending event (the earlier of crossing and collision).
template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::schedule(int i) {
  const int c = cell_of_[i], s = slot_of_[i];
  const CellBlock<Slots>& b = cell_[c];
  const int cx = c % cps_, cy = c / cps_;
  const double vx = b.vx[s], vy = b.vy[s];
  const double tx = vx == 0 ? k_inf : (wall_[cx + (vx > 0)] - b.x[s]) / vx;
  const double ty = vy == 0 ? k_inf : (wall_[cy + (vy > 0)] - b.y[s]) / vy;
  event_[i].cross_axis = ty < tx;
  event_[i].cross_time = now_ + std::max(std::min(tx, ty), 0.0);
  calendar_.update(i, std::min(event_[i].coll_time, event_[i].cross_time));
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::predict(int i) {
  advance(i);
  const int c = cell_of_[i], cx = c % cps_, cy = c / cps_;
  int cells[9], k = 0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) cells[k++] = index(wrap(cx + dx), wrap(cy + dy));
  double best = k_inf;
  std::int32_t partner = -1;
  search(i, cells, 9, !interior(cx, cy), best, partner);
  event_[i].coll_time = best;
  event_[i].partner = partner;
  event_[i].partner_counter = counter_[static_cast<std::size_t>(std::max(partner, 0))];
  schedule(i);
}

// i moves onto the wall into its next cell (its data to that cell's block), and only the three
// cells that came into range can hold new partners.
template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::cross_cell(int i) {
  advance(i);
  const int c = cell_of_[i], s = slot_of_[i];
  const CellBlock<Slots>& b = cell_[c];
  const int axis = event_[i].cross_axis;
  int x[2] = {c % cps_, c / cps_};
  double state[5] = {b.x[s], b.y[s], b.vx[s], b.vy[s], b.t[s]};
  const bool up = state[2 + axis] > 0;
  const int sign = up ? 1 : -1;
  state[axis] = wall_[x[axis] + up];
  x[axis] += sign;
  if (x[axis] == cps_) x[axis] = 0, state[axis] = 0;
  if (x[axis] < 0) x[axis] = cps_ - 1, state[axis] = box_;
  unfile(i);
  file(i, index(x[0], x[1]), state);
  int cells[3];
  for (int d = -1; d <= 1; ++d)
    cells[d + 1] = axis == 0 ? index(wrap(x[0] + sign), wrap(x[1] + d))
                             : index(wrap(x[0] + d), wrap(x[1] + sign));
  double best = event_[i].coll_time;
  std::int32_t partner = -1;
  search(i, cells, 3, !interior(x[0], x[1]), best, partner);
  if (partner >= 0) {
    event_[i].coll_time = best;
    event_[i].partner = partner;
    event_[i].partner_counter = counter_[static_cast<std::size_t>(partner)];
  }
  schedule(i);
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::collide(int i, int j) {
  advance(i);
  advance(j);
  CellBlock<Slots>& bi = block_of(i);
  CellBlock<Slots>& bj = block_of(j);
  const int si = slot_of_[i], sj = slot_of_[j];
  double dx = bi.x[si] - bj.x[sj], dy = bi.y[si] - bj.y[sj];
  dx += dx > half_box_ ? -box_ : (dx < -half_box_ ? box_ : 0.0);
  dy += dy > half_box_ ? -box_ : (dy < -half_box_ ? box_ : 0.0);
  const double dvx = bi.vx[si] - bj.vx[sj], dvy = bi.vy[si] - bj.vy[sj];
  const double approach = dx * dvx + dy * dvy;
  if (approach < 0) {
    const double inv_distance = 1.0 / std::sqrt(dx * dx + dy * dy);
    const double ex = dx * inv_distance, ey = dy * inv_distance;
    // Inelastic hard disks: the normal relative velocity g_n goes to -restitution g_n.
    const double kick = 0.5 * (1.0 + restitution) * approach * inv_distance;
    bi.vx[si] -= kick * ex, bi.vy[si] -= kick * ey;
    bj.vx[sj] += kick * ex, bj.vy[sj] += kick * ey;
    ++counter_[static_cast<std::size_t>(i)], ++counter_[static_cast<std::size_t>(j)];
    ++collisions_;
  }
  predict(i);
  predict(j);
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::run(std::uint64_t collisions_to) {
  while (collisions_ < collisions_to) {
    const auto [t, i] = calendar_.top();
    now_ = t;
    ++events_;
    Event& e = event_[static_cast<std::size_t>(i)];
    if (e.cross_time < e.coll_time)
      cross_cell(i);
    else if (counter_[static_cast<std::size_t>(e.partner)] != e.partner_counter)
      predict(i);  // stale: the partner's velocity changed since
    else
      collide(i, e.partner);
  }
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::restart() {
  for (int i = 0; i < n_; ++i) advance(i);
  for (int i = 0; i < n_; ++i) block_of(i).t[slot_of_[i]] = 0;
  now_ = 0;
  // Calendar buckets of about one event each, from the mean wait of a first prediction.
  calendar_.reset(n_, 0.0, 1.0 / n_, 4 * std::int64_t{n_});
  for (int i = 0; i < n_; ++i) predict(i);
  double sum = 0;
  int finite = 0;
  for (int i = 0; i < n_; ++i)
    if (calendar_.time(i) < k_inf) sum += calendar_.time(i), ++finite;
  calendar_.reset(n_, 0.0, sum / finite / n_, 4 * std::int64_t{n_});
  for (int i = 0; i < n_; ++i) predict(i);
}

template <int Slots, int Unrolled>
double BlockGas<Slots, Unrolled>::temperature() const {
  double sum = 0;
  for (int i = 0; i < n_; ++i) {
    const CellBlock<Slots>& b = block_of(i);
    sum += b.vx[slot_of_[i]] * b.vx[slot_of_[i]] + b.vy[slot_of_[i]] * b.vy[slot_of_[i]];
  }
  return sum / (2.0 * n_);
}

template <int Slots, int Unrolled>
void BlockGas<Slots, Unrolled>::scale_velocities(double factor) {
  for (int i = 0; i < n_; ++i) {
    CellBlock<Slots>& b = block_of(i);
    b.vx[slot_of_[i]] *= factor, b.vy[slot_of_[i]] *= factor;
  }
}

template <int Slots, int Unrolled>
double BlockGas<Slots, Unrolled>::min_pair_distance() const {
  std::vector<double> x(n_), y(n_);
  for (int i = 0; i < n_; ++i) {
    const CellBlock<Slots>& b = block_of(i);
    const int s = slot_of_[i];
    x[i] = b.x[s] + b.vx[s] * (now_ - b.t[s]), y[i] = b.y[s] + b.vy[s] * (now_ - b.t[s]);
  }
  double best = k_inf;
  for (int i = 0; i < n_; ++i) {
    const int cx = cell_of_[i] % cps_, cy = cell_of_[i] / cps_;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const CellBlock<Slots>& b = cell_[index(wrap(cx + dx), wrap(cy + dy))];
        for (int u = 0; u < b.count; ++u) {
          const int j = b.id[u];
          if (j == i) continue;
          double rx = x[i] - x[j], ry = y[i] - y[j];
          rx -= box_ * std::round(rx / box_), ry -= box_ * std::round(ry / box_);
          best = std::min(best, rx * rx + ry * ry);
        }
      }
  }
  return std::sqrt(best);
}

// Random sequential placement (cells of at least one diameter make the overlap test local),
// Maxwell velocities with zero momentum and T = 1.
template <int Slots, int Unrolled>
BlockGas<Slots, Unrolled>::BlockGas(int particles, double density, double occupancy,
                                    unsigned seed) {
  n_ = particles;
  box_ = std::sqrt(n_ / density);
  half_box_ = 0.5 * box_;
  const double width_target = std::max(1.0, std::sqrt(occupancy / density));  // cells >= sigma
  cps_ = std::max(4, static_cast<int>(std::floor(box_ / width_target)));
  width_ = box_ / cps_;
  wall_.resize(static_cast<std::size_t>(cps_) + 1);
  for (int k = 0; k < cps_; ++k) wall_[static_cast<std::size_t>(k)] = k * width_;
  wall_.back() = box_;
  cell_.resize(static_cast<std::size_t>(cps_) * static_cast<std::size_t>(cps_));
  for (auto& b : cell_) {
    b.count = 0;
    for (int s = 0; s < Slots; ++s)
      b.x[s] = b.y[s] = k_nan, b.vx[s] = b.vy[s] = b.t[s] = 0, b.id[s] = 0;
  }
  cell_of_.assign(static_cast<std::size_t>(n_), 0);
  slot_of_.assign(static_cast<std::size_t>(n_), 0);
  counter_.assign(static_cast<std::size_t>(n_), 0);
  event_.assign(static_cast<std::size_t>(n_), Event{});
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, box_);
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (int i = 0; i < n_; ++i) {
    double state[5] = {0, 0, 0, 0, 0};
    int c = 0;
    for (bool free = false; !free;) {
      state[0] = uniform(rng), state[1] = uniform(rng);
      const int cx = std::min(cps_ - 1, static_cast<int>(state[0] / width_));
      const int cy = std::min(cps_ - 1, static_cast<int>(state[1] / width_));
      c = index(cx, cy);
      free = true;
      for (int dy = -1; dy <= 1 && free; ++dy)
        for (int dx = -1; dx <= 1 && free; ++dx) {
          const CellBlock<Slots>& b = cell_[index(wrap(cx + dx), wrap(cy + dy))];
          for (int u = 0; u < b.count && free; ++u) {
            double rx = state[0] - b.x[u], ry = state[1] - b.y[u];
            rx -= box_ * std::round(rx / box_), ry -= box_ * std::round(ry / box_);
            free = rx * rx + ry * ry > 1.0;
          }
        }
    }
    state[2] = gauss(rng), state[3] = gauss(rng);
    file(i, c, state);
  }
  double mx = 0, my = 0;
  for (int i = 0; i < n_; ++i) mx += block_of(i).vx[slot_of_[i]], my += block_of(i).vy[slot_of_[i]];
  for (int i = 0; i < n_; ++i) {
    block_of(i).vx[slot_of_[i]] -= mx / n_;
    block_of(i).vy[slot_of_[i]] -= my / n_;
  }
  scale_velocities(1.0 / std::sqrt(temperature()));
  restart();
}

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// The bench's protocol: one collision per particle of elastic relaxation, T back to 1, then
// `timed` collisions at the given restitution.
template <int Slots, int Unrolled>
int study(int particles, double density, double occupancy, double restitution,
          std::uint64_t timed, unsigned seed) {
  BlockGas<Slots, Unrolled> gas(particles, density, occupancy, seed);
  gas.run(static_cast<std::uint64_t>(particles) / 2);
  gas.scale_velocities(1.0 / std::sqrt(gas.temperature()));
  gas.restart();
  gas.collisions_ = gas.events_ = gas.candidates_ = 0;
  gas.restitution = restitution;
  const double cpu = thread_cpu_seconds();
  CALLGRIND_TOGGLE_COLLECT;
  gas.run(timed);
  CALLGRIND_TOGGLE_COLLECT;
  const double seconds = thread_cpu_seconds() - cpu;
  // Enskog's collision frequency per particle at T = 1 (m = sigma = 1): 2 n g2 sqrt(pi T), with
  // Henderson's contact value g2 = (1 - 7 eta / 16) / (1 - eta)^2, eta = pi n / 4.
  const double eta = std::numbers::pi / 4.0 * density;
  const double g2 = (1.0 - 7.0 * eta / 16.0) / ((1.0 - eta) * (1.0 - eta));
  const double enskog = 2.0 * density * g2 * std::sqrt(std::numbers::pi);
  const auto collisions = static_cast<double>(gas.collisions_);
  // The check holds at T = 1 only: an inelastic gas cools, and its ratio is not printed.
  const double omega_ratio = restitution == 1.0
                                 ? 2.0 * collisions / particles / gas.now_ / enskog
                                 : std::numeric_limits<double>::quiet_NaN();
  std::printf(
      "cells_per_side %d width %.3f per_cell %.2f unrolled %d collisions %llu events_per_coll %.3f "
      "candidates_per_coll %.1f coll_per_cpu_s %.4g omega_over_enskog %.4f min_distance %.12f\n",
      gas.cells_per_side(), gas.cell_width(),
      particles / static_cast<double>(gas.cells_per_side() * gas.cells_per_side()), Unrolled,
      static_cast<unsigned long long>(gas.collisions_),
      static_cast<double>(gas.events_) / collisions,
      static_cast<double>(gas.candidates_) / collisions, collisions / seconds,
      omega_ratio, gas.min_pair_distance());
  return 0;
}

// Slots per cell: room for the most crowded cell of a Poisson gas of that occupancy.
template <int Unrolled>
int study_for(int particles, double density, double occupancy, double restitution,
              std::uint64_t timed, unsigned seed) {
  if (occupancy <= 1.0)
    return study<8, Unrolled>(particles, density, occupancy, restitution, timed, seed);
  if (occupancy <= 3.0)
    return study<16, Unrolled>(particles, density, occupancy, restitution, timed, seed);
  return study<24, Unrolled>(particles, density, occupancy, restitution, timed, seed);
}

}  // namespace

int main(int argc, char** argv) {
  const int particles = argc > 1 ? std::atoi(argv[1]) : 5000;
  const double density = argc > 2 ? std::atof(argv[2]) : 0.05;
  const double occupancy = argc > 3 ? std::atof(argv[3]) : 2.0;
  const double restitution = argc > 4 ? std::atof(argv[4]) : 0.93;
  const std::uint64_t timed = argc > 5 ? std::strtoull(argv[5], nullptr, 10) : 200000;
  const auto seed = static_cast<unsigned>(argc > 6 ? std::atoi(argv[6]) : 1);
  const int unrolled = argc > 7 ? std::atoi(argv[7]) : 4;
  if (particles < 16 || !(density > 0 && density < 0.5) || !(occupancy > 0 && occupancy <= 4) ||
      !(restitution > 0 && restitution <= 1) || timed == 0 || (unrolled != 2 && unrolled != 4)) {
    std::fprintf(stderr,
                 "usage: cell_blocks_study [N >= 16] [density in (0, 0.5)] [occupancy in (0, 4]] "
                 "[restitution in (0, 1]] [collisions >= 1] [seed] [unrolled: 2 or 4]\n");
    return 2;
  }
  return unrolled == 2 ? study_for<2>(particles, density, occupancy, restitution, timed, seed)
                       : study_for<4>(particles, density, occupancy, restitution, timed, seed);
}

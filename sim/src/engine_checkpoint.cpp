// The engine's checkpoint: the one list of the members that the parameters do not fix
// (checkpoint.hpp). A translation unit of its own rather than a part of engine.cpp: in engine.cpp
// the extra functions changed GCC's inlining in the hot path (cross_cell, predict) and cost 3 %
// more instructions per collision (bench/engine_counts.sh); here the engine compiles as without it.
#include <algorithm>
#include <cmath>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/engine.hpp"

namespace molchaos::sim {

// Exactness. The engine's future depends on more than positions and velocities: on the order of
// the events in the calendar's bucket lists and of the members in the cell lists (ties), on the
// lazily advanced particle clocks, the collision counters that invalidate stale events, and the
// internal clock's rescaling. Rebuilding these (as resync() does) would give a different but
// equally valid trajectory, and the same one as the uninterrupted run only if that run also
// resynchronised at the checkpoint's time, which would tie the trajectory to the checkpoint
// schedule (and to when a batch system's signal arrives). So every such member is restored bit for
// bit instead, and a checkpoint may be taken between any two advance_to() calls: stopping there
// (paused, or reached at a sample time that every run of these parameters reaches) changes
// nothing in the state. What the constructor derives from the parameters (geometry, collision
// model, stop conditions, collapse threshold) is rebuilt by constructing the engine from them.
//
// A new member of Engine: add it to checkpoint_members() below unless the constructor sets it
// from the parameters alone, and raise k_checkpoint_format (checkpoint.hpp).

template <int D, class Observer>
template <class Self, class Archive>
void Engine<D, Observer>::checkpoint_members(Self& self, Archive& archive) {
  static_assert(std::is_trivially_copyable_v<Observer>, "observers are saved as bytes");
  archive(self.part_, self.id_, self.ev_, self.last_collision_time_);
  CellMembers::checkpoint_members(self.members_, archive);
  archive(self.cell_links_);
  archive(self.center_);
  NeighbourLists::checkpoint_members(self.lists_, archive);
  EventCalendar::checkpoint_members(self.calendar_, archive);
  archive(self.clock_, self.sum_u2_, self.collisions_, self.events_);
  archive(self.shuffle_rng_, self.micro_run_, self.stalled_events_, self.observer_, self.stop_,
          self.stop_reason_);
}

template <int D, class Observer>
void Engine<D, Observer>::save_state(CheckpointWriter& out) const {
  checkpoint_members(*this, out);
}

template <int D, class Observer>
void Engine<D, Observer>::restore_state(CheckpointReader& in) {
  checkpoint_members(*this, in);
  const std::size_t n = static_cast<std::size_t>(n_);
  if (part_.size() != n + 1 || id_.size() != n || ev_.size() != n ||
      last_collision_time_.size() != n || (neighbour_lists_ && center_.size() != n * D) ||
      cell_links_.size() != (links_in_records_ ? 0 : n + 1))
    in.fail("engine arrays of another size than the parameters' N");
}

// A checkpoint whose checksum holds can still carry a state without sense (written by a faulty
// build, or edited with the checksum recomputed). The engine would run it on, silently wrong or
// into a dead-lock, so it is refused here, before any event, naming the first thing wrong: every
// particle filed once, in the cell it names and lies in (by its list centre with neighbour
// lists); finite positions inside the box (or within a shell of their list centres), velocities,
// local times no later than the clock, event partners that exist; the kinetic energy the engine
// carries equal to the velocities' (to 1e-6: its running sum drifts by rounding far less between
// two resyncs, which recompute it); no overlapping pair.
template <int D, class Observer>
void Engine<D, Observer>::check_restored(const CheckpointReader& in) const {
  const std::int32_t n = n_;
  auto particle = [&](std::int32_t i, const std::string& what) {
    in.fail("particle " + std::to_string(i) + " " + what);
  };
  if (!std::isfinite(clock_.now) || clock_.now < 0)
    in.fail("internal clock not a finite time >= 0");
  // theta = 0 ran for ever; theta < 0 ran to the run's end without a collision.
  if (!(clock_.theta > 0) || !std::isfinite(clock_.theta) || !std::isfinite(clock_.t_offset))
    in.fail("clock's time unit theta not a finite number > 0, or its offset not finite");
  if (collisions_ > events_) in.fail("more collisions than events");
  // All zero, the shuffle drew particle 0 for ever: a run with the paper's shuffle never ended.
  if (!shuffle_rng_.well_formed())
    in.fail("shuffle's random generator in the all-zero state or with a spare that is not finite");
  // Sums that are not finite went into the samples' contact statistics, and on into the output.
  if constexpr (requires(const Observer& o) { o.well_formed(); })
    if (!observer_.well_formed())
      in.fail("collision observer's sums not finite or not matching its count of collisions");
  // A run is saved only while it goes on: not stopped, below the collapse and dead-lock counts.
  if (stop_ || micro_run_ >= k_collapse_collisions || stalled_events_ >= k_stall_events)
    in.fail("a run that has stopped, or counts at a collapse or dead-lock");
  std::vector<char> seen(static_cast<std::size_t>(n), 0);
  for (std::int32_t i = 0; i < n; ++i) {
    const std::int32_t k = id_[i];
    if (k < 0 || k >= n || seen[k])
      particle(i, "has an original index that is out of range or repeated");
    seen[k] = 1;
  }
  std::fill(seen.begin(), seen.end(), 0);
  if (!members_.shaped_for(cells_, n)) in.fail("cell lists of another size than the grid's");
  if (next_in_cell(n) != n) in.fail("the end of the cell lists does not link to itself");
  if (!calendar_.well_formed(n))
    in.fail("event calendar not filing each particle once, in the bucket of its time");
  if (neighbour_lists_ && !lists_.well_formed(n))
    in.fail("neighbour lists of another size than N, or listing particles out of range");
  for (std::size_t c = 0; c < cells_; ++c)  // a list that loops meets a particle seen before
    for (std::int32_t i = members_.first(static_cast<int>(c)); i != n; i = next_in_cell(i)) {
      if (i < 0 || i > n || seen[i] || ev_[i].cell != static_cast<int>(c))
        in.fail("cell " + std::to_string(c) + " lists a particle that is out of range, listed "
                "twice, or filed in another cell");
      seen[i] = 1;
    }
  const double slack = 1e-9 * box_;
  double sum_u2 = 0;
  for (std::int32_t i = 0; i < n; ++i) {
    const Particle& p = part_[i];
    if (!seen[i]) particle(i, "is in no cell");
    if (!std::isfinite(p.t) || p.t > clock_.now)
      particle(i, "has a local time that is not finite or lies after the clock");
    if (!(last_collision_time_[i] <= clock_.now))  // -inf before its first collision
      particle(i, "has a last collision that is not a time or lies after the clock");
    double shift2 = 0;
    int x[D];
    coords_(ev_[i].cell, x);
    for (int a = 0; a < D; ++a) {
      if (!std::isfinite(p.r[a]) || !std::isfinite(p.v[a]))
        particle(i, "has a position or velocity that is not finite");
      const double reference = neighbour_lists_ ? center_[D * i + a] : p.r[a];
      if (reference < -slack || reference > box_ + slack)
        particle(i, "lies outside the box [0, " + std::to_string(box_) + "]");
      if (reference < wall_[x[a]] - slack || reference > wall_[x[a] + 1] + slack)
        particle(i, "lies outside the cell it is filed in");
      shift2 += neighbour_lists_ ? (p.r[a] - reference) * (p.r[a] - reference) : 0.0;
      sum_u2 += p.v[a] * p.v[a];
    }
    if (shift2 > (shell_ + slack) * (shell_ + slack)) particle(i, "lies outside its shell");
    const EventData& e = ev_[i];
    if (e.partner < -1 || e.partner >= n || std::isnan(e.coll_time) || std::isnan(e.cross_time))
      particle(i, "has a pending event with no such partner or no time");
    if (calendar_.time(i) != std::min(e.coll_time, e.cross_time))
      particle(i, "is filed in the event calendar at another time than its pending event's");
  }
  if (!(std::abs(sum_u2 - sum_u2_) <= 1e-6 * sum_u2))
    in.fail("kinetic energy " + std::to_string(sum_u2_) + " differs from the velocities' " +
            std::to_string(sum_u2));
  if (const double d = min_pair_distance(); d < 1.0 - k_overlap_tolerance)
    in.fail("two particles overlap (closest pair at distance " + std::to_string(d) + " sigma)");
}

template <int D, class Observer>
std::string Engine<D, Observer>::checkpoint_layout() {
  // Appended piece by piece: GCC 12 warns (-Wrestrict, falsely) on "literal" + std::string.
  const std::pair<const char*, std::size_t> parts[] = {{"d", D},
                                                       {" particle ", sizeof(Particle)},
                                                       {" event ", sizeof(EventData)},
                                                       {" observer ", sizeof(Observer)},
                                                       {" rng ", sizeof(Rng)}};
  std::string layout;
  for (const auto& [name, size] : parts) {
    layout += name;
    layout += std::to_string(size);
  }
  return layout;
}

// The engines of run() (engine.cpp instantiates the rest of each).
#define MOLCHAOS_ENGINE_CHECKPOINT(D, Observer)                           \
  template void Engine<D, Observer>::save_state(CheckpointWriter&) const; \
  template void Engine<D, Observer>::restore_state(CheckpointReader&);    \
  template void Engine<D, Observer>::check_restored(const CheckpointReader&) const; \
  template std::string Engine<D, Observer>::checkpoint_layout();
MOLCHAOS_ENGINE_CHECKPOINT(2, NoObserver)
MOLCHAOS_ENGINE_CHECKPOINT(3, NoObserver)
MOLCHAOS_ENGINE_CHECKPOINT(2, ContactStatistics)
MOLCHAOS_ENGINE_CHECKPOINT(3, ContactStatistics)
#undef MOLCHAOS_ENGINE_CHECKPOINT

}  // namespace molchaos::sim

// The event-driven engine for d-dimensional hard spheres (d = 2, 3) in a periodic box.
//
// Design (after Smallenburg, arXiv 2201.01100): one pending event per particle (its earliest
// predicted collision or bookkeeping event) in a calendar queue (event_calendar.hpp);
// particle-local times (a particle's position is stored at the time of its last event); lazy
// invalidation by per-particle collision counters. Neighbour search: cell lists with cells of at
// least sigma and cell-crossing events (disks, dilute spheres), or, for dense spheres, neighbour
// lists with a shell (a bookkeeping event when a particle leaves its shell). Velocities and time
// are kept in internal units that are rescaled as the gas cools, so event times stay O(1); the
// physical time t = t_offset + theta * tau is kept exactly.
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "molchaos/sim/cell_grid.hpp"
#include "molchaos/sim/cell_members.hpp"
#include "molchaos/sim/collision.hpp"
#include "molchaos/sim/collision_model.hpp"
#include "molchaos/sim/collision_observers.hpp"
#include "molchaos/sim/event_calendar.hpp"
#include "molchaos/sim/internal_clock.hpp"
#include "molchaos/sim/neighbour_lists.hpp"
#include "molchaos/sim/parameters.hpp"
#include "molchaos/sim/result.hpp"
#include "molchaos/sim/rng.hpp"
#include "molchaos/sim/sample_observers.hpp"
#include "molchaos/sim/stop_reason.hpp"

namespace molchaos::sim {

class CheckpointWriter;  // checkpoint.hpp
class CheckpointReader;

/// Observer: the per-collision observer (collision_observers.hpp), NoObserver by default.
template <int D, class Observer = NoObserver>
class Engine {
 public:
  /// Builds the initial state: random non-overlapping positions, Maxwell velocities with zero
  /// momentum and T = 1 exactly. Throws std::runtime_error when the density is too high to place
  /// the particles. Does not relax (call relax()). The collision model of the run (rule, TC,
  /// shuffle) is CollisionModel::from(p), fixed for the engine's life. A set `interrupt` ends
  /// the build with InitialStateInterrupted (initial_state.hpp), seen within 2^16 particles of
  /// each step but the sort of the particles by cell.
  explicit Engine(const Parameters& p, const std::atomic<bool>* interrupt = nullptr);

  /// A run with CollisionModel::elastic() for the given collisions per particle, then T rescaled
  /// to 1, time and counters reset to 0. Throws std::invalid_argument (naming
  /// relax_collisions_per_particle and its range here) when that would take more than 1e11
  /// events: in extremely dilute gases, where cell crossings outnumber collisions by far.
  /// With `go_on`, the relaxation pauses every `pause_events` events (a pause changes nothing in
  /// the state) and calls go_on(): when it returns false, relax() returns false at once and the
  /// engine, half relaxed, is fit only to be discarded.
  bool relax(double collisions_per_particle, const std::function<bool()>& go_on = {},
             std::uint64_t pause_events = std::uint64_t{1} << 20);

  /// Refuses (std::invalid_argument naming t_end and its range here) a run from T = 1 to the
  /// physical time t_end that would take more than 1e11 events by the homogeneous gas's
  /// estimate (Haff's law with the first-order cooling rate below restitution 1), as relax()
  /// refuses a relaxation: in extremely dilute gases, where cell crossings outnumber collisions
  /// by far, such a run would go on for days without a word.
  void check_run_length(double t_end) const;

  /// Replaces the state (tests): positions in [0, box)^d, physical velocities; time reset to 0.
  void set_state(const std::vector<double>& positions, const std::vector<double>& velocities);

  enum class Status { reached, paused, stopped };
  /// Processes every event before physical time t (>= time()); then time() == t. Returns paused
  /// after max_events events (for progress reports), stopped when a stop condition fired first
  /// (stop_reason() says which).
  Status advance_to(double t, std::uint64_t max_events = std::numeric_limits<std::uint64_t>::max());
  /// Processes exactly one event (tests). Returns stopped when a stop condition fired.
  Status step();

  double time() const;  // physical
  double box() const { return box_; }
  std::int32_t size() const { return n_; }
  double temperature() const;     // from the velocities, T = <v^2>/d
  double kinetic_energy() const;  // sum v^2 / 2
  std::array<double, D> momentum() const;
  std::uint64_t collisions() const { return collisions_; }
  std::uint64_t events() const { return events_; }
  /// Why the engine stopped (meaningful after Status::stopped), and the CSV text for it.
  StopReason stop_reason() const { return stop_reason_; }
  std::string stop_message() const { return describe(stop_reason_, time(), model_.tc.duration); }
  Observer& observer() { return observer_; }
  const Observer& observer() const { return observer_; }
  int cells_per_side() const { return cells_per_side_; }
  bool uses_neighbour_lists() const { return neighbour_lists_; }

  /// Smallest pair distance now (cell-list search over neighbouring cells); the engine guarantees
  /// it is never below 1 - 1e-10. For tests and the debug check.
  double min_pair_distance() const;
  /// How far below contact (sigma) the closest pair may lie before the overlap checks (the debug
  /// check during a run, the sense check of a restored checkpoint) call it an overlap.
  static constexpr double k_overlap_tolerance = 1e-10;
  /// Throws std::logic_error if a pair is closer than 1 - 1e-10.
  void check_overlaps() const;

  /// Observables at the current time (sample_observers.hpp).
  Sample sample() const { return temperature_sample(*this); }  // contacts: ContactStatistics
  Snapshot snapshot() const { return snapshot_of(*this); }

  /// Read access for observers at sample times, particles in engine order (renumbered by cell):
  /// position now, internal velocity u (physical v = u / clock().theta), original index.
  void position_now(std::int32_t i, double* r) const;
  const double* internal_velocity(std::int32_t i) const { return part_[i].v; }
  std::int32_t original_index(std::int32_t i) const { return id_[i]; }
  const InternalClock& clock() const { return clock_; }
  static constexpr int dimension = D;

  const CollisionModel& collision_model() const { return model_; }

  /// Stop conditions (no physics): after `limit` collisions in all (0 = none), or after the
  /// events they imply (event_limit()), when T falls below t_min (0 = never).
  void set_collision_limit(std::uint64_t limit);
  /// The event bound of the collision limit (0 = none): limit * k_events_per_expected_event
  /// times the events per collision of a homogeneous gas at this density and cell size.
  std::uint64_t event_limit() const { return event_limit_; }
  void set_min_temperature(double t_min) { min_temperature_ = t_min; }
  /// Clears a fired stop condition (max_collisions, min_temperature) so the run can go on.
  void resume() {
    stop_ = false;
  }
  /// Full overlap check every `every` events (0 = never); throws std::logic_error on overlap.
  void set_debug_overlap_check(std::uint64_t every) { debug_check_every_ = every; }

  /// Approximate heap memory held by the engine's arrays, in bytes.
  std::size_t memory_bytes() const;

  /// Checkpoints (checkpoint.hpp, engine_checkpoint.cpp): the whole state that the parameters do
  /// not fix, bit for bit, between advance_to() calls. restore_state() into an engine constructed
  /// from the same parameters (not relaxed) continues exactly as the saved one would have.
  void save_state(CheckpointWriter& out) const;
  void restore_state(CheckpointReader& in);
  /// Refuses (CheckpointError) a restored state without sense: for checkpoint files, which may
  /// have been damaged or edited with their checksum recomputed.
  void check_restored(const CheckpointReader& in) const;
  /// Sizes of the saved records (a checkpoint of another layout is refused).
  static std::string checkpoint_layout();

 private:
  template <class Self, class Archive>
  static void checkpoint_members(Self& self, Archive& archive);
  enum class Outcome { reached, resync, paused, stopped };
  // Prefetch: the engine's data outgrow the cache (outgrows_cache_), so the event loop prefetches
  // records; a template parameter, so that an engine in the cache does not test for it at every
  // event and every pair search.
  template <class Shuffle, bool Prefetch>
  Outcome run_events(double tau_stop, std::uint64_t event_limit, const CollisionModel& model,
                     const Shuffle& shuffle);
  template <class Shuffle>
  Outcome run_events_for(double tau_stop, std::uint64_t event_limit, const CollisionModel& model,
                         const Shuffle& shuffle);
  Outcome dispatch(double tau_stop, std::uint64_t event_limit, const CollisionModel& model);
  Outcome dispatch_shuffle(double tau_stop, std::uint64_t event_limit, const CollisionModel& model);
  template <bool Prefetch, class Shuffle>
  void collide(std::int32_t i, std::int32_t j, const CollisionModel& model,
               const Shuffle& shuffle);
  [[gnu::always_inline]] void prefetch_listed_partners(std::int32_t i) const;
  // Inlined into the event loop, which has most events cross a cell: out of line, its call saved
  // and restored six registers and spilled more (20 of a crossing's 410 instructions in the
  // paper's case).
  template <bool Prefetch>
  [[gnu::always_inline]] void cross_cell(std::int32_t i);
  template <bool Prefetch = false>
  void predict(std::int32_t i);
  // predict(i), then predict(j), for the two particles of a collision (one gather for both where
  // their stencils allow it).
  template <bool Prefetch>
  void predict_pair(std::int32_t i, std::int32_t j);
  // The end of a prediction: i's pending event from its earliest partner (best, partner) and its
  // next bookkeeping event; x its cell coordinates (cells only).
  [[gnu::always_inline]] void schedule(std::int32_t i, double best, std::int32_t partner,
                                       const int* x);
  // The hot helpers carry always_inline here, on their declarations: on the out-of-class
  // definitions alone GCC took it as a hint and kept earliest() and advance_particle() out of line
  // in cross_cell() (3 % more instructions per collision in the paper's case).
  [[gnu::always_inline]] double pair_time(std::int32_t i, std::int32_t j) const;
#if defined(__SSE2__)
  template <bool Wrap>
  [[gnu::always_inline]] __m128d pair_times(std::int32_t i, std::int32_t j1, std::int32_t j2) const;
#endif
  template <bool Wrap>
  [[gnu::always_inline]] std::int32_t keep_neighbours(std::int32_t i, std::int32_t* cand,
                                                      std::int32_t count, std::int32_t lower) const;
  // The members of the Count cells, to candidates_ from index `first` on; returns how many.
  // InRecords: links_in_records_.
  template <int Count, int Unrolled, bool InRecords>
  [[gnu::always_inline]] std::int32_t gather(const int* cells, std::int32_t first = 0) {
    if constexpr (InRecords)
      return members_.gather<Count, Unrolled>(record_links(), cells, candidates_.data() + first);
    else
      return members_.gather<Count, Unrolled>(cell_links_, cells, candidates_.data() + first);
  }
  template <bool Prefetch, bool Wrap = true>
  [[gnu::always_inline]] void earliest(std::int32_t i, std::int32_t* list, std::int32_t count,
                                       double& best, std::int32_t& partner) const;
  // earliest() with the wrap where `wrap` says (a cell on the box boundary, a list near it).
  template <bool Prefetch>
  [[gnu::always_inline]] void search(bool wrap, std::int32_t i, std::int32_t* list,
                                     std::int32_t count, double& best,
                                     std::int32_t& partner) const {
    if (wrap)
      earliest<Prefetch, true>(i, list, count, best, partner);
    else
      earliest<Prefetch, false>(i, list, count, best, partner);
  }
  [[gnu::always_inline]] bool interior_cell(const int* x) const;
  [[gnu::always_inline]] bool list_needs_wrap(std::int32_t i) const;
  [[gnu::always_inline]] void stencil_of(std::int32_t i, const int* x, int* stencil) const;
  [[gnu::always_inline]] void crossing(std::int32_t i, const int* x);
  void shell_exit(std::int32_t i);
  template <bool Prefetch>
  void rebuild_neighbours(std::int32_t i);
  void build_neighbour_lists();
  void collect_neighbours(std::int32_t i, bool only_higher);
  [[gnu::always_inline]] void advance_particle(std::int32_t i);
  void resync();
  void rebuild_events();
  void sort_by_cell();
  void reset_cells();
  void build_cells();
  int cell_of_position(const double* r) const;
  [[gnu::always_inline]] void file_in_cell(std::int32_t i, int c);
  [[gnu::always_inline]] void cell_remove(std::int32_t i);
  void request_stop(StopReason reason);
  double sum_velocity_squared() const;
  void scale_velocities(double factor);  // and recomputes sum_u2_

  // Geometry.
  std::int32_t n_ = 0;
  double box_ = 0, half_box_ = 0;
  int cells_per_side_ = 0;
  double cell_width_ = 0;
  CellCoordinates<D> coords_;  // a cell's coordinates from its index (no per-particle copy)
  std::array<int, D == 2 ? 9 : 27> stencil_offset_{};  // neighbour cells of an interior cell
  // The cells entering the stencil of an interior cell entered along axis a, upwards (u = 1) or
  // downwards (u = 0): slab_offset_[2 a + u].
  std::array<std::array<int, D == 2 ? 3 : 9>, 2 * D> slab_offset_{};
  std::array<int, D> stride_{};  // cell index change per step along each axis
  std::vector<double> wall_;     // cell walls: k * cell_width_, and box_ for the last one

  // The record a pair prediction reads about the partner, one per particle and one 64-byte cache
  // line each (d = 2 uses 48 bytes; unaligned, they straddled two lines every other time, and one
  // line each ran 1.07 to 1.11 times as fast beyond the cache, the paper's case 0.99): an array
  // of small structs rather than separate arrays, because each prediction touches all of these
  // fields of a random partner at once.
  struct alignas(64) Particle {
    double r[D];            // position at the local time t, in [0, box]
    double v[D];            // velocity, internal units
    double t;               // local time (tau) of r
    std::uint32_t counter;  // bumped whenever v changes (lazy invalidation)
    std::int32_t next;      // the next member of its cell, or n (CellMembers)
  };
  // One record more than particles: the end of the cells' lists, which links to itself
  // (CellMembers); particles() leaves it out.
  HugePageVector<Particle> part_;
  std::span<Particle> particles() { return {part_.data(), static_cast<std::size_t>(n_)}; }
  std::span<const Particle> particles() const {
    return {part_.data(), static_cast<std::size_t>(n_)};
  }
  std::vector<std::int32_t> id_;  // the particle's original index (snapshots keep that order)
  // Per-particle pending event, one 32-byte record: the earliest predicted collision (time,
  // partner, partner's counter at prediction), the next bookkeeping event (cell crossing along
  // cross_axis, or shell exit), and the cell the particle is filed in, which only its own events
  // read (the partner's record has room for the cell list's link instead).
  struct EventData {
    double coll_time = std::numeric_limits<double>::infinity();
    double cross_time = std::numeric_limits<double>::infinity();
    std::int32_t partner = -1;
    std::uint32_t partner_counter = 0;
    std::int32_t cross_axis = 0;
    std::int32_t cell = 0;  // the cell it is filed in (cells, or neighbour lists' centre cells)
  };
  HugePageVector<EventData> ev_;
  HugePageVector<double> last_collision_time_;  // tau of the particle's last collision
  // The cells' members, and scratch for a stencil's: room for every particle and one more.
  CellMembers members_;
  // The links of the cells' lists (CellMembers): in the particle records (dilute cells,
  // k_links_in_records in engine.cpp), else in an array of their own, n + 1.
  bool links_in_records_ = false;
  HugePageVector<std::int32_t> cell_links_;
  RecordLinks<Particle> record_links() { return {part_.data()}; }
  // f(links) with the cells' links where they lie: the one place that asks links_in_records_ at
  // run time (the event loop's gathers know it from their template arguments).
  template <class F>
  [[gnu::always_inline]] void with_cell_links(F&& f) {
    if (links_in_records_)
      f(record_links());
    else
      f(cell_links_);
  }
  std::int32_t next_in_cell(std::int32_t i) const {
    return links_in_records_ ? part_[i].next : cell_links_[i];
  }
  std::size_t cells_ = 0;  // number of cells
  std::vector<std::int32_t> candidates_;

  // Neighbour lists (dense spheres only): shell centres and the lists.
  bool neighbour_lists_ = false;
  double shell_ = 0;
  // A particle lists every particle whose shell centre lies within this of its own.
  double list_cutoff() const { return 1.0 + 2.0 * shell_; }
  std::vector<double> center_;
  NeighbourLists lists_;

  // Event calendar: one entry per particle.
  EventCalendar calendar_;
  // Data beyond the cache (decided at construction): wider cells for disks, prefetches, particles
  // numbered along a Hilbert curve.
  bool outgrows_cache_ = true;
  // The constructor's interrupt, while it builds the initial state only: the rebuilds of a
  // running engine (at a rescaling) go on, since a run stops only where it can be saved.
  const std::atomic<bool>* build_interrupt_ = nullptr;

  // Time and units: physical t = t_offset + theta * tau, physical v = u / theta.
  InternalClock clock_;
  double sum_u2_ = 0;  // sum of internal u^2, updated per collision, recomputed at resync
  std::uint64_t collisions_ = 0, events_ = 0;

  // The run's physics, and its stop conditions.
  const CollisionModel model_;
  std::uint64_t collision_limit_ = 0;
  std::uint64_t event_limit_ = 0;  // from collision_limit_ (set_collision_limit)
  double events_per_collision_ = 1;  // of a homogeneous gas (constructor)
  double collision_frequency_ = 1;   // Enskog's, per particle at T = 1 (constructor)
  double restitution_ = 1;
  double min_temperature_ = 0;
  std::uint64_t debug_check_every_ = 0;
  Rng shuffle_rng_;

  // Collapse detector: consecutive collisions closer in time than micro_interval_ (internal
  // units) to a previous collision of one of the pair.
  double micro_interval_ = 0;
  std::uint64_t micro_run_ = 0;
  std::uint64_t stalled_events_ = 0;  // consecutive events at one time without a collision

  Observer observer_;
  bool stop_ = false;
  StopReason stop_reason_ = StopReason::t_end;
};

extern template class Engine<2, NoObserver>;
extern template class Engine<3, NoObserver>;
extern template class Engine<2, ContactStatistics>;
extern template class Engine<3, ContactStatistics>;
extern template class Engine<2, LastCollision>;
extern template class Engine<3, LastCollision>;

}  // namespace molchaos::sim

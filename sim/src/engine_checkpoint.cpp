// The engine's checkpoint: the one list of the members that the parameters do not fix
// (checkpoint.hpp). A translation unit of its own rather than a part of engine.cpp: in engine.cpp
// the extra functions changed GCC's inlining in the hot path (cross_cell, predict) and cost 3 %
// more instructions per collision (bench/engine_counts.sh); here the engine compiles as without it.
#include <string>
#include <type_traits>
#include <utility>

#include "molchaos/sim/checkpoint.hpp"
#include "molchaos/sim/engine.hpp"

namespace molchaos::sim {

// Exactness. The engine's future depends on more than positions and velocities: on the order of
// the events in the calendar's bucket lists and of the members in the cell blocks (ties), on the
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
  // Cell blocks: the aligned origin depends on the allocation's address, so only the blocks are
  // saved; the reader allocates them for the saved capacity first.
  archive(self.capacity_);
  if constexpr (Archive::reading) self.allocate_cells();
  archive.bytes(self.cell_block(0), self.cells_ * (static_cast<std::size_t>(self.capacity_) + 1) *
                                        sizeof(std::int32_t));
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
  if (part_.size() != n || id_.size() != n || ev_.size() != n || last_collision_time_.size() != n ||
      (neighbour_lists_ && center_.size() != n * D))
    in.fail("engine arrays of another size than the parameters' N");
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
  template std::string Engine<D, Observer>::checkpoint_layout();
MOLCHAOS_ENGINE_CHECKPOINT(2, NoObserver)
MOLCHAOS_ENGINE_CHECKPOINT(3, NoObserver)
MOLCHAOS_ENGINE_CHECKPOINT(2, ContactStatistics)
MOLCHAOS_ENGINE_CHECKPOINT(3, ContactStatistics)
#undef MOLCHAOS_ENGINE_CHECKPOINT

}  // namespace molchaos::sim

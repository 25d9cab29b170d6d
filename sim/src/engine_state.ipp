// Part of engine.cpp (included by it: one translation unit, so that its explicit instantiations
// cover these members): the engine's state outside the event loop. Construction (grid sizing,
// initial state), set_state, the relaxation run, the resync that rescales velocities and restarts
// the clock, the rebuild of cells, lists and calendar, cell storage, observables, debug checks.

template <int D, class Observer>
Engine<D, Observer>::Engine(const Parameters& p, const std::atomic<bool>* interrupt)
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
  const std::size_t n = static_cast<std::size_t>(n_);
  part_.assign(n + 1, Particle{});
  id_.resize(n);
  for (std::int32_t i = 0; i < n_; ++i) id_[i] = i;
  ev_.assign(n, EventData{});
  last_collision_time_.assign(n, -k_inf);
  auto cell_width_for = [&](double occupancy) {
    return neighbour_lists_
               ? list_cutoff()
               : std::max(1.0, std::pow(occupancy / p.density, 1.0 / static_cast<double>(D)));
  };
  // Whether the engine's data (with the cells for the cache, their links unless in the records,
  // and a candidate slot per particle) outgrow the cache.
  const auto cells_in_cache = static_cast<std::size_t>(
      std::pow(std::floor(box_ / cell_width_for(k_cell_occupancy<D>)), D));
  const bool links_in_records_in_cache = !neighbour_lists_ && k_links_in_records<D, false>;
  outgrows_cache_ = memory_bytes() + EventCalendar::memory_bytes_for(n_) +
                        CellMembers::memory_bytes_for(cells_in_cache) +
                        (links_in_records_in_cache ? 0 : n + 1) * sizeof(std::int32_t) +
                        n * sizeof(std::int32_t) >
                    k_cache_bytes;
  links_in_records_ = outgrows_cache_ ? !neighbour_lists_ && k_links_in_records<D, true>
                                      : links_in_records_in_cache;
  if (!links_in_records_) cell_links_.assign(n + 1, n_);
  const double width_target = cell_width_for(outgrows_cache_ ? k_cell_occupancy_beyond_cache<D>
                                                             : k_cell_occupancy<D>);
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
  coords_ = CellCoordinates<D>(cells_per_side_);
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

  min_temperature_ = p.min_temperature;
  const double collision_frequency = enskog_collision_frequency(D, p.density, 1.0);
  collision_frequency_ = collision_frequency;
  restitution_ = p.restitution;
  micro_interval_ = k_micro_fraction / collision_frequency;
  {
    // Events per collision of a homogeneous gas (independent of T): the collision, up to four
    // stale predictions of the particles whose velocity changed, and each particle's bookkeeping
    // events: cell crossings at rate D <|v_x|> / width, or shell exits at rate <|v|> / shell.
    const double bookkeeping_rate =
        neighbour_lists_ ? std::sqrt(8.0 / std::numbers::pi) / shell_
                         : D * std::sqrt(2.0 / std::numbers::pi) / cell_width_;
    events_per_collision_ = 5.0 + 2.0 * bookkeeping_rate / collision_frequency;
  }
  set_collision_limit(p.max_collisions);

  std::size_t cells = 1;
  for (int a = 0; a < D; ++a) cells *= static_cast<std::size_t>(cells_per_side_);
  cells_ = cells;
  candidates_.resize(static_cast<std::size_t>(n_) + 1);

  Rng rng(p.seed);
  build_interrupt_ = interrupt;
  const std::vector<double> positions = place_particles<D>(n_, box_, rng, interrupt);
  const std::vector<double> velocities = maxwell_velocities<D>(n_, rng);
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) {
      part_[i].r[a] = positions[D * i + a];
      part_[i].v[a] = velocities[D * i + a];
    }
  sum_u2_ = sum_velocity_squared();
  build_cells();
  rebuild_events();
  build_interrupt_ = nullptr;
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
void Engine<D, Observer>::check_run_length(double t_end) const {
  // Collisions per particle to time t from T = 1 (run_length.hpp: Haff's law to the stop
  // temperature, --min-temperature or the floor of double precision; the TC model's slower
  // cooling), capped by the collision limit. An estimate, in the homogeneous gas.
  const RunLengthGas gas{D, collision_frequency_, restitution_, model_.tc.duration,
                         std::max(min_temperature_, k_temperature_floor)};
  const double limit = collision_limit_ > 0
                           ? 2.0 * static_cast<double>(collision_limit_) / n_
                           : std::numeric_limits<double>::infinity();
  const auto events_to = [&](double t) {
    return std::min(estimated_collisions_per_particle(gas, t), limit) * n_ / 2.0 *
           events_per_collision_;
  };
  const double expected_events = events_to(t_end);
  if (!(expected_events > k_max_run_events)) return;
  const double longest = longest_time_within(events_to, t_end, k_max_run_events);
  char text[240];
  std::snprintf(text, sizeof text,
                " would take %s at this density (an estimated %.2g per collision: the collision, "
                "its stale predictions and the %s)",
                estimated_count(expected_events, "events").c_str(), events_per_collision_,
                neighbour_lists_ ? "shell exits" : "cell crossings");
  throw std::invalid_argument("t_end: " + message_number(t_end) + text + "; allowed range (0, " +
                              message_number(longest) + "] here: a shorter run or a denser gas");
}

template <int D, class Observer>
bool Engine<D, Observer>::relax(double collisions_per_particle, const std::function<bool()>& go_on,
                                std::uint64_t pause_events) {
  const auto target = static_cast<std::uint64_t>(
      std::ceil(collisions_per_particle * static_cast<double>(n_) / 2.0));
  // A relaxation counts collisions, not time: in a gas so dilute that a particle crosses many
  // cells between collisions, its events grow as the crossings do (about 1/sqrt(n) per
  // collision), and 20 collisions per particle at n = 1e-20 would take days without a word.
  const double expected_events = static_cast<double>(target) * events_per_collision_;
  if (expected_events > k_max_run_events) {
    const double most = k_max_run_events / events_per_collision_ * 2.0 / n_;
    auto estimate = [](double x) {  // two digits: an estimate
      char text[32];
      std::snprintf(text, sizeof text, "%.2g", x);
      return std::string(text);
    };
    throw std::invalid_argument(
        "relax_collisions_per_particle: " + message_number(collisions_per_particle) +
        " collisions per particle would take " + estimated_count(expected_events, "events") +
        " at this density (" + estimate(events_per_collision_) +
        " per collision, most of them cell crossings); allowed range [0, " +
        message_number(most) + "] here: relax less (0: none) or simulate a denser gas");
  }
  const std::uint64_t limit = collision_limit_;
  const double t_min = min_temperature_;
  min_temperature_ = 0;
  if (target > 0) {
    collision_limit_ = collisions_ + target;
    for (;;) {
      const std::uint64_t event_limit =
          go_on ? events_ + pause_events : std::numeric_limits<std::uint64_t>::max();
      const Outcome outcome = dispatch(k_inf, event_limit, CollisionModel::elastic());
      if (outcome == Outcome::resync) {
        resync();
        continue;
      }
      if (outcome != Outcome::paused) break;
      if (go_on && !go_on()) return false;
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
  for (auto& particle : particles()) particle.t = 0;
  std::fill(last_collision_time_.begin(), last_collision_time_.end(), -k_inf);
  collisions_ = events_ = 0;
  micro_run_ = 0;
  stalled_events_ = 0;
  observer_ = Observer{};
  rebuild_events();
  return true;
}

template <int D, class Observer>
void Engine<D, Observer>::position_now(std::int32_t i, double* r) const {
  const double dt = clock_.now - part_[i].t;
  for (int a = 0; a < D; ++a) r[a] = part_[i].r[a] + part_[i].v[a] * dt;
}

template <int D, class Observer>
void Engine<D, Observer>::build_neighbour_lists() {
  center_.resize(static_cast<std::size_t>(n_) * D);
  int capacity = 0;  // 0: keep the capacity the lists grew to
  if (lists_.capacity() == 0) {
    const double cutoff = list_cutoff();
    const double expected = 4.0 / 3.0 * std::numbers::pi * cutoff * cutoff * cutoff *
                            static_cast<double>(n_) / std::pow(box_, 3);
    capacity = static_cast<int>(std::ceil(2 * expected + 8));
  }
  lists_.reset(n_, capacity);
  for (std::int32_t i = 0; i < n_; ++i)
    for (int a = 0; a < D; ++a) center_[D * i + a] = part_[i].r[a];
  for (std::int32_t i = 0; i < n_; ++i) collect_neighbours(i, true);
}

template <int D, class Observer>
void Engine<D, Observer>::set_collision_limit(std::uint64_t limit) {
  collision_limit_ = limit;
  const double events = static_cast<double>(limit) * events_per_collision_ *
                        static_cast<double>(k_events_per_expected_event);
  event_limit_ = events < 1.8e19 ? static_cast<std::uint64_t>(events) : 0;
}

template <int D, class Observer>
void Engine<D, Observer>::resync() {
  for (std::int32_t i = 0; i < n_; ++i) advance_particle(i);
  sum_u2_ = sum_velocity_squared();
  if (remove_momentum_drift<D>(particles(), sum_u2_, [](Particle& p) { return p.v; }))
    sum_u2_ = sum_velocity_squared();
  const double temperature = sum_u2_ / (static_cast<double>(n_) * D);
  double factor = 1.0;
  // Physical T = T_internal / theta^2: at the floor of double precision the run stops (no
  // further rescaling, which would overflow theta^2).
  if (!(temperature / clock_.theta / clock_.theta >= k_temperature_floor))
    request_stop(StopReason::temperature_floor);
  else if (temperature < k_rescale_temperature && temperature > 0) {
    factor = 1.0 / std::sqrt(temperature);
    scale_velocities(factor);
  }
  for (auto& t : last_collision_time_) t = clock_.restarted(t, factor);
  for (auto& particle : particles()) particle.t = 0;
  clock_.restart(factor);
  rebuild_events();
}

// Renumbers the particles cell by cell (within a cell, in their old order) so that neighbours sit
// close in memory: a prediction reads its partners from a few cache lines instead of random ones.
// When the data outgrow the cache the cells are taken along a Hilbert curve (hilbert_curve.hpp),
// which keeps the particles of a stencil's cells numbered close together, where the row-by-row
// order puts each row of the stencil a row of cells apart; in the cache the row-by-row order is
// kept (the numbering changes the rounding of sums over the particles, hence trajectories).
// Rebuilds the cell lists. Only called with every particle at clock_.now and all predictions
// about to be redone.
template <int D, class Observer>
void Engine<D, Observer>::sort_by_cell() {
  const std::size_t n = static_cast<std::size_t>(n_);
  std::vector<std::int32_t> order(n);  // new number -> old number
  {
    const int bits = hilbert_bits(cells_per_side_);
    std::vector<std::uint64_t> key(n);
    for (std::size_t i = 0; i < n; ++i) {
      stop_build_if_interrupted(build_interrupt_, static_cast<std::int64_t>(i));
      int x[D];
      coords_(ev_[i].cell, x);
      key[i] = outgrows_cache_ ? hilbert_index<D>(x, bits) : static_cast<std::uint64_t>(ev_[i].cell);
      order[i] = static_cast<std::int32_t>(i);
    }
    std::sort(order.begin(), order.end(), [&key](std::int32_t a, std::int32_t b) {
      return key[a] < key[b] || (key[a] == key[b] && a < b);
    });
  }
  // Permuted in place, cycle by cycle (a sorted copy of the arrays would raise the peak memory
  // of a large run by 60 bytes per particle): position k takes the particle order[k].
  for (std::size_t start = 0; start < n; ++start) {
    stop_build_if_interrupted(build_interrupt_, static_cast<std::int64_t>(start));
    if (order[start] < 0) continue;
    const Particle particle = part_[start];
    const EventData event = ev_[start];  // its cell; the rest is predicted again
    const double last = last_collision_time_[start];
    const std::int32_t id = id_[start];
    for (std::size_t k = start;;) {
      const auto from = static_cast<std::size_t>(order[k]);
      order[k] = -1;  // placed
      if (from == start) {
        part_[k] = particle;
        ev_[k] = event;
        last_collision_time_[k] = last;
        id_[k] = id;
        break;
      }
      part_[k] = part_[from];
      ev_[k] = ev_[from];
      last_collision_time_[k] = last_collision_time_[from];
      id_[k] = id_[from];
      k = from;
    }
  }
  // Filed from the last particle to the first: each cell lists its members in increasing index.
  reset_cells();
  for (std::int32_t i = n_ - 1; i >= 0; --i) file_in_cell(i, ev_[i].cell);
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
      ev_[i].cell = cell_of_position(part_[i].r);
    }
  sort_by_cell();
  if (neighbour_lists_) build_neighbour_lists();
  // Calendar buckets: about one event per bucket. The bucket width comes from the mean time to
  // the particles' next events (measured after predicting with a provisional width).
  const std::int64_t buckets = 4 * static_cast<std::int64_t>(n_);  // window ~ 4 mean waits
  double width = calendar_.bucket_width();
  for (int pass = 0; pass < 2; ++pass) {
    calendar_.reset(n_, clock_.now, width, buckets);
    for (std::int32_t i = 0; i < n_; ++i) {
      stop_build_if_interrupted(build_interrupt_, i);
      if (outgrows_cache_)
        predict<true>(i);  // the cells' links where predict<true> looks for them
      else
        predict<false>(i);
    }
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

// Empty cells for particles 0 .. n-1, their lists ended by n.
template <int D, class Observer>
void Engine<D, Observer>::reset_cells() {
  with_cell_links([&](auto&& links) { members_.reset(cells_, n_, links); });
}

template <int D, class Observer>
void Engine<D, Observer>::build_cells() {
  reset_cells();
  for (std::int32_t i = n_ - 1; i >= 0; --i) {
    for (int a = 0; a < D; ++a) {
      double& x = part_[i].r[a];
      if (x < 0) x += box_;
      if (x >= box_) x -= box_;
    }
    file_in_cell(i, cell_of_position(part_[i].r));
  }
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::file_in_cell(std::int32_t i, int c) {
  ev_[i].cell = c;
  with_cell_links([&](auto&& links) { members_.add(links, i, c); });
}

template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::cell_remove(std::int32_t i) {
  with_cell_links([&](auto&& links) { members_.remove(links, i, ev_[i].cell); });
}

template <int D, class Observer>
double Engine<D, Observer>::sum_velocity_squared() const {
  double sum = 0;
  for (const auto& particle : particles())
    for (double v : particle.v) sum += v * v;
  return sum;
}

template <int D, class Observer>
void Engine<D, Observer>::scale_velocities(double factor) {
  for (auto& particle : particles())
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
    int x[D];
    coords_(ev_[i].cell, x);
    neighbour_cells<D>(x, cells_per_side_, stencil);
    for (int s = 0; s < stencil_size<D>(); ++s)
      for (std::int32_t j = members_.first(stencil[s]); j != members_.end(); j = next_in_cell(j)) {
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
  return bytes(part_) + bytes(id_) + bytes(ev_) + bytes(last_collision_time_) +
         members_.memory_bytes() + bytes(candidates_) + bytes(center_) + lists_.memory_bytes() +
         calendar_.memory_bytes();
}

// Part of engine.cpp (included by it, one translation unit): the pair search of a prediction,
// the hot inner loop of the engine. The contact time of two particles (scalar reference and the
// SSE2 version for two partners at once), the gathering of a stencil's cell members, the
// branch-free selection of the earliest partner, and the shared search of a collision's two
// particles.

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
// most in the sign of a zero b, which both treat as "not approaching". Wrap = false leaves the
// wrap out (12 of a pass's operations in d = 2): for the stencil of a cell off the box boundary,
// whose members lie less than two cell widths, so less than half the box, from i along every axis,
// where the minimum image is the plain difference.
template <int D, class Observer>
template <bool Wrap>
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
    if constexpr (Wrap) {
      d = _mm_sub_pd(d, _mm_and_pd(_mm_cmpgt_pd(d, half), box));
      d = _mm_add_pd(d, _mm_and_pd(_mm_cmplt_pd(d, minus_half), box));
    }
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

// The earliest collision of i (at clock_.now) with the listed candidates after `best`: updates
// best and partner; Wrap = false when no candidate can be nearer through the periodic boundary
// (pair_times()). Branch-free selection; candidates in list order, the first of equal times wins.
// list[count] must be writable: an odd list is padded there with i itself (its pair time with
// itself is +inf), so that one loop of pairs does all, without a remainder loop whose trip count
// the branch predictor would have to guess.
template <int D, class Observer>
template <bool Prefetch, bool Wrap>
[[gnu::always_inline]] inline void Engine<D, Observer>::earliest(std::int32_t i, std::int32_t* list,
                                                       std::int32_t count, double& best,
                                                       std::int32_t& partner) const {
  double b = best;
  std::int32_t p = partner;
  if constexpr (Prefetch)
    for (std::int32_t k = 0; k < count; ++k) __builtin_prefetch(&part_[list[k]]);
#if defined(__SSE2__)
  list[count] = i;
  for (std::int32_t k = 0; k < count; k += 2) {  // two partners per pass, one in each half
    const std::int32_t j1 = list[k], j2 = list[k + 1];
    double t[2];
    _mm_storeu_pd(t, pair_times<Wrap>(i, j1, j2));
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

// The candidates whose shell centre lies within the list cutoff of i's, compacted to the front of
// cand in candidate order; i itself and every j <= lower are left out (lower = i for the initial
// build, which files each pair once, else -1). Returns how many. Branch-free (about one
// candidate in six is kept); with SSE2 two candidates per pass, the components regrouped as in
// pair_times() and the sum in the scalar order, so the kept set is the same. cand[count] must be
// writable: an odd list is padded there with i. Wrap = false for the stencil of a cell off the
// box boundary with 4 cells or more a side, whose centres lie less than half the box from i's.
template <int D, class Observer>
template <bool Wrap>
[[gnu::always_inline]] inline std::int32_t Engine<D, Observer>::keep_neighbours(
    std::int32_t i, std::int32_t* cand, std::int32_t count, std::int32_t lower) const {
  const double cutoff = list_cutoff() + 1e-9;  // slack for rounding at the shell boundary
  const double cutoff2 = cutoff * cutoff;
  const double* ci = &center_[D * i];
  std::int32_t found = 0;
  auto keep = [&](std::int32_t j, int within) {
    cand[found] = j;
    found += within & static_cast<int>(j != i) & static_cast<int>(j > lower);
  };
#if defined(__SSE2__)
  const __m128d half = _mm_set1_pd(half_box_), minus_half = _mm_set1_pd(-half_box_);
  const __m128d box = _mm_set1_pd(box_), limit = _mm_set1_pd(cutoff2);
  cand[count] = i;
  for (std::int32_t k = 0; k < count; k += 2) {
    const std::int32_t j1 = cand[k], j2 = cand[k + 1];
    __m128d d2 = _mm_setzero_pd();
    for (int a = 0; a < D; ++a) {
      const __m128d cj = _mm_loadh_pd(_mm_load_sd(&center_[D * j1 + a]), &center_[D * j2 + a]);
      __m128d d = _mm_sub_pd(_mm_set1_pd(ci[a]), cj);
      if constexpr (Wrap) {
        d = _mm_sub_pd(d, _mm_and_pd(_mm_cmpgt_pd(d, half), box));
        d = _mm_add_pd(d, _mm_and_pd(_mm_cmplt_pd(d, minus_half), box));
      }
      d2 = a == 0 ? _mm_mul_pd(d, d) : _mm_add_pd(d2, _mm_mul_pd(d, d));
    }
    const int within = _mm_movemask_pd(_mm_cmplt_pd(d2, limit));
    keep(j1, within & 1);
    keep(j2, within >> 1);
  }
#else
  for (std::int32_t k = 0; k < count; ++k) {
    const std::int32_t j = cand[k];
    double d2 = 0;
    for (int a = 0; a < D; ++a) {
      double d = ci[a] - center_[D * j + a];
      if constexpr (Wrap) {
        d -= d > half_box_ ? box_ : 0.0;
        d += d < -half_box_ ? box_ : 0.0;
      }
      d2 += d * d;
    }
    keep(j, static_cast<int>(d2 < cutoff2));
  }
#endif
  return found;
}

// Whether i's neighbour list needs the periodic wrap in its pair predictions. Not when i's shell
// centre lies at least cutoff + shell inside every face of the box: a listed partner's centre,
// within the cutoff of i's, is then stored as the image nearest i (centres lie in [0, box)), and
// both particles lie within a shell of their centres, so every separation is the plain difference
// and shorter than half the box (cutoff + 2 shell < box / 2).
template <int D, class Observer>
[[gnu::always_inline]] inline bool Engine<D, Observer>::list_needs_wrap(std::int32_t i) const {
  const double margin = list_cutoff() + shell_ + 1e-9;
  bool inside = true;
  for (int a = 0; a < D; ++a) {
    const double c = center_[D * i + a];
    inside = inside & (c >= margin) & (c <= box_ - margin);
  }
  return !inside;
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

// The 3^D cells around i's cell (i's cell included), x its coordinates.
template <int D, class Observer>
[[gnu::always_inline]] inline void Engine<D, Observer>::stencil_of(std::int32_t i, const int* x,
                                                                   int* stencil) const {
  if (interior_cell(x)) {
    for (int s = 0; s < stencil_size<D>(); ++s) stencil[s] = ev_[i].cell + stencil_offset_[s];
  } else {
    neighbour_cells<D>(x, cells_per_side_, stencil);
  }
}

// The two particles of a collision touch, so their cells are the same or neighbours and their
// stencils overlap. Where the cells are the same, or neighbours along the last axis (the
// outermost of a stencil's order) without the periodic wrap between them, each stencil is a
// contiguous run of the union's members gathered once: the lower cell's stencil, its lowest layer
// first, then the layer above it that only the upper cell's stencil holds. Each particle then
// meets its candidates in the order of its own stencil and selects the partner predict() would;
// the searches only read records (collide() has moved both particles to clock_.now), so their
// order does not matter, and the pending events are filed i first, as by predict(i), predict(j).
// The paper's case: 4 collisions in 5 share a gather (isotropic contacts, cells of 3.2 sigma).
// Other pairs (neighbours along another axis or across the box boundary) and neighbour lists
// take two predictions.
template <int D, class Observer>
template <bool Prefetch>
void Engine<D, Observer>::predict_pair(std::int32_t i, std::int32_t j) {
  const int layer = stride_[D - 1];
  const int step = ev_[j].cell - ev_[i].cell;  // 0 or +-layer only for the cases above
  if (neighbour_lists_ || (step != 0 && step != layer && step != -layer)) {
    predict<Prefetch>(i);
    predict<Prefetch>(j);
    return;
  }
  assert((links_in_records_ == k_links_in_records<D, Prefetch>));
  constexpr int unrolled = k_branch_free_members<D, Prefetch>;
  constexpr bool in_records = k_links_in_records<D, Prefetch>;
  const std::int32_t lo = step < 0 ? j : i, hi = step < 0 ? i : j;
  int x_lo[D], x_hi[D];
  coords_(ev_[lo].cell, x_lo);
  coords_(ev_[hi].cell, x_hi);
  int cells[stencil_size<D>() + slab_size<D>()];
  stencil_of(lo, x_lo, cells);
  const std::int32_t lowest = gather<slab_size<D>(), unrolled, in_records>(cells);
  const std::int32_t lo_end =
      lowest + gather<stencil_size<D>() - slab_size<D>(), unrolled, in_records>(
                   cells + slab_size<D>(), lowest);
  const std::int32_t hi_begin = step == 0 ? 0 : lowest;
  std::int32_t hi_end = lo_end;
  if (step != 0) {
    int* above = cells + stencil_size<D>();
    if (interior_cell(x_hi)) {
      const int* offset = slab_offset_[2 * (D - 1) + 1].data();
      for (int s = 0; s < slab_size<D>(); ++s) above[s] = ev_[hi].cell + offset[s];
    } else {
      slab_cells<D>(x_hi, cells_per_side_, D - 1, 1, above);
    }
    hi_end += gather<slab_size<D>(), unrolled, in_records>(above, lo_end);
  }
  std::int32_t* cand = candidates_.data();
  // hi's search first: lo's pads its list at lo_end, among hi's candidates.
  double best_lo = k_inf, best_hi = k_inf;
  std::int32_t partner_lo = -1, partner_hi = -1;
  search<Prefetch>(!interior_cell(x_hi), hi, cand + hi_begin, hi_end - hi_begin, best_hi,
                   partner_hi);
  search<Prefetch>(!interior_cell(x_lo), lo, cand, lo_end, best_lo, partner_lo);
  if (lo == i) {
    schedule(i, best_lo, partner_lo, x_lo);
    schedule(j, best_hi, partner_hi, x_hi);
  } else {
    schedule(i, best_hi, partner_hi, x_hi);
    schedule(j, best_lo, partner_lo, x_lo);
  }
}

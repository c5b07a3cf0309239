// hypergas/edmd/engine.hpp -- event-driven molecular dynamics of hard spheres in D dims.
//
// Public API (what the command line calls):
//
//   edmd::Config cfg;  cfg.n = 32000; cfg.packing = 0.26; cfg.seed = 7;
//   cfg.init = InitialState::maxwell;  cfg.debug_overlap = false;
//   edmd::Engine<3> e(cfg);              // lattice start (+ LS compression if needed)
//   e.run_until(t, &observer, every);    // observer called at t0, t0+every, ... <= t
//   e.time(); e.collisions();            // time in sigma sqrt(m/kT); collision count
//   e.pressure_Z();                      // PV/(N kT) from the collision virial
//   e.collision_rate();                  // collisions per particle per unit time
//   e.mean_free_time();                  // 1 / collision_rate
//   e.temperature();  e.particles();  e.bytes_per_particle();
//   e.reset_observables();               // start a new measurement window now
//   edmd::jamming_packing(D)             // (box.hpp) largest --packing accepted
//
// Engine<D, F, Queue>: F must have positions; F.species (or F.masses) gives two masses,
// F.radii two sizes (Config::size_ratio). Queue is the event queue: CalendarQueue (default,
// calendar_queue.hpp) or EventQueue (the indexed binary heap, event_queue.hpp); both hold one
// entry per particle and give identical trajectories up to ties. Units: sigma = 1, m = 1,
// kT = 1 by default.
//
// Algorithm: each particle keeps a local clock (its position is stored at the time of its
// last event), its two earliest predicted pair events (time, partner, partner's event
// counter) and one cell-crossing time; the earliest is its key in the event queue. A
// pair event is valid only if the partner's counter is unchanged (lazy invalidation); when
// the first is invalid the runner-up is used if still valid, else the particle is scanned
// again. Which stencil cells a prediction scans (Config::Scan): in D >= 3 the horizon scan
// (scan_horizon) skips every cell farther than a contact distance from the box bounding the
// particle's path to its next crossing, and a crossing rescans; in D <= 2 the slab scan
// takes the whole stencil and a crossing keeps still-valid pair events and scans only the
// newly adjacent slab of cells. From D >= 4 the filtered scan also keeps, per particle, the
// box bounding its path to its next crossing (PBox, 16 bytes) and per cell the union of its
// members' boxes: a stencil cell, then a member, whose box is farther than a contact
// distance from the scanner's is skipped (drop_far_cells, gather_filtered). A scan's pair
// times are computed in a batch, two at a time and without data-dependent branches
// (earliest_pairs, contact_times). Measured (3D, eta = 0.26; 6D, eta = 0.05): horizon/slab
// 1.08-1.18x in 3D, 1.26-1.46x in 5D; in 6D ~1130 (slab), 642 (horizon) and 63 (filtered)
// pair times per collision, and filtered/horizon about 2.3x; equal in 3D, where the
// filter is off. An event costs O(neighbours) with the calendar queue (O(neighbours +
// log N) with the heap; measured at 3D, eta = 0.26: equal speed at N <= 256000, the
// calendar 1.05-1.3x the heap at N = 1e6 on a 32 MB L3, equal where the L3 holds it all).
//
// Memory: position, clock and velocity of a particle are one record (one cache line in
// 3D, particles.hpp); a scan first lists its candidates and prefetches their records,
// then computes, so that the ~13 records of a 3D scan arrive together; and every
// Config::reorder_interval collisions per particle the particles are renumbered in
// Z-order of their cells (reorder()), so that neighbours stay near in memory. None of this
// changes a trajectory (a unit test checks bit-for-bit equality with and without).
//
// Correctness argument for one event per particle: if i and j will collide next among all
// their events, the one of them whose trajectory was predicted last scanned the other with
// both current trajectories, so its key is at most that collision time.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "hypergas/collision.hpp"
#include "hypergas/edmd/box.hpp"
#include "hypergas/edmd/cells.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/edmd/calendar_queue.hpp"
#include "hypergas/edmd/event_queue.hpp"
#include "hypergas/edmd/lattice.hpp"
#include "hypergas/edmd/pair_time.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"

namespace hypergas::edmd {

template <class E>
void compress(E& e, double target_scale, const Config& cfg);

/// Hard-sphere EDMD engine (see the file comment). D in 1..6.
template <int D, Features F = Features{.positions = true}, class Queue = CalendarQueue>
class Engine {
  static_assert(F.positions, "the EDMD engine needs Features{.positions = true}");

 public:
  using Store = Particles<D, F>;
  /// Config::Scan::automatic uses the horizon scan from this dimension up (measured below),
  /// and filters candidates by their path boxes from auto_filter_dim up.
  static constexpr int auto_horizon_dim = 3;
  static constexpr int auto_filter_dim = 4;

  /// Places cfg.n particles on a lattice at packing cfg.packing, draws velocities in state
  /// cfg.init, compresses (Lubachevsky–Stillinger) if the lattice is too tight, and predicts
  /// all events. Throws InvalidInput for bad parameters or a box below 2 diameters.
  explicit Engine(const Config& cfg)
      : debug_(cfg.debug_overlap),
        horizon_(cfg.scan == Scan::horizon || cfg.scan == Scan::filtered ||
                 (cfg.scan == Scan::automatic && D >= auto_horizon_dim)),
        filter_(cfg.scan == Scan::filtered ||
                (cfg.scan == Scan::automatic && D >= auto_filter_dim)) {
    if (cfg.n < 2) throw InvalidInput("EDMD needs at least 2 particles");
    if (cfg.n > 0xFFFFFFF0ull) throw InvalidInput("EDMD: too many particles");
    if constexpr (D >= 2) check_packing(D, cfg.packing);
    else if (!(cfg.packing > 0.0 && cfg.packing < 1.0))
      throw InvalidInput("1D packing fraction must be in (0, 1)");
    if (!(cfg.size_ratio > 0.0 && std::isfinite(cfg.size_ratio)))
      throw InvalidInput("size ratio must be finite and > 0");
    const std::size_t n = cfg.n;
    p_.resize(n);
    Rng rng(cfg.seed, 0);
    Rng vrng = rng.split(1);
    initialize_velocities(p_, cfg.init, vrng, cfg.init_params);
    double vol = 0.0;
    const std::size_t n1 = static_cast<std::size_t>(
        std::llround(cfg.init_params.fraction * static_cast<double>(n)));
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (F.radii) p_.set_radius(i, i < n - n1 ? 0.5 : 0.5 * cfg.size_ratio);
      vol += ball_volume(D, base_contact(i, i));
    }
    (void)n1;
    L_ = std::pow(vol / cfg.packing, 1.0 / D);
    max_base_ = 0.0;
    for (std::size_t i = 0; i < n; ++i) max_base_ = std::max(max_base_, base_contact(i, i));
    Rng lrng = rng.split(2);
    const LatticeSites<D> sites = lattice_sites<D>(n, L_, lrng);
    for (std::size_t i = 0; i < n; ++i) p_.position(i) = sites.x[i];
    image_.assign(n * D, 0);
    cnt_.assign(n, 0);
    ev_.assign(n, Ev{});
    id_.resize(n);
    slot_.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) id_[i] = slot_[i] = i;
    reorder_every_ = cfg.reorder_interval > 0.0
                         ? static_cast<std::uint64_t>(cfg.reorder_interval * 0.5 * n) + 1
                         : ~std::uint64_t{0};
    // Lattice gaps below 10% of a diameter make the occupied sites a near-contact network
    // (in 5D, 26% of the D_5 sites give ~10 touching neighbours each) whose collision rate
    // diverges under compression: N = 1000, eta = 0.14 did 3e6 collisions by t = 2e-8.
    // Such starts shrink the diameters to 90% of the site spacing and let the
    // Lubachevsky-Stillinger compression (compression.hpp) grow them back.
    const double fit = sites.nearest / max_base_;
    scale_ref_ = fit >= 1.1 ? 1.0 : 0.9 * fit;
    rebuild();
    if (scale_ref_ < 1.0) {
      compress(*this, 1.0, cfg);
      restart_clock();  // the compression is preparation: the run starts at t = 0
    }
    reset_observables();
  }

  // ---- running ------------------------------------------------------------------------
  /// Processes all events up to time t (sigma sqrt(m/kT)). If obs is non-null it is called
  /// at times now, now + every, ... <= t with velocities and unwrapped positions.
  void run_until(double t, Observer* obs = nullptr, double every = 0.0) {
    if (obs && !(every > 0.0)) throw InvalidInput("sampling interval must be > 0");
    if (!(t >= now_))
      throw InvalidInput("run_until(" + std::to_string(t) + "): the gas is already at t = " +
                         std::to_string(now_));
    double next_sample = obs ? now_ : never;
    std::uint64_t k = 0;
    const double t0 = now_;
    for (;;) {
      const double te = q_.top_time();
      while (obs && next_sample <= t && next_sample <= te) {
        sample(next_sample, *obs);
        next_sample = t0 + static_cast<double>(++k) * every;
      }
      if (te > t) break;
      step();
    }
    now_ = t;
  }
  /// Processes exactly one event (a collision, a cell crossing or a re-prediction).
  void step() {
    if (ncoll_ >= next_reorder_) reorder();
    const std::uint32_t i = q_.top();
    now_ = q_.top_time();
    Ev& e = ev_[i];
    if (e.t_pair <= e.t_cross) {
      const std::int32_t j = e.partner;
      if (j < 0 || cnt_[j] != e.pcount) {
        ++nstale_;
        if (e.partner2 >= 0 && cnt_[e.partner2] == e.pcount2) {
          // The runner-up of i's last scan is still valid: every pair with a particle that
          // has not changed course since that scan is at least that late, and a pair with
          // one that has was scanned by it (see the file comment). No rescan needed.
          e.t_pair = e.t_pair2, e.partner = e.partner2, e.pcount = e.pcount2;
          e.t_pair2 = never, e.partner2 = -1;
          q_.update(i, std::min(e.t_pair, e.t_cross));
          return;
        }
        advance(i);
        predict(i);
        return;
      }
      collide(i, static_cast<std::uint32_t>(j));
      predict(i);
      predict(static_cast<std::uint32_t>(j));
      if (debug_) check_overlaps();
    } else {
      ++ncross_;
      cross(i);
      if (debug_) check_overlaps();
    }
  }

  // ---- observables --------------------------------------------------------------------
  double time() const { return now_; }
  std::uint64_t collisions() const { return ncoll_; }
  /// Events other than collisions since the start: cell crossings, and stale pair events
  /// (the partner collided with someone else first) that only cost a re-prediction.
  std::uint64_t crossings() const { return ncross_; }
  std::uint64_t stale_events() const { return nstale_; }
  /// Pair times computed by the scans since the start (the cost measure of the cell lists).
  std::uint64_t pairs_tested() const { return npairs_; }
  /// Predictions (neighbour scans) since the start: after collisions, crossings and stale
  /// events whose runner-up was no longer valid.
  std::uint64_t scans() const { return nscan_; }
  std::size_t size() const { return p_.size(); }
  double box_side() const { return L_; }
  /// Packing fraction at the current diameters.
  double packing() const {
    double v = 0.0;
    for (std::size_t i = 0; i < p_.size(); ++i) v += ball_volume(D, contact(i, i));
    return v / std::pow(L_, D);
  }
  /// Kinetic temperature kT = sum m v^2 / (D N) (energy units).
  double temperature() const { return 2.0 * kinetic_energy() / (D * static_cast<double>(size())); }
  double kinetic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < size(); ++i) e += p_.mass(i) * p_.velocity(i).squaredNorm();
    return 0.5 * e;
  }
  Vec<D> momentum() const {
    Vec<D> m = Vec<D>::Zero();
    for (std::size_t i = 0; i < size(); ++i) m += p_.mass(i) * p_.velocity(i);
    return m;
  }
  /// Starts a new measurement window for Z, collision rate and mean free time.
  void reset_observables() {
    t_meas_ = now_;
    coll_meas_ = ncoll_;
    virial_ = 0.0;
  }
  /// Collisions in the current window, and its sum of r_ij . dp_i (energy units * time...).
  std::uint64_t window_collisions() const { return ncoll_ - coll_meas_; }
  double window_time() const { return now_ - t_meas_; }
  double virial_sum() const { return virial_; }
  /// Reduced pressure Z = PV/(N kT) = 1 + sum_coll r_ij . dp_i / (D N kT t) over the window.
  double pressure_Z() const {
    return 1.0 + virial_ / (D * static_cast<double>(size()) * temperature() * window_time());
  }
  /// Collisions per particle per unit time in the window (2 per collision).
  double collision_rate() const {
    return 2.0 * static_cast<double>(window_collisions()) /
           (static_cast<double>(size()) * window_time());
  }
  /// Mean free time per particle, 1 / collision_rate (sigma sqrt(m/kT)).
  double mean_free_time() const { return 1.0 / collision_rate(); }
  /// The particle store in memory order: the engine renumbers particles by position from
  /// time to time (reorder()); original_id(i) is the number particle i started with, and
  /// snapshots (run_until's observer) always use the original numbering.
  const Store& particles() const { return p_; }
  std::size_t original_id(std::size_t i) const { return id_[i]; }
  /// Unwrapped position of particle a (original numbering) at the current time (length).
  Vec<D> unwrapped_position(std::size_t a) const {
    const std::size_t i = slot_[a];
    Vec<D> x = p_.position(i) + p_.velocity(i) * (now_ - p_.local_time(i));
    for (int k = 0; k < D; ++k) x[k] += L_ * image_[i * D + k];
    return x;
  }
  /// Persistent bytes per particle of the whole engine state.
  double bytes_per_particle() const {
    const double n = static_cast<double>(size());
    return p_.bytes_per_particle() + D * sizeof(std::int32_t) + sizeof(Ev) +
           3 * sizeof(std::uint32_t) + Queue::bytes_per_particle() +
           cells_.bytes_per_particle(size()) +
           (filter_ ? sizeof(PBox) * (1.0 + static_cast<double>(cbox_.size()) / n) : 0.0);
  }
  int cells_per_side() const { return cells_.per_side(); }
  /// Whether predictions use the horizon scan (Config::Scan) rather than slab scans, and
  /// whether they filter candidates by path boxes (Scan::filtered).
  bool horizon_scan() const { return horizon_; }
  bool path_filter() const { return filter_; }
  /// Current diameter scale (1 after compression) and its growth rate (per unit time).
  double diameter_scale() const { return scale_ref_ + rate_ * (now_ - t_scale_); }

  /// Brings every particle to the current time, rebuilds cells for the current diameters
  /// (growth rate `rate` from now on), rescales velocities to kinetic temperature kT if
  /// kT > 0, sets the diameter scale to `exact_scale` if > 0 (only to remove round-off), and
  /// re-predicts every event. Used by the LS compression (compression.hpp).
  void restart(double rate, double kT = 0.0, double exact_scale = 0.0) {
    scale_ref_ = exact_scale > 0.0 ? exact_scale : diameter_scale();
    t_scale_ = now_;
    rate_ = rate;
    for (std::uint32_t i = 0; i < size(); ++i) advance(i);  // before velocities change
    if (kT > 0.0) {
      const double f = std::sqrt(kT / temperature());
      for (std::size_t i = 0; i < size(); ++i) p_.velocity(i) *= f;
    }
    rebuild();
  }
  /// Moves the origin of time to now: t = 0 and zero collisions afterwards (the state and
  /// the diameters are unchanged; every event is predicted again).
  void restart_clock() {
    for (std::uint32_t i = 0; i < size(); ++i) advance(i);
    scale_ref_ = diameter_scale();
    for (std::size_t i = 0; i < size(); ++i) p_.local_time(i) = 0.0;
    now_ = t_scale_ = 0.0;
    ncoll_ = ncross_ = nstale_ = npairs_ = nscan_ = next_reorder_ = 0;
    rebuild();
  }
  /// Turns the per-event all-pairs overlap check on or off; returns the previous setting.
  bool set_debug(bool on) {
    const bool old = debug_;
    debug_ = on;
    return old;
  }
  /// Largest diameter scale the current cells allow (cell width / largest base diameter).
  /// In the one-cell box (fewer than 3 cells per side) the limit is half the box side: a
  /// sphere must not touch its own image.
  double max_scale_for_cells() const {
    return (cells_.per_side() == 1 ? 0.5 * L_ : cells_.width()) / max_base_;
  }
  /// Checks all pairs (O(N^2)); throws std::logic_error naming an overlapping pair.
  void check_overlaps() const {
    const double tol = 1e-9;
    for (std::size_t i = 0; i < size(); ++i) {
      const Vec<D> xi = pos_now(i);
      for (std::size_t j = i + 1; j < size(); ++j) {
        Vec<D> r = xi - pos_now(j);
        for (int k = 0; k < D; ++k) r[k] -= L_ * std::round(r[k] / L_);
        const double s = contact(i, j);
        if (r.squaredNorm() < s * s * (1.0 - tol))
          throw std::logic_error("EDMD overlap at t = " + std::to_string(now_) + ": particles " +
                                 std::to_string(id_[i]) + ", " + std::to_string(id_[j]) +
                                 " at distance " +
                                 std::to_string(r.norm()) + " < " + std::to_string(s));
      }
    }
  }

 private:
  struct Ev {
    double t_pair = never;
    double t_cross = never;
    double t_pair2 = never;   // second-earliest pair event of the same scan (fallback)
    std::int32_t partner = -1;
    std::uint32_t pcount = 0;
    std::int32_t partner2 = -1;
    std::uint32_t pcount2 = 0;
    std::int32_t cross = 0;  // axis * 2 + (1 if upward)
  };
  /// The two earliest pair times (relative) and partners found by a scan.
  struct Top2 {
    double t1 = never, t2 = never;
    std::int32_t p1 = -1, p2 = -1;
    void offer(double t, std::int32_t j) {
      if (t < t2) {
        if (t < t1) {
          t2 = t1, p2 = p1;
          t1 = t, p1 = j;
        } else {
          t2 = t, p2 = j;
        }
      }
    }
  };

  /// Contact distance of i and j at unit scale (sum of radii; 1 without radii).
  double base_contact(std::size_t i, std::size_t j) const {
    if constexpr (F.radii) return p_.radius(i) + p_.radius(j);
    else {
      (void)i, (void)j;
      return 1.0;
    }
  }
  double contact(std::size_t i, std::size_t j) const {
    return base_contact(i, j) * diameter_scale();
  }
  Vec<D> pos_now(std::size_t i) const { return p_.position(i) + p_.velocity(i) * (now_ - p_.local_time(i)); }
  void advance(std::uint32_t i) {
    p_.position(i) += p_.velocity(i) * (now_ - p_.local_time(i));
    p_.local_time(i) = now_;
  }

  void rebuild() {
    const std::size_t n = size();
    for (std::uint32_t i = 0; i < n; ++i) {
      advance(i);
      auto x = p_.position(i);
      for (int k = 0; k < D; ++k) {
        const double f = std::floor(x[k] / L_);
        if (f != 0.0) {
          x[k] -= f * L_;
          image_[i * D + k] += static_cast<std::int32_t>(f);
        }
        if (x[k] >= L_) {  // -tiny wraps to L by round-off
          x[k] -= L_;
          ++image_[i * D + k];
        }
      }
    }
    // Scan::filtered keeps a 16-byte box per cell: at most 1.5 cells per particle (24 bytes)
    cells_.build(L_, max_base_ * diameter_scale(), n, filter_ ? 1.5 : 2.0);
    for (std::uint32_t i = 0; i < n; ++i) {
      std::array<int, D> c;
      for (int k = 0; k < D; ++k) c[k] = cells_.coord(p_.position(i)[k]);
      cells_.insert(i, cells_.index(c));
    }
    if (filter_) {  // every box is needed before the first scan
      box_levels_ = 256.0 * std::max(1, cells_.per_side() / 5) / L_;
      pbox_.resize(n);
      cbox_.assign(cells_.count(), PBox{});
      for (std::uint32_t i = 0; i < n; ++i) {
        predict_crossing(i);
        set_path_box(i, ev_[i].t_cross - now_);
      }
    }
    std::vector<double> keys(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      scan(i, -1, 0, Top2{});
      keys[i] = std::min(ev_[i].t_pair, ev_[i].t_cross);
    }
    q_.build(keys);
  }

  /// Time of the next crossing of i out of its cell (i is at the current time).
  void predict_crossing(std::uint32_t i) {
    const auto c = cells_.coords(cells_.cell_of(i));
    const auto x = p_.position(i);
    const auto v = p_.velocity(i);
    double best = never;
    std::int32_t code = 0;
    for (int k = 0; k < D; ++k) {
      double t = never;
      if (v[k] > 0.0) {
        t = (cells_.face_hi(c[k]) - x[k]) / v[k];
        if (t < best) best = t, code = 2 * k + 1;
      } else if (v[k] < 0.0) {
        t = (cells_.face_lo(c[k]) - x[k]) / v[k];
        if (t < best) best = t, code = 2 * k;
      }
    }
    ev_[i].t_cross = now_ + std::max(best, 0.0);
    ev_[i].cross = code;
  }

  /// Pair time of i (at now) with j's cell image (position + shift), or never.
  [[gnu::always_inline]] double pair_time(std::uint32_t i, std::uint32_t j, const Vec<D>& shift,
                                          double sc) const {
    const Vec<D> r = p_.position(j) + p_.velocity(j) * (now_ - p_.local_time(j)) + shift - p_.position(i);
    const Vec<D> v = p_.velocity(j) - p_.velocity(i);
    const double b = base_contact(i, j);
    return contact_time(r.dot(v), v.squaredNorm(), r.squaredNorm(), b * sc, b * rate_);
  }

  /// Scans neighbour cells of i (all, or the slab `dir` along `axis`), keeping the earliest
  /// pair event if it beats `best` (relative time) with `partner`; then predicts the crossing.
  void scan(std::uint32_t i, int axis, int dir, Top2 top) {
    const double sc = diameter_scale();
    if (cells_.per_side() == 1) {
      scan_small_box(i, sc);
      return;
    }
    if (horizon_) {
      scan_horizon(i, sc);
      return;
    }
    // Two passes: list the candidates and prefetch their records, then compute. A record
    // is one cache line in 3D, and outside the L2 cache a scan's ~13 records arrive
    // together instead of one miss after another.
    const auto h = cells_.coords(cells_.cell_of(i));
    visit_.clear();
    cells_.for_each_neighbor(
        h,
        [&](std::uint32_t c, const Vec<D>& shift) {
          cells_.prefetch(c);
          std::uint32_t code = 0;  // the 2-bit shift codes of scan_horizon
          for (int k = 0; k < D; ++k)
            code |= (shift[k] < 0.0 ? 1u : shift[k] > 0.0 ? 2u : 0u) << (2 * k);
          visit_.push_back({c, code});
        },
        axis, dir);
    nvisit_ = visit_.size();
    gather(i);
    store(i, earliest_pairs(i, sc, top));
    predict_crossing(i);
  }
  /// Lists the particles of the cells in visit_, except i, as the candidates
  /// cand_[0, ncand_), and prefetches their records (or, records = false, their PBoxes).
  /// Cells hold 0.5-0.7 particles on average at the benchmark densities (1.3-1.4 in an
  /// occupied one), so a loop per cell would mispredict its exit at most cells: the first
  /// two members are written without a branch (a missing one's `none` is written and not
  /// counted), and only third and later members loop. Heads are prefetched 8 cells ahead.
  /// gather and gather_filtered stay out of line (6D, seven interleaved runs: inlined into
  /// scan_horizon, median 82k against 88k collisions per second; and profiles name them).
  [[gnu::noinline]] void gather(std::uint32_t i, bool records = true) {
    std::size_t n = 0;
    const auto me = static_cast<std::int32_t>(i);
    auto fetch = [&](std::int32_t j) {
      const auto jj = static_cast<std::size_t>(j < 0 ? 0 : j);
      if (!records) {  // Scan::filtered: the path box (one line) instead of the record
        __builtin_prefetch(&pbox_[jj]);
        return;
      }
      const double* rec = p_.position(jj).data();
      __builtin_prefetch(rec);
      if constexpr (Store::stride > 8) __builtin_prefetch(rec + 8);  // 4D-6D: 2 lines
    };
    if (cand_.size() < 2 * nvisit_ + 1) cand_.resize(2 * nvisit_ + 64);
    const std::size_t nv = nvisit_;
    constexpr std::size_t ahead = 8;
    for (std::size_t v = 0; v < std::min(ahead, nv); ++v) cells_.prefetch(visit_[v].j);
    for (std::size_t v = 0; v < nv; ++v) {
      const Cand& c = visit_[v];
      cells_.prefetch(visit_[std::min(v + ahead, nv - 1)].j);
      std::int32_t j = cells_.head(c.j);
      fetch(j);
      cand_[n] = {static_cast<std::uint32_t>(j), c.shift};
      n += static_cast<std::size_t>((j != Cells<D>::none) & (j != me));
      j = cells_.next(j);
      fetch(j);
      cand_[n] = {static_cast<std::uint32_t>(j), c.shift};
      n += static_cast<std::size_t>((j != Cells<D>::none) & (j != me));
      for (j = cells_.next(j); j != Cells<D>::none; j = cells_.next(j)) {  // next(none) = none
        // room for this member and the first two members of the cells still to come
        if (cand_.size() < n + 2 * (nv - v) + 1) cand_.resize(2 * cand_.size());
        fetch(j);
        cand_[n] = {static_cast<std::uint32_t>(j), c.shift};
        n += static_cast<std::size_t>(j != me);
      }
    }
    ncand_ = n;
  }

  /// Earliest two pair events of i (at now) with the candidates cand_[0, ncand_), offered
  /// to `top`. Three passes: the dot products of every pair (straight-line code), their
  /// contact times without branches (contact_times), then the two smallest. Same times as
  /// pair_time, bit for bit.
  Top2 earliest_pairs(std::uint32_t i, double sc, Top2 top) {
    const std::size_t n = ncand_;
    npairs_ += n;
    ++nscan_;
    if (dots_.size() < 4 * n) dots_.resize(4 * n);
    double* rv = dots_.data();
    double* vv = rv + n;
    double* rr = vv + n;
    double* tt = rr + n;
    if constexpr (F.radii) bases_.resize(n);
    const Vec<D> xi = p_.position(i), vi = p_.velocity(i);
    const double shv[4] = {0.0, -L_, L_, 0.0};
    for (std::size_t c = 0; c < n; ++c) {
      const std::uint32_t j = cand_[c].j;
      Vec<D> shift;
      for (int k = 0; k < D; ++k) shift[k] = shv[(cand_[c].shift >> (2 * k)) & 3u];
      const Vec<D> r =
          p_.position(j) + p_.velocity(j) * (now_ - p_.local_time(j)) + shift - xi;
      const Vec<D> v = p_.velocity(j) - vi;
      rv[c] = r.dot(v), vv[c] = v.squaredNorm(), rr[c] = r.squaredNorm();
      if constexpr (F.radii) bases_[c] = base_contact(i, j);
    }
    contact_times(n, rv, vv, rr, F.radii ? bases_.data() : nullptr, sc, rate_, tt);
    for (std::size_t c = 0; c < n; ++c)
      if (tt[c] < top.t2) top.offer(tt[c], static_cast<std::int32_t>(cand_[c].j));
    return top;
  }

  /// Box bounding a particle's straight path from its last scan to its next cell crossing
  /// (Scan::filtered) on a grid of box_levels_ levels per unit length, rounded outward,
  /// kept modulo 256 (a byte per bound). Every event that changes a path (collision,
  /// crossing, stale rescan) rescans the particle and rewrites its box. A collision at t*
  /// found by the later scanner i of a pair (scan_horizon's argument) has the partner j at
  /// t* on the path j had at its last scan, so inside j's box: a j whose box is farther than
  /// a contact distance from i's box is not a partner to find now, and is skipped.
  /// Lanes 2k, 2k+1 hold lo_k and -hi_k; a scanner's `probe` holds hi_k and -lo_k, so
  /// lane-wise differences are lo_j - hi_i and lo_i - hi_j: the per-axis gaps when positive
  /// (never both). The grid has 256 p levels per box side L, p = floor(m / 5) for m >= 5
  /// cells per side (so 256 levels span 5 to 9 cells: a level is at most 9/256 of a cell
  /// width, 0.024 sigma in the 6D benchmark), and modulo 256 it is periodic in L. Boxes of
  /// a scan lie in neighbouring cells, less than 2 cells = 2 * 256 p / m <= 102.4 levels
  /// (+2 rounding) apart, so the differences taken as signed bytes are the true ones.
  struct alignas(16) PBox {
    static constexpr int lanes = 16;
    std::uint8_t v[lanes];
    /// Whether the squared gap sum of boxes b and probe is at most `bound` (levels^2).
    static bool near(const PBox& b, const PBox& probe, std::int32_t bound) {
#if defined(__SSE2__)
      const __m128i zero = _mm_setzero_si128();
      const __m128i d = _mm_sub_epi8(_mm_load_si128(reinterpret_cast<const __m128i*>(b.v)),
                                     _mm_load_si128(reinterpret_cast<const __m128i*>(probe.v)));
      // signed bytes to 16-bit lanes, negative gaps to 0
      const __m128i lo = _mm_max_epi16(_mm_srai_epi16(_mm_unpacklo_epi8(d, d), 8), zero);
      const __m128i hi = _mm_max_epi16(_mm_srai_epi16(_mm_unpackhi_epi8(d, d), 8), zero);
      __m128i acc = _mm_add_epi32(_mm_madd_epi16(lo, lo), _mm_madd_epi16(hi, hi));
      acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, 0x4E));
      acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, 0xB1));
      return _mm_cvtsi128_si32(acc) <= bound;
#else
      std::int32_t s = 0;
      for (int l = 0; l < lanes; ++l) {
        const std::int32_t e =
            static_cast<std::int8_t>(static_cast<std::uint8_t>(b.v[l] - probe.v[l]));
        const std::int32_t g = e > 0 ? e : 0;
        s += g * g;
      }
      return s <= bound;
#endif
    }
  };
  /// One stencil offset along one axis for scan_horizon: its part of the cell index, its
  /// squared gap to the path's box, and its periodic shift code (2 bits: 1 = -L, 2 = +L).
  struct AxisStep {
    std::uint32_t idx;
    std::uint32_t code;
    double gap2;
  };
  using AxisSteps = std::array<std::array<AxisStep, 3>, D>;
  /// A partial stencil offset of walk_stencil: cell index and shift code of the axes
  /// chosen so far, and their summed squared gaps.
  struct Node {
    std::uint32_t idx, code;
    double g2;
  };
  /// Lists in visit_ the occupied stencil cells whose summed squared gaps stay within
  /// `bound`. Axis by axis from D-1 down to 0, every kept partial offset is extended by the
  /// steps of the next axis, so a partial sum above the bound drops its whole subtree; an
  /// extension is written and then counted or not, without a branch (whether one is kept
  /// is unpredictable: in 6D about 1000 extensions give 335 cells). The cells come in the
  /// lexicographic order of the steps, as from a depth-first walk.
  void walk_stencil(const AxisSteps& st, const std::array<int, D>& nst, double bound) {
    if (nodes_.size() < 2 * stencil_cells) nodes_.resize(2 * stencil_cells);
    if (visit_.size() < stencil_cells) visit_.resize(stencil_cells);
    Node* a = nodes_.data();
    Node* b = a + stencil_cells;
    a[0] = {0u, 0u, 0.0};
    std::size_t na = 1;
    for (int k = D - 1; k >= 1; --k) {
      std::size_t nb = 0;
      for (std::size_t e = 0; e < na; ++e) {
        const Node p = a[e];
        for (int s = 0; s < nst[k]; ++s) {
          const AxisStep& t = st[k][s];
          const double g = p.g2 + t.gap2;
          b[nb] = {p.idx + t.idx, p.code | t.code, g};
          nb += static_cast<std::size_t>(g <= bound);
        }
      }
      std::swap(a, b);
      na = nb;
    }
    std::size_t nv = 0;
    for (std::size_t e = 0; e < na; ++e) {
      const Node p = a[e];
      for (int s = 0; s < nst[0]; ++s) {
        const AxisStep& t = st[0][s];
        const std::uint32_t c = p.idx + t.idx;
        visit_[nv] = {c, p.code | t.code};
        nv += static_cast<std::size_t>(p.g2 + t.gap2 <= bound) & cells_.occupied(c);
      }
    }
    nvisit_ = nv;
  }

  /// Horizon scan (Config::Scan::horizon; 3 or more cells per side). Until its next cell
  /// crossing, H from now, i stays in the box B spanned by its path x_i + v_i t, t in [0, H].
  /// A collision of i and j at t* is found by the scan of whichever of them predicted last
  /// before t*: neither crosses a cell between that scan and t* (a crossing is an event, and
  /// every event of a particle in this mode rescans it), so the scanner's position at t* is
  /// in its B and the other particle is in the cell it occupied at the scan. A stencil cell
  /// farther from B than the largest contact distance reachable by time H therefore holds
  /// no partner to find now, and is skipped. The squared distance is summed axis by axis
  /// (walk_stencil), so one far axis skips a whole slab of the stencil. A pair found
  /// beyond H is still recorded (it is a correct prediction, only possibly not the first).
  void scan_horizon(std::uint32_t i, double sc) {
    predict_crossing(i);
    const double H = ev_[i].t_cross - now_;
    const auto h = cells_.coords(cells_.cell_of(i));
    const int m = cells_.per_side();
    const Vec<D> x = p_.position(i);
    const Vec<D> v = p_.velocity(i);
    // Largest contact distance before the crossing, with a margin for round-off in the
    // gaps (a touching cell is never skipped).
    const double smax = max_base_ * (sc + (rate_ > 0.0 ? rate_ * H : 0.0)) * (1.0 + 1e-9) +
                        1e-12 * L_;
    const double bound = smax * smax;
    AxisSteps st;
    std::array<int, D> nst{};
    std::uint32_t stride = 1;
    const bool filter = filter_ && m >= 5;  // Scan::filtered (see PBox)
    for (int k = 0; k < D; ++k) {
      const auto [lo, hi] = path_extent(x[k], v[k], H);
      const double gdown = std::max(lo - cells_.face_lo(h[k]), 0.0);
      const double gup = std::max(cells_.face_hi(h[k]) - hi, 0.0);
      int a = 0;
      st[k][a++] = {static_cast<std::uint32_t>(h[k]) * stride, 0u, 0.0};
      if (gdown * gdown <= bound) {
        const bool wrap = h[k] == 0;
        st[k][a++] = {static_cast<std::uint32_t>(wrap ? m - 1 : h[k] - 1) * stride,
                      wrap ? 1u << (2 * k) : 0u, gdown * gdown};
      }
      if (gup * gup <= bound) {
        const bool wrap = h[k] + 1 == m;
        st[k][a++] = {static_cast<std::uint32_t>(wrap ? 0 : h[k] + 1) * stride,
                      wrap ? 2u << (2 * k) : 0u, gup * gup};
      }
      nst[k] = a;
      stride *= static_cast<std::uint32_t>(m);
    }
    walk_stencil(st, nst, bound);
    const PBox probe = filter_ ? set_path_box(i, H) : PBox{};  // kept even if not used now
    if (filter) {
      // smax <= cell width, so r <= 256 p / m + 2 <= 54 levels
      const auto r = static_cast<std::int32_t>(std::ceil(smax * box_levels_)) + 1;
      drop_far_cells(probe, r * r);
      gather_filtered(i, probe, r * r);
    } else {
      gather(i);
    }
    store(i, earliest_pairs(i, sc, Top2{}));
  }

  /// Range of one coordinate x + v t over t in [0, H] (H = never only if v = 0).
  static std::pair<double, double> path_extent(double x, double v, double H) {
    const double ext = v == 0.0 ? 0.0 : v * H;
    return {std::min(x, x + ext), std::max(x, x + ext)};
  }
  /// Writes i's path box for the next H time units (i at now) and returns its probe.
  PBox set_path_box(std::uint32_t i, double H) {
    const double q = box_levels_;
    const Vec<D> x = p_.position(i);
    const Vec<D> v = p_.velocity(i);
    PBox mine{}, probe{};
    for (int k = 0; k < D; ++k) {  // outward to the grid; u8 casts take levels mod 2^8
      const auto [lo, hi] = path_extent(x[k], v[k], H);
      const auto glo = static_cast<std::int64_t>(std::floor(std::max(lo, 0.0) * q));
      const auto ghi = static_cast<std::int64_t>(std::ceil(std::min(hi, L_) * q));
      mine.v[2 * k] = static_cast<std::uint8_t>(glo);
      mine.v[2 * k + 1] = static_cast<std::uint8_t>(-ghi);
      probe.v[2 * k] = static_cast<std::uint8_t>(ghi);
      probe.v[2 * k + 1] = static_cast<std::uint8_t>(-glo);
    }
    pbox_[i] = mine;
    update_cell_box(cells_.cell_of(i));
    return probe;
  }
  /// Union of two path boxes of one cell (lane-wise the lower bound, and the lower -hi):
  /// the lanes of a cell's boxes lie within 128 levels of each other (PBox), so the
  /// smaller of two is the one whose signed byte difference to the other is negative.
  static PBox unite(const PBox& a, const PBox& b) {
#if defined(__SSE2__)
    const __m128i x = _mm_load_si128(reinterpret_cast<const __m128i*>(a.v));
    const __m128i y = _mm_load_si128(reinterpret_cast<const __m128i*>(b.v));
    const __m128i take = _mm_cmpgt_epi8(_mm_setzero_si128(), _mm_sub_epi8(y, x));
    PBox u;
    _mm_store_si128(reinterpret_cast<__m128i*>(u.v),
                    _mm_xor_si128(x, _mm_and_si128(_mm_xor_si128(x, y), take)));
    return u;
#else
    PBox u;
    for (int l = 0; l < PBox::lanes; ++l) {
      const auto d = static_cast<std::int8_t>(static_cast<std::uint8_t>(b.v[l] - a.v[l]));
      u.v[l] = d < 0 ? b.v[l] : a.v[l];
    }
    return u;
#endif
  }
  /// Recomputes cell c's box, the union of its members' path boxes (cbox_): after a
  /// member's box changed (set_path_box) or a member left (cross). An empty cell keeps a
  /// stale box; scans skip it by its occupancy bit.
  void update_cell_box(std::uint32_t c) {
    std::int32_t j = cells_.head(c);
    if (j == Cells<D>::none) return;
    PBox u = pbox_[static_cast<std::size_t>(j)];
    for (j = cells_.next(j); j != Cells<D>::none; j = cells_.next(j))
      u = unite(u, pbox_[static_cast<std::size_t>(j)]);
    cbox_[c] = u;
  }
  /// Drops from visit_ the cells whose box (the union of their members' path boxes) is
  /// farther than the contact distance from the scanner's: none of their members could
  /// pass gather_filtered. In 6D about 170 occupied cells of a scan come here.
  void drop_far_cells(const PBox& probe, std::int32_t bound) {
    const std::size_t nv = nvisit_;
    constexpr std::size_t ahead = 8;
    for (std::size_t v = 0; v < std::min(ahead, nv); ++v)
      __builtin_prefetch(&cbox_[visit_[v].j]);
    std::size_t n = 0;
    for (std::size_t v = 0; v < nv; ++v) {
      __builtin_prefetch(&cbox_[visit_[std::min(v + ahead, nv - 1)].j]);
      const Cand c = visit_[v];
      visit_[n] = c;
      n += static_cast<std::size_t>(PBox::near(cbox_[c.j], probe, bound));
    }
    nvisit_ = n;
  }
  /// gather() for Scan::filtered: a member j is a candidate only if PBox::near(j's box,
  /// the scanner's probe) holds. Two passes: list every member and prefetch its box (the
  /// boxes of a 6D scan's ~230 members are mostly outside L2), then keep the near ones;
  /// records are prefetched for those only.
  [[gnu::noinline]] void gather_filtered(std::uint32_t i, const PBox& probe, std::int32_t bound) {
    gather(i, false);
    const PBox* box = pbox_.data();
    std::size_t n = 0;
    for (std::size_t c = 0; c < ncand_; ++c) {
      const Cand k = cand_[c];
      cand_[n] = k;
      n += static_cast<std::size_t>(PBox::near(box[k.j], probe, bound));
    }
    ncand_ = n;
    for (std::size_t c = 0; c < n; ++c) {
      const double* rec = p_.position(cand_[c].j).data();
      __builtin_prefetch(rec);
      if constexpr (Store::stride > 8) __builtin_prefetch(rec + 8);
    }
  }

  /// Records a scan's two earliest pair events (relative times) as i's pair events.
  void store(std::uint32_t i, const Top2& top) {
    Ev& e = ev_[i];
    e.t_pair = now_ + top.t1;
    e.partner = top.p1;
    e.pcount = top.p1 >= 0 ? cnt_[top.p1] : 0;
    e.t_pair2 = now_ + top.t2;
    e.partner2 = top.p2;
    e.pcount2 = top.p2 >= 0 ? cnt_[top.p2] : 0;
  }

  /// Scan of the one-cell box (fewer than 3 cells per side, cells.hpp). Every other particle
  /// j is a neighbour under the 3^D shifts {-L,0,L}^D, but only a few shifts can matter
  /// before i's next crossing (after which i scans again): along axis k the relative
  /// coordinate d_k + u_k t, t in [0, H], H = time to i's crossing, must come within the
  /// largest contact distance of the horizon for shift S_k to give a contact. Typically
  /// fewer than one shift combination per pair survives, instead of 3^D (729 in 6D).
  /// Every collision is still found: a collision at t* is predicted by the scan of i or j
  /// at the later of their last events, whose horizon reaches t*.
  void scan_small_box(std::uint32_t i, double sc) {
    predict_crossing(i);
    Ev& e = ev_[i];
    const double H = e.t_cross - now_;
    const Vec<D> xi = p_.position(i);
    const Vec<D> vi = p_.velocity(i);
    Top2 top;
    for (std::int32_t j = cells_.head(0); j != Cells<D>::none; j = cells_.next(j)) {
      if (static_cast<std::uint32_t>(j) == i) continue;
      const Vec<D> d = pos_now(static_cast<std::size_t>(j)) - xi;
      const Vec<D> u = p_.velocity(j) - vi;
      const double b = base_contact(i, j);
      const double smax = b * (sc + (rate_ > 0.0 ? rate_ * H : 0.0));
      std::array<std::array<double, 3>, D> opts;
      std::array<int, D> cnt{};
      bool any = true;
      for (int k = 0; k < D && any; ++k) {
        const double ext = u[k] == 0.0 ? 0.0 : u[k] * H;  // inf * 0 would be NaN
        const double lo = std::min(d[k], d[k] + ext), hi = std::max(d[k], d[k] + ext);
        for (const double S : {0.0, -L_, L_})
          if (lo + S < smax && hi + S > -smax) opts[k][cnt[k]++] = S;
        any = cnt[k] > 0;
      }
      if (!any) continue;
      std::array<int, D> at{};
      for (;;) {  // odometer over the surviving shift combinations
        Vec<D> shift;
        for (int k = 0; k < D; ++k) shift[k] = opts[k][at[k]];
        top.offer(pair_time(i, static_cast<std::uint32_t>(j), shift, sc), j);
        int k = 0;
        while (k < D && ++at[k] == cnt[k]) at[k++] = 0;
        if (k == D) break;
      }
    }
    store(i, top);
  }

  /// Full prediction for i (advanced to now) and queue update.
  void predict(std::uint32_t i) {
    scan(i, -1, 0, Top2{});
    q_.update(i, std::min(ev_[i].t_pair, ev_[i].t_cross));
  }

  void collide(std::uint32_t i, std::uint32_t j) {
    advance(i);
    advance(j);
    Vec<D> r = p_.position(i) - p_.position(j);
    for (int k = 0; k < D; ++k) r[k] -= L_ * std::round(r[k] / L_);  // contact: |r_k| <= L/2
    const double rn = r.norm();
    const Vec<D> n = r / rn;
    const double wi = p_.inv_mass(i), wj = p_.inv_mass(j);
    const Vec<D> vi0 = p_.velocity(i);
    detail::collide_unchecked<D>(p_.velocity(i), p_.velocity(j), wi, wj, n);
    if (rate_ != 0.0) {  // LS: separate at least as fast as the contact distance grows
      const double a = 2.0 * base_contact(i, j) * rate_;
      p_.velocity(i) += (a * wi / (wi + wj)) * n;
      p_.velocity(j) -= (a * wj / (wi + wj)) * n;
    }
    virial_ += (p_.velocity(i) - vi0).dot(r) / wi;
    ++cnt_[i];
    ++cnt_[j];
    ++ncoll_;
  }

  void cross(std::uint32_t i) {
    advance(i);
    const int k = ev_[i].cross / 2;
    const int dir = (ev_[i].cross & 1) ? 1 : -1;
    auto c = cells_.coords(cells_.cell_of(i));
    const int m = cells_.per_side();
    const double w = cells_.width();
    auto x = p_.position(i);
    c[k] += dir;
    if (c[k] == m) {
      c[k] = 0, x[k] = 0.0, ++image_[i * D + k];
    } else if (c[k] < 0) {
      c[k] = m - 1, x[k] = L_, --image_[i * D + k];
    } else {
      x[k] = (dir > 0 ? c[k] : c[k] + 1) * w;
    }
    const std::uint32_t left = cells_.cell_of(i);
    cells_.remove(i);
    cells_.insert(i, cells_.index(c));
    if (filter_) update_cell_box(left);  // the new cell's box follows i's scan below
    Ev& e = ev_[i];
    const bool keep = !horizon_ && m >= 3 && e.partner >= 0 && cnt_[e.partner] == e.pcount;
    if (keep) {
      Top2 top{e.t_pair - now_, e.t_pair2 - now_, e.partner, e.partner2};
      if (top.p2 >= 0 && cnt_[top.p2] != e.pcount2) top.t2 = never, top.p2 = -1;
      scan(i, k, dir, top);
    } else {
      scan(i, -1, 0, Top2{});
    }
    q_.update(i, std::min(e.t_pair, e.t_cross));
  }

  /// Renumbers the particles in Z-order of their cells, so that a scan's neighbours lie
  /// near each other in memory (at N = 256000 the state is larger than the caches, and a
  /// random numbering makes nearly every neighbour a cache miss). A pure permutation of
  /// every per-particle array: no particle is advanced and no event re-predicted, so the
  /// trajectories are unchanged bit for bit. Snapshots and error messages report the
  /// original numbering (id_).
  void reorder() {
    const std::uint32_t n = static_cast<std::uint32_t>(size());
    next_reorder_ = ncoll_ + reorder_every_;
    std::vector<std::pair<std::uint64_t, std::uint32_t>> key(n);
    for (std::uint32_t i = 0; i < n; ++i) key[i] = {cells_.morton(cells_.cell_of(i)), i};
    std::sort(key.begin(), key.end());
    std::vector<std::uint32_t> from(n), to(n), cell(n);
    for (std::uint32_t i = 0; i < n; ++i) from[i] = key[i].second, to[key[i].second] = i;
    p_.permute(from);
    permute_records(image_, from, D);
    permute_records(cnt_, from, 1);
    permute_records(ev_, from, 1);
    permute_records(id_, from, 1);
    if (filter_) permute_records(pbox_, from, 1);
    for (std::uint32_t i = 0; i < n; ++i) {
      Ev& e = ev_[i];
      if (e.partner >= 0) e.partner = static_cast<std::int32_t>(to[e.partner]);
      if (e.partner2 >= 0) e.partner2 = static_cast<std::int32_t>(to[e.partner2]);
      cell[i] = cells_.cell_of(from[i]);
      slot_[id_[i]] = i;
    }
    cells_.clear();
    for (std::uint32_t i = n; i-- > 0;) cells_.insert(i, cell[i]);  // lists in slot order
    std::vector<double> keys(n);
    for (std::uint32_t i = 0; i < n; ++i) keys[i] = std::min(ev_[i].t_pair, ev_[i].t_cross);
    q_.build(keys);
  }

  void sample(double ts, Observer& obs) const {
    const std::size_t n = size();
    constexpr int st = Store::stride;
    std::vector<double> xu(n * st, 0.0);
    for (std::size_t a = 0; a < n; ++a) {  // a: original id, i: its current slot
      const std::size_t i = slot_[a];
      for (int k = 0; k < D; ++k)
        xu[a * st + k] = p_.position(i)[k] + p_.velocity(i)[k] * (ts - p_.local_time(i)) +
                         L_ * image_[i * D + k];
    }
    Store ordered = p_;  // velocities in the original numbering
    ordered.permute(slot_);
    Snapshot s = make_snapshot(ordered);
    s.time = ts;
    s.collisions = ncoll_;
    s.collisions_per_particle = 2.0 * static_cast<double>(ncoll_) / static_cast<double>(n);
    s.positions = xu.data();
    obs.observe(s);
  }

  Store p_;
  std::vector<std::int32_t> image_;   // periodic image counts (unwrapped = x + L image)
  std::vector<std::uint32_t> cnt_;    // per-particle collision counters
  std::vector<Ev> ev_;
  struct Cand {
    std::uint32_t j, shift;  // particle (or cell), periodic shift code: 2 bits per axis,
                             // 0 none, 1 = -L, 2 = +L (AxisStep)
  };
  std::vector<Cand> cand_;      // scratch of scan(): candidates [0, ncand_)
  std::size_t ncand_ = 0;
  std::vector<Cand> visit_;     // scratch of scan(): stencil cells (cell, shift)
  std::size_t nvisit_ = 0;      //   in use: [0, nvisit_)
  std::vector<Node> nodes_;     // scratch of walk_stencil()
  static constexpr std::size_t stencil_cells = [] {
    std::size_t c = 1;
    for (int k = 0; k < D; ++k) c *= 3;
    return c;
  }();
  std::vector<PBox> pbox_;      // Scan::filtered: each particle's path box,
  std::vector<PBox> cbox_;      //   each cell's union of its members' boxes
  double box_levels_ = 0.0;     //   and its grid levels per unit length
  std::vector<double> dots_, bases_;  // scratch of earliest_pairs()
  std::vector<std::uint32_t> id_, slot_;  // original id of each slot, and its inverse
  std::uint64_t reorder_every_ = 0, next_reorder_ = 0;  // renumbering period (collisions)
  Queue q_;
  Cells<D> cells_;
  double L_ = 0.0, max_base_ = 1.0;
  double now_ = 0.0;
  double scale_ref_ = 1.0, t_scale_ = 0.0, rate_ = 0.0;
  std::uint64_t ncoll_ = 0, coll_meas_ = 0, ncross_ = 0, nstale_ = 0, npairs_ = 0, nscan_ = 0;
  double t_meas_ = 0.0, virial_ = 0.0;
  bool debug_ = false;
  bool horizon_ = false;  // Config::Scan::horizon or filtered in effect
  bool filter_ = false;   // Config::Scan::filtered in effect (pbox_ kept)
};

}  // namespace hypergas::edmd

#include "hypergas/edmd/compression.hpp"

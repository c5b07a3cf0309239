// hypergas/edmd/compression.hpp -- Lubachevsky–Stillinger compression: grow all diameters
// at a constant relative rate during event-driven MD until they reach a target.
//
// B. D. Lubachevsky & F. H. Stillinger, "Geometric properties of random disk packings",
// J. Stat. Phys. 60, 561 (1990); in D dimensions as in Skoge, Donev, Stillinger & Torquato,
// Phys. Rev. E 74, 041127 (2006). The contact distance of a pair grows as
// s(t) = s_base (scale0 + gamma t); collision times solve |r + v t| = s(t) (pair_time.hpp),
// and each collision adds a normal impulse giving the pair an extra separation speed
// 2 s_base gamma, so that spheres move apart faster than they grow. The collisions heat the
// gas: velocities are rescaled to the initial temperature after every stage of
// `Config::compression_stage` time units, and whenever the cell grid must be rebuilt for the
// larger diameters. Near jamming the collision rate diverges; the compression then stops
// with InvalidInput after `Config::max_compression_collisions` collisions. With
// Config::debug_overlap the all-pairs check runs at every stage end during compression
// (after every event once compressed). The compression is elastic: an engine with
// restitution below 1 (restitution.hpp) compresses at restitution 1 and gets its
// restitution back afterwards (with fresh TC clocks, Engine::set_restitution).
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include "hypergas/edmd/config.hpp"
#include "hypergas/error.hpp"

namespace hypergas::edmd {

/// Grows the diameter scale of `e` to `target_scale` (dimensionless, 1 = nominal diameters)
/// at relative rate cfg.growth_rate per unit time, keeping the kinetic temperature,
/// elastically. E is an edmd::Engine (engine.hpp): it uses temperature, collisions,
/// set_debug, restart, diameter_scale, max_scale_for_cells, run_until, time, packing,
/// check_overlaps, restitution and set_restitution.
template <class E>
void compress(E& e, double target_scale, const Config& cfg) {
  if (!(cfg.growth_rate > 0.0)) throw InvalidInput("compression growth rate must be > 0");
  struct Elastic {  // restitution 1 while compressing, restored however compress ends
    E& e;
    double alpha;
    explicit Elastic(E& en) : e(en), alpha(en.restitution()) {
      if (alpha < 1.0) e.set_restitution(1.0);
    }
    ~Elastic() {
      if (alpha < 1.0) e.set_restitution(alpha);
    }
    Elastic(const Elastic&) = delete;
    Elastic& operator=(const Elastic&) = delete;
  } elastic(e);
  const double kT = e.temperature();
  const std::uint64_t c0 = e.collisions();
  // The O(N^2) debug check runs at every stage end here, not after every event.
  const bool debug = e.set_debug(false);
  e.restart(cfg.growth_rate);
  while (e.diameter_scale() < target_scale) {
    const double sc = e.diameter_scale();
    const double lim = std::min(target_scale, e.max_scale_for_cells());
    const double dt = std::min((lim - sc) / cfg.growth_rate, cfg.compression_stage);
    e.run_until(e.time() + std::max(dt, 0.0));
    if (e.collisions() - c0 > cfg.max_compression_collisions)
      throw InvalidInput("compression jammed at packing " + std::to_string(e.packing()) +
                         " after " + std::to_string(e.collisions() - c0) + " collisions");
    const bool done = e.diameter_scale() >= target_scale * (1.0 - 1e-12);
    e.restart(done ? 0.0 : cfg.growth_rate, kT, done ? target_scale : 0.0);
    if (debug) e.check_overlaps();
    if (done) break;
  }
  e.set_debug(debug);
}

}  // namespace hypergas::edmd

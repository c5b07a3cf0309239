// hypergas/edmd/state.hpp -- the state of an EDMD run that the event loop and the neighbour
// scans share: particles (each at its own local time), periodic images, collision counters,
// predicted events, original numbering, the cell grid, the clock, the diameter scale, and
// the event counters, and for granular runs (restitution < 1) each particle's time of last
// collision (TC model, restitution.hpp).
//
// Memory: position, clock and velocity of a particle are one record (one cache line in 3D,
// particles.hpp). The diameter scale is scale_ref + rate (now - t_scale): 1 in a run, growing
// during the Lubachevsky–Stillinger compression (compression.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "hypergas/edmd/box.hpp"
#include "hypergas/edmd/cells.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/edmd/events.hpp"
#include "hypergas/edmd/given_state.hpp"
#include "hypergas/edmd/lattice.hpp"
#include "hypergas/edmd/pair_time.hpp"
#include "hypergas/edmd/restitution.hpp"
#include "hypergas/error.hpp"
#include "hypergas/geometry.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::edmd {

/// Shared state of the EDMD engine (see the file comment). Plain data with the helpers the
/// engine and its scan policies use on it.
template <int D, Features F>
struct State {
  using Store = Particles<D, F>;

  Store p;
  std::vector<std::int32_t> image;  // periodic image counts (unwrapped = x + L image)
  std::vector<std::uint32_t> cnt;   // per-particle collision counters
  std::vector<Ev> ev;
  std::vector<std::uint32_t> id, slot;  // original id of each slot, and its inverse
  // Time of each particle's last collision while the restitution is below 1 (-inf: none
  // since dissipation was switched on); empty in elastic runs. Per slot, like cnt.
  std::vector<double> t_last;
  Cells<D> cells;
  double L = 0.0, max_base = 1.0;
  double now = 0.0;
  double scale_ref = 1.0, t_scale = 0.0, rate = 0.0;
  std::uint64_t ncoll = 0, ncross = 0, nstale = 0, npairs = 0, nscan = 0;
  std::uint64_t ntc = 0;  // collisions made elastic by the TC rule

  /// Places cfg.n particles on a lattice at packing cfg.packing with velocities of state
  /// cfg.init, at time 0 with no events; sets the diameter scale the lattice allows (1, or
  /// below 1 when the lattice is too tight and the compression must grow the diameters).
  /// Throws InvalidInput for bad parameters.
  void setup(const Config& cfg) {
    if (cfg.n < 2) throw InvalidInput("EDMD needs at least 2 particles");
    if (cfg.n > 0xFFFFFFF0ull) throw InvalidInput("EDMD: too many particles");
    check_restitution(cfg.restitution);
    check_tc_time(cfg.tc_time);
    if constexpr (D >= 2) check_packing(D, cfg.packing);
    else if (!(cfg.packing > 0.0 && cfg.packing < 1.0))
      throw InvalidInput("1D packing fraction must be in (0, 1)");
    const std::size_t n = cfg.n;
    p.resize(n);
    Rng rng(cfg.seed, 0);
    Rng vrng = rng.split(1);
    initialize_velocities(p, cfg.init, vrng, cfg.initial);
    double vol = 0.0;  // volume of the spheres at unit scale
    for (std::size_t i = 0; i < n; ++i) vol += ball_volume(D, base_contact(i, i));
    L = std::pow(vol / cfg.packing, 1.0 / D);
    max_base = 1.0;
    Rng lrng = rng.split(2);
    const LatticeSites<D> sites = lattice_sites<D>(n, L, lrng);
    for (std::size_t i = 0; i < n; ++i) p.position(i) = sites.x[i];
    fresh_bookkeeping(n);
    // Lattice gaps below 10% of a diameter make the occupied sites a near-contact network
    // (in 5D, 26% of the D_5 sites give ~10 touching neighbours each) whose collision rate
    // diverges under compression: N = 1000, eta = 0.14 did 3e6 collisions by t = 2e-8.
    // Such starts shrink the diameters to 90% of the site spacing and let the
    // Lubachevsky-Stillinger compression (compression.hpp) grow them back.
    const double fit = sites.nearest / max_base;
    scale_ref = fit >= 1.1 ? 1.0 : 0.9 * fit;
    if (cfg.start_packing != 0.0) {
      if (!(cfg.start_packing > 0.0 && cfg.start_packing <= cfg.packing))
        throw InvalidInput("start packing must be in (0, packing]");
      scale_ref = std::min(scale_ref, std::pow(cfg.start_packing / cfg.packing, 1.0 / D));
    }
  }

  /// Takes the positions, velocities and box of a given state (given_state.hpp, checked
  /// there) at time 0 with no events; diameter scale 1 (no compression). Species where the
  /// engine has two: species 1 has mass cfg.initial.mass_ratio.
  void setup_given(const Config& cfg, const GivenState& g) {
    check_restitution(cfg.restitution);
    check_tc_time(cfg.tc_time);
    const std::size_t n = g.n;
    p.resize(n);
    if constexpr (F.species) {
      p.set_species_mass(0, 1.0);
      p.set_species_mass(1, cfg.initial.mass_ratio);
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (int a = 0; a < D; ++a) {
        p.position(i)[a] = g.positions[i * D + std::size_t(a)];
        p.velocity(i)[a] = g.velocities[i * D + std::size_t(a)];
      }
      if constexpr (F.species) p.set_species(i, g.species ? g.species[i] : 0);
    }
    L = g.box;
    max_base = 1.0;
    fresh_bookkeeping(n);
    scale_ref = 1.0;
  }

  /// No images, collisions or events yet; slots in the original numbering.
  void fresh_bookkeeping(std::size_t n) {
    image.assign(n * D, 0);
    cnt.assign(n, 0);
    ev.assign(n, Ev{});
    id.resize(n);
    slot.resize(n);
    for (std::uint32_t i = 0; i < n; ++i) id[i] = slot[i] = i;
  }

  /// Saves or restores the whole state (hypergas/checkpoint.hpp).
  template <class Archive>
  void io(Archive& a) {
    a.tag("edmd-state");
    a(p, image, cnt, ev, id, slot, cells, L, max_base, now, scale_ref, t_scale, rate, ncoll,
      ncross, nstale, npairs, nscan);
    a.tag("edmd-granular");
    a(t_last, ntc);
  }

  std::size_t size() const { return p.size(); }
  /// Current diameter scale (1 after compression).
  double diameter_scale() const { return scale_ref + rate * (now - t_scale); }
  /// Contact distance of i and j at unit scale: the diameter, 1.
  double base_contact(std::size_t, std::size_t) const { return 1.0; }
  double contact(std::size_t i, std::size_t j) const {
    return base_contact(i, j) * diameter_scale();
  }
  /// Position of i at the current time.
  Vec<D> pos_now(std::size_t i) const {
    return p.position(i) + p.velocity(i) * (now - p.local_time(i));
  }
  void advance(std::uint32_t i) {
    p.position(i) += p.velocity(i) * (now - p.local_time(i));
    p.local_time(i) = now;
  }

  /// Brings particle i to now and into the box [0, L)^D, counting the images it left.
  void wrap(std::uint32_t i) {
    advance(i);
    for (int k = 0; k < D; ++k) wrap_axis(i, k);
  }
  /// Brings coordinate k of i's record into [0, L), counting the images it left.
  void wrap_axis(std::uint32_t i, int k) {
    auto x = p.position(i);
    const double f = std::floor(x[k] / L);
    if (f != 0.0) {
      x[k] -= f * L;
      image[i * D + k] += static_cast<std::int32_t>(f);
    }
    if (x[k] >= L) {  // -tiny wraps to L by round-off
      x[k] -= L;
      ++image[i * D + k];
    }
  }
  /// Builds the cell grid for the current diameters (at most `per_particle` cells per
  /// particle, each at least `extra` wider than the largest contact distance) and files
  /// every particle (in the box) in its cell.
  void build_cells(double per_particle, double extra = 0.0) {
    const std::size_t n = size();
    cells.build(L, max_base * diameter_scale(), n, per_particle, extra);
    for (std::uint32_t i = 0; i < n; ++i) {
      std::array<int, D> c;
      for (int k = 0; k < D; ++k) c[k] = cells.coord(p.position(i)[k]);
      cells.insert(i, cells.index(c));
    }
  }

  /// Time of the next crossing of i out of its cell (i is at the current time).
  void predict_crossing(std::uint32_t i) {
    const auto c = cells.coords(cells.cell_of(i));
    const auto x = p.position(i);
    const auto v = p.velocity(i);
    double best = never;
    std::int32_t code = 0;
    for (int k = 0; k < D; ++k) {
      double t = never;
      if (v[k] > 0.0) {
        t = (cells.face_hi(c[k]) - x[k]) / v[k];
        if (t < best) best = t, code = 2 * k + 1;
      } else if (v[k] < 0.0) {
        t = (cells.face_lo(c[k]) - x[k]) / v[k];
        if (t < best) best = t, code = 2 * k;
      }
    }
    ev[i].t_cross = now + std::max(best, 0.0);
    ev[i].cross = code;
  }

  /// Records a scan's two earliest pair events (relative times) as i's pair events.
  void store(std::uint32_t i, const Top2& top) {
    Ev& e = ev[i];
    e.t_pair = now + top.t1;
    e.partner = top.p1;
    e.pcount = top.p1 >= 0 ? cnt[top.p1] : 0;
    e.t_pair2 = now + top.t2;
    e.partner2 = top.p2;
    e.pcount2 = top.p2 >= 0 ? cnt[top.p2] : 0;
  }

  /// Packing fraction at the current diameters.
  double packing() const {
    double v = 0.0;
    for (std::size_t i = 0; i < p.size(); ++i) v += ball_volume(D, contact(i, i));
    return v / std::pow(L, D);
  }
  /// Largest diameter scale the current cells allow ((cell width - extra) / largest base
  /// diameter, `extra` as in build_cells). In the one-cell box (fewer than 3 cells per
  /// side) the limit is half the box side: a sphere must not touch its own image.
  double max_scale_for_cells(double extra = 0.0) const {
    return (cells.per_side() == 1 ? 0.5 * L : cells.width() - extra) / max_base;
  }
  /// Checks all pairs (O(N^2)); throws std::logic_error naming an overlapping pair. With
  /// `sheared`, the images above the box are displaced by `delta` along x (Lees–Edwards,
  /// lees_edwards.hpp).
  void check_overlaps(bool sheared = false, double delta = 0.0) const {
    const double tol = 1e-9;
    for (std::size_t i = 0; i < size(); ++i) {
      const Vec<D> xi = pos_now(i);
      for (std::size_t j = i + 1; j < size(); ++j) {
        Vec<D> r = xi - pos_now(j);
        if (D >= 2 && sheared) {
          constexpr int y = D >= 2 ? 1 : 0;
          const double f = std::round(r[y] / L);
          r[y] -= f * L;
          r[0] -= f * delta;
        }
        for (int k = 0; k < D; ++k) r[k] -= L * std::round(r[k] / L);
        const double s = contact(i, j);
        if (r.squaredNorm() < s * s * (1.0 - tol))
          throw std::logic_error("EDMD overlap at t = " + std::to_string(now) + ": particles " +
                                 std::to_string(id[i]) + ", " + std::to_string(id[j]) +
                                 " at distance " + std::to_string(r.norm()) + " < " +
                                 std::to_string(s));
      }
    }
  }

  /// Pair time of i (at now) with j's cell image (position + shift), or never.
  [[gnu::always_inline]] double pair_time(std::uint32_t i, std::uint32_t j, const Vec<D>& shift,
                                          double sc) const {
    const Vec<D> r =
        p.position(j) + p.velocity(j) * (now - p.local_time(j)) + shift - p.position(i);
    const Vec<D> v = p.velocity(j) - p.velocity(i);
    const double b = base_contact(i, j);
    return contact_time(r.dot(v), v.squaredNorm(), r.squaredNorm(), b * sc, b * rate);
  }
};

}  // namespace hypergas::edmd

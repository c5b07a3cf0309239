// hypergas/dsmc/detail/state.hpp -- the state that the pieces of the DSMC engine share (the
// velocities, the epochs' random stream, the majorant, the clock and the counters) and the
// per-candidate kernel on it: draw a candidate, test it, collide it. The kernel functions
// are force-inlined into the candidate loop (lane.hpp), the block schedule (parallel.hpp)
// and the self-check (self_check.hpp), which all decide a candidate the same way.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/detail/candidates.hpp"
#include "hypergas/dsmc/majorant.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/update.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/tally/tally.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::dsmc::detail {

/// What a collision reports to: nothing (NoHook, the plain kernel), a tally (TallyHook: the
/// old and new velocities of both particles, hypergas/tally/tally.hpp) or collective fluxes
/// (FluxHook and LaneFluxHook, hypergas/tally/fluxes.hpp).
/// The candidate loop is compiled once for each, so a run without a tally runs the
/// same code as an engine that has none.
struct NoHook {
  static constexpr bool active = false;
};
struct TallyHook {
  static constexpr bool active = true;
  tally::Tally* t = nullptr;
  /// Particles i and j went from oi, oj to ni, nj.
  template <int D, Features F>
  [[gnu::always_inline]] void collided(const Particles<D, F>& p, std::uint32_t i,
                                       std::uint32_t j, const double* oi, const double* oj,
                                       const double* ni, const double* nj) const {
    int si = 0, sj = 0;
    if constexpr (F.species) si = p.species(i), sj = p.species(j);
    t->exchange<D, F.species>(oi, oj, ni, nj, si, sj);
  }
};
/// Collective fluxes (tally/fluxes.hpp: one species only), with or without a tally (t may
/// be null: the branch is the same at every collision). Tagged: the fluxes' tagged particles
/// hear of every candidate (the exact scheme); the lanes scheme has none (LaneFluxHook), so
/// its candidate loop is compiled once more per engine, not twice.
template <bool WithTally, bool Tagged = true>
struct FluxHook {
  static constexpr bool active = true;
  tally::Fluxes* f = nullptr;
  tally::Tally* t = nullptr;
  template <int D, Features F>
  [[gnu::always_inline]] void collided(const Particles<D, F>& p, std::uint32_t i,
                                       std::uint32_t j, const double* oi, const double* oj,
                                       const double* ni, const double* nj) const {
    f->exchange<D>(oi, oj, ni, nj);
    if constexpr (WithTally)
      if (t) TallyHook{t}.collided(p, i, j, oi, oj, ni, nj);
  }
  /// Candidate K collided i and j (old velocities oi, oj): tagged particles' displacements.
  [[gnu::always_inline]] void at_candidate(std::uint64_t K, std::uint32_t i, std::uint32_t j,
                                           const double* oi, const double* oj) const
    requires Tagged
  {
    f->tagged_collision(K, i, j, oi, oj);
  }
};
using LaneFluxHook = FluxHook<true, false>;

/// The k-th of m uniform order statistics on [0, 1], Beta(k, m - k + 1), drawn as
/// X / (X + Y) with X ~ Gamma(k) first and Y ~ Gamma(m - k + 1): where an epoch of m
/// candidates stopped at its k-th (stepping.hpp, kac_lanes.hpp).
inline double order_statistic(Rng& rng, std::uint64_t k, std::uint64_t m) {
  std::gamma_distribution<double> ga(static_cast<double>(k)), gb(static_cast<double>(m - k + 1));
  const double x = ga(rng), y = gb(rng);
  return x / (x + y);
}

template <class Model, int D>
[[gnu::noinline]] Vec<D> deflect_outlined(const Vec<D>& g, double gn, EventStream& rng) {
  return Model::template deflect<D>(g, gn, rng);
}

/// Whether pair (i, j) of p with acceptance uniform u is accepted now with bound G.
template <int D, Features F, class Model>
[[gnu::always_inline]] inline bool accepts_pair(const Particles<D, F>& p, const Model& model,
                                                std::uint32_t i, std::uint32_t j, double u,
                                                double G) {
  if constexpr (Model::needs_majorant) {
    constexpr int stride = Particles<D, F>::stride;
    const double* v = p.velocity_data().data();
    double g2 = 0.0;
    for (int d = 0; d < D; ++d) {
      const double x = v[std::size_t(i) * stride + d] - v[std::size_t(j) * stride + d];
      g2 += x * x;
    }
    return model.accept(g2, u, G);
  } else {
    (void)p, (void)model, (void)i, (void)j, (void)u, (void)G;
    return true;
  }
}

/// Collides particles i and j of p with the scattering stream rng_k (candidate K's) and the
/// restitution impulse, reports it to `hook`, and returns the larger of the two new squared
/// speeds (0 for models without a majorant). The one collision of every DSMC scheme.
template <class Model, bool Outlined = false, int D, Features F, class Hook>
[[gnu::always_inline]] inline double collide_pair(Particles<D, F>& p, std::uint32_t i,
                                                  std::uint32_t j, double impulse,
                                                  EventStream rng_k, std::uint64_t K,
                                                  const Hook& hook) {
  using Map = Eigen::Map<Vec<D>>;
  constexpr int stride = Particles<D, F>::stride;
  double* v = p.velocity_data().data();
  Map vi(v + std::size_t(i) * stride), vj(v + std::size_t(j) * stride);
  const Vec<D> g = vi - vj;
  const double gn = std::sqrt(g.squaredNorm());
  Vec<D> delta;
  if constexpr (Outlined) delta = deflect_outlined<Model, D>(g, gn, rng_k) - g;
  else delta = Model::template deflect<D>(g, gn, rng_k) - g;
  if constexpr (Hook::active) {
    const Vec<D> oi = vi, oj = vj;
    apply_deflection<D>(p, i, j, vi, vj, delta, impulse);
    hook.collided(p, i, j, oi.data(), oj.data(), vi.data(), vj.data());
    if constexpr (requires { hook.at_candidate(K, i, j, oi.data(), oj.data()); })
      hook.at_candidate(K, i, j, oi.data(), oj.data());
  } else {
    (void)hook, (void)K;
    apply_deflection<D>(p, i, j, vi, vj, delta, impulse);
  }
  if constexpr (Model::needs_majorant)
    return std::max(vi.squaredNorm(), vj.squaredNorm());
  else
    return 0.0;
}

/// Shared state of Engine<D, Model, F>: plain data with the per-candidate kernel. Every
/// member but `draws` and `impulse` is saved by the engine's io() (the draws are a function
/// of the seed, the impulse of cfg).
template <int D, class Model, Features F>
struct State {
  using ParticlesT = Particles<D, F>;
  using ModelType = Model;
  static constexpr int dim = D;
  static constexpr int stride = ParticlesT::stride;
  static constexpr bool checks = true;  // the candidate loop's self-check (self_check.hpp)

  State(const Config& c, Model m) : cfg(c), model(m), rng(Rng(c.seed).split(2)), draws(c.seed) {}
  State(const Config& c, Model m, ParticlesT particles)
      : cfg(c), p(std::move(particles)), model(m), rng(Rng(c.seed).split(2)), draws(c.seed) {}

  Config cfg;
  ParticlesT p;
  Model model;
  Rng rng;               // the epochs' Poisson counts and order-statistic times
  std::uint32_t n = 0;
  double c = 0.0;        // rate constant
  double lambda = 0.0;   // candidate rate N c G^a / 2 (per mean collision time)
  SpeedBound bound;
  double raise_to = 0.0;  // pending new maximum squared speed
  double time = 0.0;
  double observed_at = -1.0;
  std::uint64_t collisions = 0, candidates = 0, since_scan = 0;
  CandidateStream draws;  // candidate K's draws: a function of (seed, K)
  bool self_check = false;
  std::uint64_t check_failures = 0;
  std::array<double, max_species> species_w{};  // the observers' species mass table
  tally::Slot tally;      // the collision-level observer's tally, if one was installed
  // Granular gases (dsmc/granular.hpp). impulse = (1 + alpha) / 2 scales each collision's
  // change of relative velocity (derived from cfg, not saved by io()); the velocities are
  // stored as v / scale with
  // log_scale = ln(scale); real_time is the time in mean collision times at kT0.
  double impulse = 1.0;
  double log_scale = 0.0;
  double real_time = 0.0;
  double kT0 = 0.0;          // the equilibrium temperature of the initial energy
  std::uint64_t kicks = 0;   // white-noise kicks so far (the next at (kicks + 1/2) drive_dt)
  // The lanes scheme (kac_lanes.hpp): deals so far (the next at deals * cfg.epoch) and
  // segments run so far (each keys its lanes' random streams).
  std::uint64_t deals = 0, segments = 0;

  /// Candidate K: its pair and acceptance uniform (candidates.hpp).
  void draw(std::uint64_t K, std::uint32_t& i, std::uint32_t& j, double& u) const {
    draws.draw(K, n, i, j, u);
  }
  void draw_pair(std::uint64_t K, std::uint32_t& i, std::uint32_t& j) const {
    draws.draw_pair(K, n, i, j);
  }
  /// Whether pair (i, j) with acceptance uniform u is accepted now with bound G.
  [[gnu::always_inline]] bool accepts(std::uint32_t i, std::uint32_t j, double u, double G) const {
    return accepts_pair(p, model, i, j, u, G);
  }
  /// Collides pair (i, j) as candidate K (its scattering words from word 2 of K on) and
  /// reports it to `hook`; returns the larger of the two new squared speeds. Outlined: the
  /// scattering is called, not inlined (the thread lanes run faster so: docs/benchmarks.md,
  /// "Kept designs"); the result is the same.
  template <bool Outlined = false, class Hook = NoHook>
  [[gnu::always_inline]] double collide(std::uint32_t i, std::uint32_t j, std::uint64_t K,
                                        const Hook& hook = Hook{}) {
    return collide_pair<Model, Outlined>(p, i, j, impulse, draws.scattering(K), K, hook);
  }
};

}  // namespace hypergas::dsmc::detail

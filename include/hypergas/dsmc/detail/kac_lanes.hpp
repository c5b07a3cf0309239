// hypergas/dsmc/detail/kac_lanes.hpp -- the lanes scheme: the gas cut into L lanes of about
// M particles, each running the exact Kac process of its own particles, dealt anew every
// epoch.
//
// Why. In the exact N-particle process every candidate may touch any particle, so its
// order is a chain of random loads through all of memory: one system cannot use a second
// core, and above the cache its rate falls (docs/benchmarks.md). A lane of M particles
// (default 2^19 bytes of records: 16384 in 3D) sits in a core's L2 cache, lanes are
// independent within an epoch, and their count L = max(1, round(N / M)) depends on N
// alone, never on the thread count.
//
// The process. Lane l holds particles [begin(l), begin(l + 1)), begin(l) = floor(l N / L).
// Within an epoch each lane is the exact Kac process of its m_l particles with pair rate
// c |g|^a / (m_l - 1) (c of the whole gas: each particle still collides once per unit time
// at equilibrium), simulated like the exact scheme (stepping.hpp): Poisson candidate counts
// under the lane's own majorant, a raise stopping the lane's epoch at its candidate's order
// statistic. The deals:
//   - deal 0 (t = 0): a uniform random permutation of all particles (Fisher-Yates);
//   - deal k >= 1 (t = k epoch): the lanes are matched in pairs by a uniform random perfect
//     matching (with L odd one lane sits out); each pair exchanges a uniformly random
//     floor(min(m_a, m_b) / 2) particles of each lane with the other's. This moves the
//     particles within the task that runs both lanes next, so a deal costs no pass of its
//     own through memory and no memory beyond the velocities.
// Stationary state: every in-lane collision keeps the lane's energy and momentum, so the
// global ones too, and keeps the uniform measure on the lane's shell; a deal is a
// permutation drawn independently of the velocities. Both therefore keep the uniform measure
// on the global energy-momentum shell, the exact process's equilibrium. What differs is the
// dynamics: lane momenta are frozen within an epoch. docs/validation.md ("The lanes scheme")
// derives the exact mean anisotropy of Maxwell molecules under this process; its bias is
// O(1 / M) per unit time.
//
// Randomness. Lane l of segment g (a segment ends at an epoch's end, an observation, a
// white-noise kick or the run's end) draws from Rng(seed).split(11).split(g).split(l); deal
// k from Rng(seed).split(12).split(k). Tasks (a lane, or a matched pair with its exchange)
// are taken by T threads in any order; nothing a task does depends on another task of the
// same segment, and the tally sums are exact (tally/tally.hpp), so the gas and every file
// are bit for bit the same for every thread count.
//
// Particle identity: a deal moves particles between array slots. Observers of the whole
// gas (moments, histograms, the collective stress and heat flux of --transport, kept by
// the collisions through LaneFluxHook) are unaffected; particle i is not the same particle
// across deals, so tagged particles (self-diffusion) need the exact scheme.
#pragma once

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <random>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/detail/candidates.hpp"
#include "hypergas/dsmc/detail/lane.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/dsmc/granular.hpp"
#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/thread_team.hpp"

namespace hypergas::dsmc::detail {

/// Bytes of particle records per lane by default: two lanes (a deal's task) fit a 1 MiB L2.
inline constexpr std::uint32_t default_lane_bytes = 1u << 19;

/// The default lane size M for records of `stride` doubles.
constexpr std::uint32_t default_lane_size(int stride) {
  return default_lane_bytes / (8u * static_cast<std::uint32_t>(stride));
}

/// The cut of n particles into lanes.
struct LaneLayout {
  std::uint32_t n = 0;
  std::uint32_t lanes = 1;
  /// L = round(n / m), at least 1 and at most n / 2 (lanes of at least 2 particles).
  static LaneLayout make(std::uint32_t n, std::uint32_t m) {
    LaneLayout l;
    l.n = n;
    const double r = std::round(static_cast<double>(n) / std::max<std::uint32_t>(m, 2));
    l.lanes = static_cast<std::uint32_t>(std::clamp(r, 1.0, static_cast<double>(n / 2)));
    return l;
  }
  std::uint32_t begin(std::uint32_t l) const {
    return static_cast<std::uint32_t>(std::uint64_t(l) * n / lanes);
  }
  std::uint32_t count(std::uint32_t l) const { return begin(l + 1) - begin(l); }
};

/// The lane size a config asks for (cfg.lane_size, or the default for the stride).
inline std::uint32_t lane_size_of(const Config& cfg, int stride) {
  return cfg.lane_size ? cfg.lane_size : default_lane_size(stride);
}

/// What one lane did in one segment.
struct LaneCounts {
  std::uint64_t collisions = 0, candidates = 0;
};

/// One lane as the candidate loop's state (lane.hpp, run_lane): particles [base, base + n)
/// of the gas, the lane's own candidate draws and majorant.
template <int D, class Model, Features F>
struct LaneView {
  using ParticlesT = Particles<D, F>;
  using ModelType = Model;
  static constexpr int dim = D;
  static constexpr int stride = ParticlesT::stride;
  static constexpr bool checks = false;

  ParticlesT& p;
  const Model& model;
  double impulse;
  std::uint32_t base, n;
  CandidateStream draws;
  SpeedBound bound;

  [[gnu::always_inline]] void draw(std::uint64_t K, std::uint32_t& i, std::uint32_t& j,
                                   double& u) const {
    draws.draw(K, n, i, j, u);
    i += base;
    j += base;
  }
  void draw_pair(std::uint64_t K, std::uint32_t& i, std::uint32_t& j) const {
    draws.draw_pair(K, n, i, j);
    i += base;
    j += base;
  }
  [[gnu::always_inline]] bool accepts(std::uint32_t i, std::uint32_t j, double u, double G) const {
    return accepts_pair(p, model, i, j, u, G);
  }
  template <bool Outlined = false, class Hook = NoHook>
  [[gnu::always_inline]] double collide(std::uint32_t i, std::uint32_t j, std::uint64_t K,
                                        const Hook& hook = Hook{}) {
    return collide_pair<Model, Outlined>(p, i, j, impulse, draws.scattering(K), K, hook);
  }
};

/// Runs the exact Kac process of particles [b, b + m) of s for a time h, drawing from
/// `rng`, through the candidate loop (lane.hpp); reports every collision to `hook`.
template <class Hook, int D, class Model, Features F>
LaneCounts kac_lane(State<D, Model, F>& s, std::uint32_t b, std::uint32_t m, double h, Rng rng,
                    const Hook& hook) {
  LaneCounts out;
  if (m < 2 || !(h > 0.0)) return out;
  LaneView<D, Model, F> view{s.p, s.model, s.impulse, b, m, CandidateStream(rng()), {}};
  if constexpr (Model::needs_majorant) view.bound.rescan(s.p, b, std::size_t(b) + m);
  const double a = s.model.exponent();
  double t = 0.0;
  std::uint64_t K = 0;  // the lane's candidates so far in this segment
  Lane lane;
  for (;;) {
    double ga = 1.0;
    if constexpr (Model::needs_majorant) ga = view.bound.bound_power(a);
    const double rest = h - t;
    std::poisson_distribution<std::uint64_t> pois(0.5 * m * s.c * ga * rest);
    const std::uint64_t M = pois(rng);
    lane.raised = false;
    lane.raise_s2 = 0.0;
    const std::uint64_t k = run_lane<true, false, false>(view, lane, K, M, view.bound.bound(), hook);
    K += k;
    if (!lane.raised) break;
    // the raise stops the lane's epoch at candidate k of M: the k-th of M uniform order
    // statistics on [t, h] (stepping.hpp, advance_exact)
    t = std::min(t + rest * order_statistic(rng, k, M), h);
    view.bound.set(lane.raise_s2);
    if (!(t < h)) break;
  }
  out.collisions = lane.collisions;
  out.candidates = K;
  return out;
}

/// Deal k >= 1 within one task: lanes a and b exchange a uniformly random half (the
/// smaller lane's size over two, rounded down) of their particles.
template <int D, Features F>
void exchange_halves(Particles<D, F>& p, std::uint32_t a0, std::uint32_t ma, std::uint32_t b0,
                     std::uint32_t mb, Rng& rng) {
  const std::uint32_t k = std::min(ma, mb) / 2;
  // partial Fisher-Yates: the first k slots of each lane become a uniform random k-subset
  for (std::uint32_t q = 0; q < k; ++q) p.swap(a0 + q, a0 + q + rng.below(ma - q));
  for (std::uint32_t q = 0; q < k; ++q) p.swap(b0 + q, b0 + q + rng.below(mb - q));
  for (std::uint32_t q = 0; q < k; ++q) p.swap(a0 + q, b0 + q);
}

/// Reads particles [b, b + m) in order, so that the exchange's random swaps that follow hit
/// the cache: a sequential pass streams from memory at full bandwidth, random first touches
/// would each wait for memory.
template <int D, Features F>
void warm_lane(const Particles<D, F>& p, std::uint32_t b, std::uint32_t m) {
  constexpr std::size_t line = 64 / sizeof(double);
  const double* v = p.velocity_data().data();
  for (std::size_t i = std::size_t(b) * Particles<D, F>::stride,
                   e = std::size_t(b + m) * Particles<D, F>::stride;
       i < e; i += line)
    __builtin_prefetch(v + i, 1);
}

/// The lanes' threads and per-thread tallies (not state: set_threads rebuilds them).
class LaneTeam {
 public:
  void configure(int threads) {
    threads_ = threads;
    if (threads == 1) team_.reset();
    else if (!team_ || team_->size() != threads) team_ = std::make_unique<ThreadTeam>(threads);
    deltas_.clear();
  }
  int threads() const { return threads_; }

  /// Runs task(q, hook of the thread) for q = 0 .. tasks - 1 on the team, in any order.
  /// With a tally, thread 0 reports to it and the others to their own deltas, merged after
  /// (exact sums: the same for any thread count). WithFluxes: the same for the collective
  /// fluxes `fluxes` (not null), through LaneFluxHook.
  template <bool WithFluxes = false, class Task>
  void run(std::uint32_t tasks, tally::Tally* main, tally::Fluxes* fluxes, Task&& task) {
    const int T = std::min<int>(threads_, static_cast<int>(std::max<std::uint32_t>(tasks, 1)));
    if (main) {
      if (deltas_.size() < std::size_t(T)) deltas_.resize(std::size_t(T));
      for (int t = 1; t < T; ++t)
        if (!(deltas_[std::size_t(t)].layout() == main->layout()))
          deltas_[std::size_t(t)] = tally::Tally(main->layout());
    }
    if constexpr (WithFluxes) {
      flux_deltas_.resize(std::size_t(T));
      for (int t = 1; t < T; ++t) flux_deltas_[std::size_t(t)] = fluxes->delta();
    }
    const auto work = [&](int t, std::atomic<std::uint32_t>* next) {
      const auto take = [&](const auto& hook) {
        for (std::uint32_t q = next ? next->fetch_add(1) : 0; q < tasks;
             q = next ? next->fetch_add(1) : q + 1)
          task(q, hook);
      };
      tally::Tally* mine = main ? (t == 0 ? main : &deltas_[std::size_t(t)]) : nullptr;
      if constexpr (WithFluxes)
        take(LaneFluxHook{t == 0 ? fluxes : &flux_deltas_[std::size_t(t)], mine});
      else if (mine)
        take(TallyHook{mine});
      else
        take(NoHook{});
    };
    if (T <= 1 || !team_) {
      work(0, nullptr);
    } else {
      std::atomic<std::uint32_t> next{0};
      team_->run([&](int t) {
        if (t < T) work(t, &next);
      });
    }
    for (int t = 1; t < T; ++t) {
      if (main) {
        main->merge(deltas_[std::size_t(t)]);
        deltas_[std::size_t(t)].clear();
      }
      if constexpr (WithFluxes) fluxes->merge(flux_deltas_[std::size_t(t)]);
    }
  }

 private:
  int threads_ = 1;
  std::unique_ptr<ThreadTeam> team_;
  std::vector<tally::Tally> deltas_;
  std::vector<tally::Fluxes> flux_deltas_;
};

/// Deal 0: a uniform random permutation of all particles.
template <int D, Features F>
void shuffle_all(Particles<D, F>& p, Rng rng) {
  for (std::size_t i = p.size() - 1; i > 0; --i) p.swap(i, rng.below(i + 1));
}

/// The lanes scheme up to t_end: segments between deals, kicks, observations and t_end.
template <int D, class Model, Features F>
void advance_lanes(State<D, Model, F>& s, LaneTeam& team, const std::function<void()>& poll,
                   double t_end) {
  tally::Fluxes* const fluxes = s.tally.fluxes.get();
  if (fluxes && (F.species || fluxes->tagged() > 0))
    throw InvalidInput("DSMC: the lanes scheme keeps collective fluxes of one species without "
                       "tagged particles only: a deal moves particles between slots");
  const LaneLayout lay = LaneLayout::make(s.n, lane_size_of(s.cfg, State<D, Model, F>::stride));
  const std::uint32_t L = lay.lanes;
  std::vector<LaneCounts> counts(L);
  std::vector<std::uint32_t> order;
  while (s.time < t_end) {
    granular_upkeep(s);
    const bool deal = s.time >= static_cast<double>(s.deals) * s.cfg.epoch;
    const std::uint64_t k = s.deals;
    if (deal) ++s.deals;
    const double target = std::min({t_end, next_kick(s), static_cast<double>(s.deals) * s.cfg.epoch});
    const double h = target - s.time;
    const Rng lane_rng = Rng(s.cfg.seed).split(11).split(s.segments);
    const Rng deal_rng = Rng(s.cfg.seed).split(12).split(k);
    ++s.segments;
    const bool pairs = deal && k > 0 && L > 1;
    if (deal && k == 0 && L > 1) shuffle_all(s.p, deal_rng.split(0));
    if (pairs) {  // the matching: a uniform random order of the lanes, taken two by two
      order.resize(L);
      for (std::uint32_t l = 0; l < L; ++l) order[l] = l;
      Rng r = deal_rng.split(1);
      for (std::uint32_t l = L - 1; l > 0; --l) std::swap(order[l], order[r.below(l + 1)]);
    }
    const std::uint32_t tasks = pairs ? (L + 1) / 2 : L;
    const auto task = [&](std::uint32_t q, const auto& hook) {
      if (!pairs) {
        counts[q] = kac_lane(s, lay.begin(q), lay.count(q), h, lane_rng.split(q), hook);
        return;
      }
      const std::uint32_t a = order[2 * q];
      if (2 * q + 1 < L) {
        const std::uint32_t b = order[2 * q + 1];
        Rng r = deal_rng.split(2 + std::uint64_t(q));
        warm_lane(s.p, lay.begin(a), lay.count(a));
        warm_lane(s.p, lay.begin(b), lay.count(b));
        exchange_halves(s.p, lay.begin(a), lay.count(a), lay.begin(b), lay.count(b), r);
        counts[b] = kac_lane(s, lay.begin(b), lay.count(b), h, lane_rng.split(b), hook);
      }
      counts[a] = kac_lane(s, lay.begin(a), lay.count(a), h, lane_rng.split(a), hook);
    };
    // the flux hook is compiled for one species only (as in the exact scheme, stepping.hpp)
    if constexpr (!F.species) {
      if (fluxes) team.run<true>(tasks, s.tally.tally.get(), fluxes, task);
      else team.run(tasks, s.tally.tally.get(), nullptr, task);
    } else {
      team.run(tasks, s.tally.tally.get(), nullptr, task);
    }
    const double t0 = s.time;
    for (const LaneCounts& c : counts) {
      s.collisions += c.collisions;
      s.candidates += c.candidates;
      s.since_scan += c.candidates;
    }
    s.time = target;
    granular_after(s, t0);
    if (poll) poll();
  }
}

}  // namespace hypergas::dsmc::detail

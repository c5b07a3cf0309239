// hypergas/dsmc/engine.hpp -- the spatially homogeneous Boltzmann gas (DSMC, Kac process).
//
// Public API (what the command line calls):
//
//   dsmc::Config cfg;                      // n, vhs_exponent, scheme, dt, seed, init,
//                                          // initial (kT, kT_species, fraction, mass_ratio)
//   dsmc::Engine<3, dsmc::HardSpheres> e(cfg);          // samples the initial state
//   e.run_until(10.0, &observer, 0.1);     // observe at t = 0, 0.1, ..., 10 (mean coll. times)
//   e.time(); e.collisions(); e.candidates(); e.particles(); e.bytes_per_particle();
//
//   Model is HardSpheres, MaxwellMolecules or VariableHardSpheres (dsmc/models.hpp;
//   registry.hpp turns a model name into the type). Two
//   species: Engine<D, Model, Features{.species = true}> (masses from the species table,
//   set by the initial state from cfg.initial.mass_ratio and .fraction).
//
// The process. N particles carry velocities only (no positions are stored or compiled
// in). Each unordered pair collides at rate c |g|^a / (N - 1) (g = relative velocity,
// a = model exponent, c = 1 / <|g|^a>_eq from dsmc/time_unit.hpp, so that at equilibrium
// every particle collides once per unit time). The exact scheme simulates this Kac master
// equation without time-step error by thinning: candidates form a Poisson process of rate
// Lambda = N c G^a / 2, where G >= |g| for every pair at every moment (dsmc/majorant.hpp);
// a candidate is a uniformly chosen pair, accepted with probability (|g|/G)^a. Over an
// epoch [t, t_end] with constant G the number of candidates is Poisson(Lambda (t_end - t))
// and their times are uniform order statistics, so no exponential waiting time is drawn per
// candidate. When an accepted collision raises a speed above the bound, the epoch stops at
// that candidate, the epoch's last one included; its time is
// the k-th of M uniform order statistics, t + (t_end - t) Beta(k, M - k + 1) (exact: the
// marks do not depend on the times), the bound is raised and a new epoch starts there (the
// Poisson process after a stopping time is fresh).
// Maxwell molecules need no majorant: every candidate collides.
//
// Bird's no-time-counter scheme (scheme = ntc) instead takes steps of dt: each step draws
// floor(Lambda dt + U) candidates with G frozen at the start of the step and accepts with
// min(1, (|g|/G)^a). Its step errors: the candidate count carries no Poisson noise, and pairs
// faster than the frozen G (created within the step) are under-sampled until the next step.
//
// 1D: with equal masses a collision only keeps or swaps the two velocities (the only
// solutions of momentum and energy conservation), so the velocity distribution never
// relaxes; 1D scenes therefore use two species with different masses.
//
// Random numbers are counter-based (counter_rng.hpp): candidate number K of the run (K = 0,
// 1, 2, ... over all epochs) draws its pair, its acceptance uniform and its scattering
// direction from SplitMix64 in counter mode keyed by the seed, with K in the counter. What
// candidate K draws therefore does not depend on which thread processes it or when; only
// the Poisson counts and order-statistic times of the epochs come from a sequential stream.
//
// The candidate loop (run_lane): candidates come in batches of 16. A batch (pairs and
// acceptance uniforms) is drawn one batch ahead and its velocities prefetched (random access
// to N = 1e6 velocities is cache-miss bound); then all 16 are tested at once - no velocity
// changes in between, so the loads overlap and no branch waits on them - and the accepted
// ones are taken in order (count-trailing-zeros on the acceptance mask). Exactness is kept
// by re-testing, after a collision, the later candidates of the batch that share one of its
// two particles. With one thread this loop is the engine.
//
// Several threads (set_threads(T)): candidates are taken in blocks of N/64 (2048 .. 65536),
// one contiguous chunk per thread. Each thread runs its chunk through the same loop,
// deferring the candidates that touch a particle of an earlier chunk or of a candidate it
// deferred before; thread 0 then takes the deferred ones in block order
// (dsmc/level_schedule.hpp). A raise of the bound at candidate k* ends the epoch there, as in
// the sequential process: what later chunks applied after k* is undone from a copy of the
// old velocities. The state after every call is bit for bit the state of the one-thread
// engine, for every T (tests/unit/test_dsmc_parallel.cpp).
//
// A self-check mode (set_self_check) re-tests every pending candidate before each step of
// the candidate loop and, with threads, replays each block sequentially on a copy of the
// velocities; it counts disagreements (tests/unit/test_dsmc_engine.cpp and
// test_dsmc_parallel.cpp require zero). Hard spheres accept by comparing squares, so a
// rejected candidate costs no square root; equal-mass scenes compile the mass weights to
// 1/2; the velocity array is advised onto transparent huge pages (dsmc/huge_pages.hpp).
// Observers are called every `every` time units, never per collision.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <random>
#include <type_traits>
#include <utility>
#include <vector>

#include "hypergas/checkpoint.hpp"
#include "hypergas/counter_rng.hpp"
#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/huge_pages.hpp"
#include "hypergas/dsmc/level_schedule.hpp"
#include "hypergas/dsmc/majorant.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/time_unit.hpp"
#include "hypergas/dsmc/update.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/thread_team.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hypergas::dsmc {

/// The DSMC engine for dimension D, collision model `Model`, particle features F (Features{}
/// or Features{.species = true}). Time in equilibrium mean collision times.
// clang-format off
template <int D, class Model, Features F = Features{}>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions) && (!F.masses) &&
           (!F.radii)
class Engine {
  // clang-format on
 public:
  using Config = dsmc::Config;
  using ParticlesT = Particles<D, F>;
  static constexpr int dim = D;
  static constexpr int stride = ParticlesT::stride;

  /// Samples cfg.n particles in the initial state cfg.init (two species only with
  /// F.species). Throws InvalidInput on a bad configuration.
  explicit Engine(const Config& cfg) : Engine(cfg, initial_particles(cfg)) {}

  /// Starts from the given particles (velocities in units where the species-0 mass is 1);
  /// cfg.n and cfg.init are ignored. Total momentum should be zero (see time_unit.hpp).
  Engine(const Config& cfg, ParticlesT particles)
      : cfg_(cfg), p_(std::move(particles)), model_(make_model(cfg)), rng_(Rng(cfg.seed).split(2)),
        draws_(cfg.seed, Domain::dsmc_candidate) {
    cfg_.n = p_.size();
    validate(cfg_);  // also checks 2 <= n < 2^32
    n_ = static_cast<std::uint32_t>(p_.size());
    c_ = dsmc::rate_constant(p_, model_.exponent());
    detail::advise_huge_pages(p_.velocity_data().data(),
                              p_.velocity_data().size() * sizeof(double));
    retune(true);
  }

  /// Restores an engine saved by io() (hypergas/checkpoint.hpp); it continues bit for bit as
  /// the saved one would have. Throws InvalidInput if the file holds another engine,
  /// dimension, model or feature set.
  Engine(const Config& cfg, checkpoint::Reader& in)
      : cfg_(cfg), model_(make_model(cfg)), rng_(Rng(cfg.seed).split(2)),
        draws_(cfg.seed, Domain::dsmc_candidate) {
    io(in);
  }
  Engine(Engine&&) noexcept = default;
  Engine& operator=(Engine&&) noexcept = default;

  /// Saves or restores the complete state: velocities, the epochs' random stream, the
  /// majorant and the counters (the candidates' draws are functions of their number, so the
  /// number of candidates so far is their whole state). The thread count is not state.
  template <class Archive>
  void io(Archive& a) {
    static_assert(std::is_trivially_copyable_v<Rng> && std::is_trivially_copyable_v<Model> &&
                  std::is_trivially_copyable_v<Config>);
    a.tag(identity());
    a(cfg_, p_, model_, rng_, n_, c_, lambda_, bound_, raise_to_, time_, observed_at_);
    a(collisions_, candidates_, since_scan_, self_check_, check_failures_, species_w_);
    if (p_.size() != n_) throw InvalidInput("checkpoint: particle count does not match");
  }
  /// "dsmc D=3 model=hs species=0": what a checkpoint must match.
  static std::string identity() {
    return "dsmc D=" + std::to_string(D) + " model=" + std::string(Model::name) +
           " species=" + std::to_string(int(F.species));
  }

  /// Calls obs with the current state (velocities, time, counters); changes nothing.
  void observe(Observer& obs) {
    Snapshot s = make_snapshot(p_);
    s.time = time_;
    s.collisions = collisions_;
    s.collisions_per_particle = collisions_per_particle();
    if constexpr (F.species) {
      int ns = 1;
      for (int k = 0; k < max_species; ++k) species_w_[k] = p_.species_inv_mass(k);
      for (std::size_t i = 0; i < p_.size(); ++i) ns = std::max(ns, p_.species(i) + 1);
      s.species = p_.species_data().data();
      s.species_inv_mass = species_w_.data();
      s.n_species = ns;
    }
    obs.observe(s);
  }

  /// Advances the process to time t (mean collision times; engine_concept.hpp). With an
  /// observer, calls obs->observe at t0, t0 + every, ... <= t, t0 = time() at the call
  /// (a grid point within 1e-9 every above t is taken at t; an instant observed by the
  /// previous call is not observed again). Throws InvalidInput if t is not finite or before
  /// time(), or if obs is set and every is not finite and > 0.
  void run_until(double t, Observer* obs = nullptr, double every = 0.0) {
    if (obs && !(every > 0.0 && std::isfinite(every)))
      throw InvalidInput("DSMC: observation interval must be finite and > 0");
    if (!std::isfinite(t)) throw InvalidInput("DSMC: end time must be finite");
    if (t < time_)
      throw InvalidInput("DSMC: run_until(" + std::to_string(t) + "): the gas is already at t = " +
                         std::to_string(time_));
    if (!obs) {
      advance_to(t);
      return;
    }
    const double t0 = time_;
    for (std::uint64_t k = 0;; ++k) {
      double tk = t0 + static_cast<double>(k) * every;
      if (tk > t) {
        if (tk - t > 1e-9 * every) break;
        tk = t;
      }
      advance_to(tk);
      if (observed_at_ != time_) {
        observe(*obs);
        observed_at_ = time_;
      }
    }
    advance_to(t);
  }

  /// Current time (mean collision times).
  double time() const { return time_; }
  /// Accepted collisions so far.
  std::uint64_t collisions() const { return collisions_; }
  /// Candidate pairs tested so far (acceptance ratio = collisions / candidates).
  std::uint64_t candidates() const { return candidates_; }
  /// 2 collisions / N: equals time() on average at equilibrium.
  double collisions_per_particle() const { return 2.0 * static_cast<double>(collisions_) / n_; }
  /// The particles (velocities in units with species-0 mass 1).
  const ParticlesT& particles() const { return p_; }
  /// Bytes of per-particle storage: the velocities (the engine and its thread team store
  /// nothing per particle).
  double bytes_per_particle() const { return p_.bytes_per_particle(); }
  /// Rate constant c: pair rate c |g|^a / (N - 1) per mean collision time.
  double rate_constant() const { return c_; }
  /// Debug self-check (slow): before each step of the candidate loop, re-tests every
  /// pending candidate of the current batch with the state of that moment and counts the
  /// decisions that differ from the batch's (see process()); a correct engine counts 0.
  void set_self_check(bool on) { self_check_ = on; }
  std::uint64_t self_check_failures() const { return check_failures_; }
  /// Runs one system on `threads` threads (1 .. 256). The result is bit for bit the same for
  /// every thread count; `block` (candidates per parallel block, 0: chosen from N) only
  /// changes the speed. Below about 20000 particles several threads would only wait for
  /// each other, so the one-thread loop runs unless a block size is given.
  void set_threads(int threads, std::uint32_t block = 0) {
    if (threads < 1 || threads > 256)
      throw InvalidInput("DSMC: threads must be in 1..256, got " + std::to_string(threads));
    const std::uint32_t auto_block = std::clamp<std::uint32_t>(n_ / 64, 2048, 65536);
    const bool parallel = block > 0 || (threads > 1 && n_ >= 20000);
    block_ = parallel ? (block > 0 ? block : auto_block) : 0;
    if (!parallel) {
      team_.reset();
      lanes_.clear();
      return;
    }
    if (!team_ || team_->size() != threads) team_ = std::make_unique<ThreadTeam>(threads);
    lanes_.assign(static_cast<std::size_t>(threads), Lane{});
  }
  /// Sets a function called between epochs (exact scheme: every ~2N candidates and at each
  /// bound raise) and between NTC steps, with the engine consistent at time(); it may throw
  /// to stop a run early (run_until then leaves the gas at time() < t, ready to go on).
  /// Calling it changes nothing in the trajectory. Empty: no calls. Not state.
  void set_poll(std::function<void()> poll) { poll_ = std::move(poll); }
  /// Threads that process one candidate block together (1: the one-thread loop).
  int threads() const { return team_ ? team_->size() : 1; }
  /// Current majorant bound G >= |g| (velocity units).
  double bound() const { return bound_.bound(); }
  const Config& config() const { return cfg_; }
  const Model& model() const { return model_; }

 private:
  // Candidates come in batches of B (see the file comment): the next batch is drawn and
  // its velocities prefetched while the current one is processed (prefetch distance B..2B).
  static constexpr int B = 16;
  struct Batch {
    std::array<std::uint32_t, B> i{}, j{};
    std::array<double, B> u{};  // acceptance uniforms (models with a majorant)
    std::uint32_t skip = 0;     // bit c: candidate c is not processed here (deferred or past the end)
  };

  /// One thread's pass over a chunk of candidates and what it leaves for the block's end.
  struct Lane {
    std::uint32_t offset = 0;              // block position of the chunk's first candidate
    std::vector<std::uint32_t> deferred;   // block positions, ascending
    std::vector<std::uint32_t> saved_at;   // block positions of applied candidates, ascending
    std::vector<std::uint32_t> saved_ij;   // their pairs
    std::vector<double> saved;             // their old velocities (2 D each)
    detail::ParticleFilter earlier, held;     // particles of earlier chunks; of deferred ones
    std::uint64_t collisions = 0;
    bool raised = false;                   // exact scheme: the lane stopped at a raise
    std::uint64_t raise_at = 0;            // block position of the raising candidate
    double raise_s2 = 0.0;
    char pad[64];                          // two lanes' counters never share a cache line
  };
  static ParticlesT initial_particles(const Config& cfg) {
    validate(cfg);
    ParticlesT p(cfg.n);
    Rng r = Rng(cfg.seed).split(1);
    initialize_velocities(p, cfg.init, r, cfg.initial);
    return p;
  }
  static Model make_model(const Config& cfg) {
    if constexpr (std::is_same_v<Model, VariableHardSpheres>)
      return Model(cfg.vhs_exponent);
    else
      return Model{};
  }

  /// Unbiased integer in [0, range) from 32 random bits x (Lemire's multiply-shift with
  /// rejection); on rejection (probability below range / 2^32) takes fresh words of
  /// candidate K from word 2^20 on, far from those its scattering uses.
  std::uint32_t bounded32(std::uint64_t K, std::uint32_t x, std::uint32_t range) const {
    const std::uint64_t m = std::uint64_t(x) * range;
    if (static_cast<std::uint32_t>(m) < range) [[unlikely]]
      return bounded32_slow(K, m, range);
    return static_cast<std::uint32_t>(m >> 32);
  }
  [[gnu::noinline]] std::uint32_t bounded32_slow(std::uint64_t K, std::uint64_t m,
                                                 std::uint32_t range) const {
    const std::uint32_t t = (0u - range) % range;
    EventStream more(draws_, K, std::uint64_t{1} << 20);
    while (static_cast<std::uint32_t>(m) < t)
      m = std::uint64_t(static_cast<std::uint32_t>(more() >> 32)) * range;
    return static_cast<std::uint32_t>(m >> 32);
  }
  /// Candidate K: a uniformly chosen ordered pair of distinct particles (word 0) and its
  /// acceptance uniform (word 1).
  void draw(std::uint64_t K, std::uint32_t& i, std::uint32_t& j, double& u) const {
    draw_pair(K, i, j);
    u = hypergas::detail::unit_interval(draws_.word(K, 1));
  }
  void draw_pair(std::uint64_t K, std::uint32_t& i, std::uint32_t& j) const {
    const std::uint64_t r = draws_.word(K, 0);
    i = bounded32(K, static_cast<std::uint32_t>(r >> 32), n_);
    j = bounded32(K, static_cast<std::uint32_t>(r), n_ - 1);
    j += (j >= i);
  }
  /// Whether pair (i, j) with acceptance uniform u is accepted now with bound G.
  [[gnu::always_inline]] bool accepts(std::uint32_t i, std::uint32_t j, double u, double G) const {
    if constexpr (Model::needs_majorant) {
      const double* v = p_.velocity_data().data();
      double g2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double x = v[std::size_t(i) * stride + d] - v[std::size_t(j) * stride + d];
        g2 += x * x;
      }
      return model_.accept(g2, u, G);
    } else {
      (void)i, (void)j, (void)u, (void)G;
      return true;
    }
  }
  /// Whether candidate c of batch b is accepted with the velocities of now and bound G.
  [[gnu::always_inline]] bool test(const Batch& b, int c, double G) const {
    return accepts(b.i[c], b.j[c], b.u[c], G);
  }
  /// Collides pair (i, j) as candidate K (its scattering words from word 2 of K on);
  /// returns the larger of the two new squared speeds.
  [[gnu::always_inline]] double collide(std::uint32_t i, std::uint32_t j, std::uint64_t K) {
    using Map = Eigen::Map<Vec<D>>;
    double* v = p_.velocity_data().data();
    Map vi(v + std::size_t(i) * stride), vj(v + std::size_t(j) * stride);
    EventStream rng(draws_, K, 2);
    const Vec<D> g = vi - vj;
    const double gn = std::sqrt(g.squaredNorm());
    const Vec<D> delta = Model::template deflect<D>(g, gn, rng) - g;
    apply_deflection<D>(p_, i, j, vi, vj, delta);
    if constexpr (Model::needs_majorant)
      return std::max(vi.squaredNorm(), vj.squaredNorm());
    else
      return 0.0;
  }
  /// Bit c set: candidate c of batch b involves particle i or j (SSE2 compares four
  /// candidates at a time, which is every x86-64; a plain loop elsewhere).
  static std::uint32_t sharing(const Batch& b, std::uint32_t i, std::uint32_t j) {
#if defined(__SSE2__)
    const __m128i si = _mm_set1_epi32(static_cast<int>(i));
    const __m128i sj = _mm_set1_epi32(static_cast<int>(j));
    std::uint32_t m = 0;
    for (int q = 0; q < B; q += 4) {
      const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b.i.data() + q));
      const __m128i e = _mm_loadu_si128(reinterpret_cast<const __m128i*>(b.j.data() + q));
      const __m128i in_a = _mm_or_si128(_mm_cmpeq_epi32(a, si), _mm_cmpeq_epi32(a, sj));
      const __m128i in_e = _mm_or_si128(_mm_cmpeq_epi32(e, si), _mm_cmpeq_epi32(e, sj));
      const __m128i hit = _mm_or_si128(in_a, in_e);
      m |= static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(hit))) << q;
    }
    return m;
#else
    std::uint32_t m = 0;
    for (int c = 0; c < B; ++c)
      m |= std::uint32_t((b.i[c] == i) | (b.i[c] == j) | (b.j[c] == i) | (b.j[c] == j)) << c;
    return m;
#endif
  }
  /// Resets the majorant from an exact scan (when `force` or after enough candidates).
  void retune(bool force) {
    if constexpr (!Model::needs_majorant) {
      lambda_ = 0.5 * n_ * c_;
      return;
    }
    if (force || since_scan_ >= 8ull * n_) {
      bound_.rescan(p_);
      since_scan_ = 0;
    }
    set_lambda();
  }
  void set_lambda() {
    const double ga =
        model_.exponent() == 1.0 ? bound_.bound() : std::pow(bound_.bound(), model_.exponent());
    lambda_ = 0.5 * n_ * c_ * ga;
  }

  /// Processes up to m candidates. Exact: stops after an accepted collision that leaves a
  /// speed above the bound and returns the number processed (raise_to_ holds the new
  /// maximum squared speed). NTC: never stops; records the largest such speed.
  template <bool Exact>
  std::uint64_t process(std::uint64_t m) {
    const std::uint64_t k = team_ && m >= 4u * block_ ? process_parallel<Exact>(m)
                                                     : process_serial<Exact>(m);
    candidates_ += k;
    return k;
  }
  template <bool Exact>
  std::uint64_t process_serial(std::uint64_t m) {
    Lane lane;
    const std::uint64_t k = run_lane<Exact, false, false>(lane, candidates_, m, bound_.bound());
    collisions_ += lane.collisions;
    raise_to_ = std::max(raise_to_, lane.raise_s2);
    return k;
  }

  /// Runs candidates first .. first + count - 1 (lane positions 0 .. count - 1) through
  /// the batch pipeline, in order. Every candidate of the current batch is tested at once
  /// (no velocity is written in between, so the loads overlap and no branch depends on
  /// them); then the accepted ones are taken in order. A collision changes two velocities
  /// only, so after it the later candidates of the batch that share a particle with it are
  /// tested again. Each candidate is thus decided with the state at its turn, exactly as
  /// one at a time.
  ///
  /// Defer: the lane is a later chunk of a parallel block; a candidate on a particle of an
  /// earlier chunk (lane.earlier) or of a candidate deferred before it (lane.held) is
  /// skipped and listed in lane.deferred (dsmc/level_schedule.hpp). Save: the old
  /// velocities of every applied candidate are kept so that the block can undo them.
  /// Returns `count`, or (exact scheme) the position after the candidate that raised the
  /// bound; the lane's collisions and raise are in lane.
  template <bool Exact, bool Defer, bool Save>
  std::uint64_t run_lane(Lane& lane, std::uint64_t first, std::uint64_t count, double G) {
    const double* const v = p_.velocity_data().data();
    std::array<Batch, 2> batch;
    // (the prefetches stay outside every branch: GCC 12 drops a prefetch behind one)
    const auto generate = [&](Batch& b, std::uint64_t at) {
      b.skip = 0;
      const bool whole = at + B <= count;
      for (int c = 0; c < B; ++c) {
        const std::uint64_t q = at + std::uint64_t(c);
        if (whole || q < count) {
          draw(first + q, b.i[c], b.j[c], b.u[c]);
        } else {
          b.skip |= 1u << c;
          b.i[c] = b.j[c] = 0;
        }
        if constexpr (Defer) {
          if (((b.skip >> c) & 1u) == 0 &&
              (lane.earlier.contains(b.i[c]) | lane.earlier.contains(b.j[c]) |
               lane.held.contains(b.i[c]) | lane.held.contains(b.j[c]))) {
            b.skip |= 1u << c;
            lane.deferred.push_back(lane.offset + static_cast<std::uint32_t>(q));
            lane.held.insert(b.i[c]);
            lane.held.insert(b.j[c]);
          }
        }
        __builtin_prefetch(v + std::size_t(b.i[c]) * stride, 1);
        __builtin_prefetch(v + std::size_t(b.j[c]) * stride, 1);
      }
    };
    const auto test_all = [&](const Batch& b) {
      std::uint32_t mask = 0;
      for (int c = 0; c < B; ++c) mask |= std::uint32_t(test(b, c, G)) << c;
      return mask & ~b.skip;
    };
    generate(batch[0], 0);
    generate(batch[1], B);
    int cur = 0;
    for (std::uint64_t at = 0; at < count; at += B) {
      const Batch& b = batch[std::size_t(cur)];
      std::uint32_t mask = test_all(b);
      int pos = 0;  // next candidate of the batch
      for (;;) {
        if (self_check_) [[unlikely]]
          verify(b, pos, G, mask);
        const std::uint32_t rest = mask >> pos << pos;
        if (rest == 0) break;
        const int c = std::countr_zero(rest);
        pos = c + 1;
        const std::uint32_t i = b.i[c], j = b.j[c];
        if constexpr (Save) {
          lane.saved_at.push_back(lane.offset + static_cast<std::uint32_t>(at + std::uint64_t(c)));
          lane.saved_ij.push_back(i);
          lane.saved_ij.push_back(j);
          for (int d = 0; d < D; ++d) lane.saved.push_back(v[std::size_t(i) * stride + d]);
          for (int d = 0; d < D; ++d) lane.saved.push_back(v[std::size_t(j) * stride + d]);
        }
        const double s2 = collide(i, j, first + at + std::uint64_t(c));
        ++lane.collisions;
        if constexpr (Model::needs_majorant) {
          // later candidates of the batch that share particle i or j: decided again
          for (std::uint32_t hit = (sharing(b, i, j) >> pos << pos) & ~b.skip; hit != 0;
               hit &= hit - 1) {
            const int c2 = std::countr_zero(hit);
            const std::uint32_t bit = 1u << c2;
            mask = test(b, c2, G) ? (mask | bit) : (mask & ~bit);
          }
          if (bound_.exceeded_by(s2)) {
            lane.raise_s2 = std::max(lane.raise_s2, s2);
            if constexpr (Exact) {
              lane.raised = true;
              return at + std::uint64_t(c) + 1;
            }
          }
        }
      }
      generate(batch[std::size_t(cur)], at + 2 * B);
      cur = 1 - cur;
    }
    return count;
  }
  /// Self-check: every pending mask bit of batch b must equal a fresh test with the state
  /// of now; counts and corrects the differences.
  void verify(const Batch& b, int from, double G, std::uint32_t& mask) {
    for (int c = from; c < B; ++c) {
      if ((b.skip >> c) & 1u) continue;
      const bool fresh = test(b, c, G);
      if (fresh != bool((mask >> c) & 1u)) {
        ++check_failures_;
        mask ^= 1u << c;
      }
    }
  }

  /// process() on the thread team, in blocks of block_ candidates cut into one chunk per
  /// thread (dsmc/level_schedule.hpp). Same result as process_serial(), bit for bit.
  ///
  /// Per block b, two phases separated by barriers:
  ///  1. each thread runs its chunk through the batch pipeline (run_lane), deferring the
  ///     candidates that may depend on an earlier chunk; threads after the first keep the
  ///     old velocities of what they apply;
  ///  2. thread 0 takes the deferred candidates in block order up to the first raise of
  ///     the bound, undoes what later chunks applied after that raise and ends the epoch
  ///     there; meanwhile every thread draws its chunk of block b + 1 and fills its set.
  template <bool Exact>
  std::uint64_t process_parallel(std::uint64_t m) {
    ThreadTeam& team = *team_;
    const int T = team.size();
    const double G = bound_.bound();
    const std::uint64_t K0 = candidates_;
    std::uint64_t done = 0;
    bool stop = false;
    std::vector<double> before;  // self-check: the velocities at the start of the block
    if (self_check_) save_velocities(before);
    const auto block_after = [&](std::uint64_t start) {
      return static_cast<std::uint32_t>(std::min<std::uint64_t>(block_, m - start));
    };
    const auto share = [T](std::uint32_t nb, int t) {
      return std::pair<std::uint32_t, std::uint32_t>(
          static_cast<std::uint32_t>(std::uint64_t(nb) * t / T),
          static_cast<std::uint32_t>(std::uint64_t(nb) * (t + 1) / T));
    };
    // thread t's set: the particles of the chunks before its own (drawn again here, so that
    // the set is written and read by one core only)
    const auto prepare = [&](std::uint64_t start, std::uint32_t nb, int t) {
      Lane& lane = lanes_[std::size_t(t)];
      const std::uint32_t lo = share(nb, t).first;
      lane.earlier.reserve(2 * std::size_t(lo));
      for (std::uint32_t c = 0; c < lo; ++c) {
        std::uint32_t i, j;
        draw_pair(K0 + start + c, i, j);
        lane.earlier.insert(i);
        lane.earlier.insert(j);
      }
    };

    team.run([&](int t) {
      Lane& lane = lanes_[std::size_t(t)];
      std::uint64_t start = 0;
      std::uint32_t nb = block_after(0);
      prepare(0, nb, t);
      team.sync();
      for (;;) {
        const auto [lo, hi] = share(nb, t);
        // 1. the chunk, deferring what may depend on earlier chunks
        lane.offset = lo;
        lane.deferred.clear();
        lane.saved_at.clear();
        lane.saved_ij.clear();
        lane.saved.clear();
        lane.held.reserve(std::size_t(hi - lo) / 8);
        lane.collisions = 0;
        lane.raise_s2 = 0.0;
        lane.raised = false;
        const std::uint64_t first = K0 + start + lo;
        const std::uint64_t ran =
            t == 0 ? run_lane<Exact, false, false>(lane, first, hi - lo, G)
                   : run_lane<Exact, true, Exact && Model::needs_majorant>(lane, first, hi - lo, G);
        lane.raise_at = lane.raised ? lo + ran - 1 : nb;
        team.sync();
        // 2. the block's end on thread 0; the next block's sets on all
        const std::uint64_t next = start + nb;
        const std::uint32_t nn = next < m ? block_after(next) : 0;
        if (t == 0) {
          bool raised = false;
          const std::uint32_t processed = finish_block<Exact>(K0 + start, nb, G, raised);
          if (self_check_) [[unlikely]] {
            check_block<Exact>(before, K0 + start, processed, raised, G);
            save_velocities(before);
          }
          done += processed;
          stop = raised;
        }
        if (nn > 0) prepare(next, nn, t);
        team.sync();
        if (stop || nn == 0) return;  // the same decision on every thread
        start = next;
        nb = nn;
      }
    });
    return done;
  }

  /// Phase 2 of a block on thread 0: the deferred candidates in block order up to the
  /// first raise (exact scheme), the undoing of what later chunks applied after it, the
  /// counters. Returns the number of candidates the block processed (up to and including
  /// the raising one); `raised` tells whether the epoch ends there.
  template <bool Exact>
  std::uint32_t finish_block(std::uint64_t base, std::uint32_t nb, double G, bool& raised) {
    raised = false;
    std::uint32_t stop_at = nb;  // block position of the first raise
    double stop_s2 = 0.0, ntc_raise = 0.0;
    std::uint64_t coll = 0;
    for (const Lane& w : lanes_) {
      if (w.raise_at < stop_at) stop_at = static_cast<std::uint32_t>(w.raise_at), stop_s2 = w.raise_s2;
      coll += w.collisions;
      ntc_raise = std::max(ntc_raise, w.raise_s2);
    }
    bool end = false;
    for (const Lane& w : lanes_) {
      for (const std::uint32_t c : w.deferred) {
        if (c >= stop_at) {
          end = true;
          break;
        }
        std::uint32_t i, j;
        double u;
        draw(base + c, i, j, u);
        if (!accepts(i, j, u, G)) continue;
        const double s2 = collide(i, j, base + c);
        ++coll;
        if constexpr (Model::needs_majorant) {
          if (bound_.exceeded_by(s2)) {
            if constexpr (Exact) {
              stop_at = c, stop_s2 = s2;
              end = true;
              break;
            } else {
              ntc_raise = std::max(ntc_raise, s2);
            }
          }
        }
      }
      if (end) break;
    }
    if constexpr (Exact && Model::needs_majorant) {
      if (stop_at < nb) {
        // undo, newest first, what chunks after the raise applied (their particles are
        // touched by no other chunk and by no applied deferred candidate)
        double* v = p_.velocity_data().data();
        for (const Lane& w : lanes_)
          for (std::size_t a = w.saved_at.size(); a-- > 0;) {
            if (w.saved_at[a] <= stop_at) break;
            const std::uint32_t i = w.saved_ij[2 * a], j = w.saved_ij[2 * a + 1];
            const double* o = w.saved.data() + a * 2 * D;
            for (int d = 0; d < D; ++d) {
              v[std::size_t(i) * stride + d] = o[d];
              v[std::size_t(j) * stride + d] = o[D + d];
            }
            --coll;
          }
        raise_to_ = std::max(raise_to_, stop_s2);
        raised = true;
      }
    } else if constexpr (Model::needs_majorant) {
      raise_to_ = std::max(raise_to_, ntc_raise);
    }
    collisions_ += coll;
    return raised ? stop_at + 1 : nb;
  }
  /// Self-check: the velocity components into / out of a flat copy.
  void save_velocities(std::vector<double>& to) const {
    to.resize(std::size_t(n_) * D);
    const double* v = p_.velocity_data().data();
    for (std::size_t q = 0; q < n_; ++q)
      for (int d = 0; d < D; ++d) to[q * D + d] = v[q * stride + d];
  }
  void load_velocities(const std::vector<double>& from) {
    double* v = p_.velocity_data().data();
    for (std::size_t q = 0; q < n_; ++q)
      for (int d = 0; d < D; ++d) v[q * stride + d] = from[q * D + d];
  }

  /// Self-check of one parallel block: replays candidates base .. base + count - 1 one at
  /// a time on `before` (the velocities at the block's start) and counts the particles
  /// whose velocities differ from the engine's, plus one if the replay raises the bound
  /// elsewhere than the engine (`raised`: the engine ended the epoch at the last one).
  template <bool Exact>
  void check_block(const std::vector<double>& before, std::uint64_t base, std::uint32_t count,
                   bool raised, double G) {
    std::vector<double> after;
    save_velocities(after);
    load_velocities(before);
    bool replay_raised = false;
    for (std::uint32_t c = 0; c < count && !replay_raised; ++c) {
      std::uint32_t i, j;
      double u;
      draw(base + c, i, j, u);
      if (!accepts(i, j, u, G)) continue;
      const double s2 = collide(i, j, base + c);
      replay_raised = Exact && Model::needs_majorant && bound_.exceeded_by(s2);
      if (replay_raised != (raised && c + 1 == count)) ++check_failures_;
    }
    if (raised && !replay_raised) ++check_failures_;
    std::vector<double> replay;
    save_velocities(replay);
    for (std::size_t q = 0; q < n_; ++q)
      for (int d = 0; d < D; ++d)
        if (std::bit_cast<std::uint64_t>(replay[q * D + d]) !=
            std::bit_cast<std::uint64_t>(after[q * D + d])) {
          ++check_failures_;
          break;
        }
    load_velocities(after);
  }

  /// Advances to t_end with the configured scheme.
  void advance_to(double t_end) {
    if (cfg_.scheme == Scheme::exact)
      advance_exact(t_end);
    else
      advance_ntc(t_end);
  }

  void advance_exact(double t_end) {
    while (time_ < t_end) {
      retune(false);
      double h = t_end - time_;
      const double hmax = 2.0 * n_ / lambda_;  // epochs of ~2N candidates
      const bool capped = h > hmax;
      if (capped) h = hmax;
      std::poisson_distribution<std::uint64_t> pois(lambda_ * h);
      const std::uint64_t m = pois(rng_);
      const std::uint64_t k = process<true>(m);
      since_scan_ += k;
      // a raise stops the epoch at its candidate, the m-th included (raise_to_ is set)
      if (raise_to_ == 0.0) {
        time_ = capped ? time_ + h : t_end;
      } else {
        // k-th of m uniform order statistics on [time_, time_ + h].
        std::gamma_distribution<double> ga(static_cast<double>(k)),
            gb(static_cast<double>(m - k + 1));
        const double x = ga(rng_), y = gb(rng_);
        time_ = std::min(time_ + h * (x / (x + y)), t_end);
        bound_.set(raise_to_);
        raise_to_ = 0.0;
        set_lambda();
      }
      if (poll_) poll_();
    }
  }

  void advance_ntc(double t_end) {
    while (time_ < t_end) {
      retune(false);
      double h = cfg_.dt;
      const bool last = h >= t_end - time_;
      if (last) h = t_end - time_;
      const auto m = static_cast<std::uint64_t>(std::floor(lambda_ * h + rng_.uniform()));
      process<false>(m);
      since_scan_ += m;
      if (raise_to_ > 0.0) {  // the bound catches up only at the end of the step
        bound_.set(raise_to_);
        raise_to_ = 0.0;
        set_lambda();
      }
      time_ = last ? t_end : time_ + h;
      if (poll_) poll_();
    }
  }

  Config cfg_;
  ParticlesT p_;
  Model model_;
  Rng rng_;
  std::uint32_t n_ = 0;
  double c_ = 0.0;       // rate constant
  double lambda_ = 0.0;  // candidate rate N c G^a / 2 (per mean collision time)
  SpeedBound bound_;
  double raise_to_ = 0.0;  // pending new maximum squared speed
  double time_ = 0.0;
  double observed_at_ = -1.0;
  std::uint64_t collisions_ = 0, candidates_ = 0, since_scan_ = 0;
  EventDraws draws_;               // candidate K's draws: a function of (seed, K)
  bool self_check_ = false;
  std::uint64_t check_failures_ = 0;
  std::array<double, max_species> species_w_{};

  // The thread team and one lane per thread (not state: rebuilt by set_threads; no team:
  // the one-thread loop).
  std::uint32_t block_ = 0;
  std::unique_ptr<ThreadTeam> team_;
  std::vector<Lane> lanes_;
  std::function<void()> poll_;  // set_poll (not state)
};

}  // namespace hypergas::dsmc

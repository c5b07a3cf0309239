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
// Speed: candidates come in batches of 16. A batch (pairs and acceptance uniforms) is
// drawn one batch ahead and its velocities prefetched (random access to N = 1e6 velocities
// is cache-miss bound); then all 16 are tested at once - no velocity changes in between,
// so the loads overlap and no branch waits on them - and the accepted ones are taken in
// order (count-trailing-zeros on the acceptance mask). Exactness is kept by re-testing:
// after a collision, the later candidates of the batch that share one of its two
// particles; after a change of the bound G, the whole rest of the batch. A self-check mode
// (set_self_check) re-tests every pending candidate before each step and counts
// disagreements; tests/unit/test_dsmc_engine.cpp requires zero (and fails without either
// re-test). The candidates and the scattering directions use xoshiro256++ (FastRng in
// rng.hpp) kept in registers, not the 128-bit-multiply PCG64 of the rest of the code.
// Hard spheres accept by comparing squares, so a rejected candidate costs no square root;
// equal-mass scenes compile the mass weights to 1/2; the velocity array is advised onto
// transparent huge pages (dsmc/huge_pages.hpp). Observers are called every `every` time
// units, never per collision.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <random>
#include <type_traits>
#include <utility>

#include "hypergas/checkpoint.hpp"
#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/huge_pages.hpp"
#include "hypergas/dsmc/majorant.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/time_unit.hpp"
#include "hypergas/dsmc/update.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"

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
        pairs_(fast_stream(cfg.seed, 4)), coll_(fast_stream(cfg.seed, 5)) {
    cfg_.n = p_.size();
    validate(cfg_);  // also checks 2 <= n < 2^32
    n_ = static_cast<std::uint32_t>(p_.size());
    c_ = dsmc::rate_constant(p_, model_.exponent());
    detail::advise_huge_pages(p_.velocity_data().data(),
                              p_.velocity_data().size() * sizeof(double));
    retune(true);
    generate(batch_[1 - cur_]);  // the batch after the (empty) current one
  }

  /// Restores an engine saved by io() (hypergas/checkpoint.hpp); it continues bit for bit as
  /// the saved one would have. Throws InvalidInput if the file holds another engine,
  /// dimension, model or feature set.
  Engine(const Config& cfg, checkpoint::Reader& in)
      : cfg_(cfg), model_(make_model(cfg)), rng_(Rng(cfg.seed).split(2)),
        pairs_(fast_stream(cfg.seed, 4)), coll_(fast_stream(cfg.seed, 5)) {
    io(in);
  }

  /// Saves or restores the complete state: velocities, the three random streams, the
  /// majorant, the epoch's position in the candidate batches and the counters.
  template <class Archive>
  void io(Archive& a) {
    static_assert(std::is_trivially_copyable_v<Rng> && std::is_trivially_copyable_v<FastRng> &&
                  std::is_trivially_copyable_v<Model> && std::is_trivially_copyable_v<Config>);
    a.tag(identity());
    a(cfg_, p_, model_, rng_, n_, c_, lambda_, bound_, raise_to_, time_, observed_at_);
    a(collisions_, candidates_, since_scan_, pairs_, coll_, batch_, cur_, pos_, mask_);
    a(tested_g_, self_check_, check_failures_, species_w_);
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
  /// Bytes of per-particle storage (the engine itself stores nothing per particle).
  double bytes_per_particle() const { return p_.bytes_per_particle(); }
  /// Rate constant c: pair rate c |g|^a / (N - 1) per mean collision time.
  double rate_constant() const { return c_; }
  /// Debug self-check (slow): before each step of the candidate loop, re-tests every
  /// pending candidate of the current batch with the state of that moment and counts the
  /// decisions that differ from the batch's (see process()); a correct engine counts 0.
  void set_self_check(bool on) { self_check_ = on; }
  std::uint64_t self_check_failures() const { return check_failures_; }
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
  static FastRng fast_stream(std::uint64_t seed, std::uint64_t k) {
    Rng r = Rng(seed).split(k);
    return FastRng(r);
  }

  /// Unbiased integer in [0, range) from 32 random bits x (Lemire's multiply-shift with
  /// rejection); redraws fresh bits from g on rejection.
  static std::uint32_t bounded32(FastRng& g, std::uint32_t x, std::uint32_t range) {
    std::uint64_t m = std::uint64_t(x) * range;
    auto l = static_cast<std::uint32_t>(m);
    if (l < range) {
      const std::uint32_t t = (0u - range) % range;
      while (l < t) {
        x = static_cast<std::uint32_t>(g() >> 32);
        m = std::uint64_t(x) * range;
        l = static_cast<std::uint32_t>(m);
      }
    }
    return static_cast<std::uint32_t>(m >> 32);
  }
  /// Draws a batch of B candidates: uniformly chosen ordered pairs of distinct particles
  /// and their acceptance uniforms; prefetches the pairs' velocities.
  void generate(Batch& b) {
    FastRng g = pairs_;  // a local copy stays in registers
    const double* v = p_.velocity_data().data();
    const std::uint32_t n = n_;
    for (int c = 0; c < B; ++c) {
      const std::uint64_t r = g();
      const std::uint32_t i = bounded32(g, static_cast<std::uint32_t>(r >> 32), n);
      std::uint32_t j = bounded32(g, static_cast<std::uint32_t>(r), n - 1);
      j += (j >= i);
      b.i[c] = i;
      b.j[c] = j;
      if constexpr (Model::needs_majorant) b.u[c] = g.uniform();
      __builtin_prefetch(v + std::size_t(i) * stride, 1);
      __builtin_prefetch(v + std::size_t(j) * stride, 1);
    }
    pairs_ = g;
  }
  /// Whether candidate c of batch b is accepted with the velocities of now and bound G.
  bool test(const Batch& b, int c, double G) const {
    if constexpr (Model::needs_majorant) {
      const double* v = p_.velocity_data().data();
      double g2 = 0.0;
      for (int d = 0; d < D; ++d) {
        const double x = v[std::size_t(b.i[c]) * stride + d] - v[std::size_t(b.j[c]) * stride + d];
        g2 += x * x;
      }
      return model_.accept(g2, b.u[c], G);
    } else {
      (void)b, (void)c, (void)G;
      return true;
    }
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
  /// Self-check: every pending mask bit must equal a fresh test with the state of now.
  void verify(double G) {
    for (int c = pos_; c < B; ++c) {
      const bool fresh = test(batch_[cur_], c, G);
      if (fresh != bool((mask_ >> c) & 1u)) {
        ++check_failures_;
        mask_ ^= 1u << c;
      }
    }
  }
  /// Tests candidates from..B-1 of the current batch with bound G (sets their mask bits).
  void test_from(int from, double G) {
    const Batch& b = batch_[cur_];
    std::uint32_t mask = mask_ & ((1u << from) - 1u);
    for (int c = from; c < B; ++c) mask |= std::uint32_t(test(b, c, G)) << c;
    mask_ = mask;
    tested_g_ = G;
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
  ///
  /// Batches: every candidate of the current batch is tested at once (no velocity is
  /// written in between, so the loads overlap and no branch depends on them); then the
  /// accepted ones are taken in order. A collision changes two velocities only, so after
  /// it the later candidates that share a particle with it are tested again; a change of
  /// the bound G (between calls) re-tests the rest of the batch. Each candidate is thus
  /// decided with the state at its turn, exactly as one at a time.
  template <bool Exact>
  std::uint64_t process(std::uint64_t m) {
    double* v = p_.velocity_data().data();
    const double G = bound_.bound();
    using Map = Eigen::Map<Vec<D>>;
    if (pos_ < B && G != tested_g_) test_from(pos_, G);
    FastRng rng = coll_;  // scattering directions; a local copy stays in registers
    std::uint64_t k = 0;
    while (k < m) {
      if (pos_ == B) {
        cur_ = 1 - cur_;
        generate(batch_[1 - cur_]);
        test_from(0, G);
        pos_ = 0;
      }
      if (self_check_) [[unlikely]] verify(G);
      const std::uint64_t left = m - k;
      const std::uint32_t rest = mask_ >> pos_;
      if (rest == 0 || std::uint64_t(std::countr_zero(rest)) >= left) {
        // no accepted candidate among the next min(left, B - pos_)
        const std::uint64_t take = std::min<std::uint64_t>(left, std::uint64_t(B - pos_));
        pos_ += static_cast<int>(take);
        k += take;
        continue;
      }
      const int c = pos_ + std::countr_zero(rest);
      k += static_cast<std::uint64_t>(c - pos_) + 1;
      pos_ = c + 1;
      const Batch& b = batch_[cur_];
      const std::uint32_t i = b.i[c], j = b.j[c];
      Map vi(v + std::size_t(i) * stride), vj(v + std::size_t(j) * stride);
      const Vec<D> g = vi - vj;
      const double gn = std::sqrt(g.squaredNorm());
      const Vec<D> delta = Model::template deflect<D>(g, gn, rng) - g;
      apply_deflection<D>(p_, i, j, vi, vj, delta);
      ++collisions_;
      if constexpr (Model::needs_majorant) {
        // later candidates of the batch that share particle i or j: decided again
        for (std::uint32_t hit = sharing(b, i, j) >> pos_ << pos_; hit != 0; hit &= hit - 1) {
          const int c2 = std::countr_zero(hit);
          const std::uint32_t bit = 1u << c2;
          mask_ = test(b, c2, G) ? (mask_ | bit) : (mask_ & ~bit);
        }
        const double s2 = std::max(vi.squaredNorm(), vj.squaredNorm());
        if (bound_.exceeded_by(s2)) {
          raise_to_ = std::max(raise_to_, s2);
          if constexpr (Exact) break;
        }
      }
    }
    coll_ = rng;
    candidates_ += k;
    return k;
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
  FastRng pairs_;                  // the candidates' random stream
  FastRng coll_;                   // the collisions' random stream (scattering)
  std::array<Batch, 2> batch_{};   // the current batch and the next one
  int cur_ = 0;                    // index of the current batch
  int pos_ = B;                    // next candidate of the current batch (B: none left)
  std::uint32_t mask_ = 0;         // bit c: candidate c of the current batch is accepted
  double tested_g_ = 0.0;          // the bound the mask was computed with
  bool self_check_ = false;
  std::uint64_t check_failures_ = 0;
  std::array<double, max_species> species_w_{};
};

}  // namespace hypergas::dsmc

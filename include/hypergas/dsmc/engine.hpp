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
// The pieces, one concept per header in dsmc/detail/ (docs/design.md, "DSMC engine files"):
//   candidates.hpp  candidate K's counter-based draws (pair, acceptance uniform, scattering)
//   state.hpp       the shared state and the per-candidate kernel (draw, accept, collide)
//   batch.hpp       a batch of 16 candidates tested at once; the shared-particle mask
//   lane.hpp        the candidate loop (run_lane): with one thread, this is the engine
//   parallel.hpp    one system on T threads in candidate blocks, bit for bit as one thread
//   self_check.hpp  the debug self-check: re-tests and block replays that count disagreements
//   stepping.hpp    exact Poisson epochs, NTC steps and the majorant upkeep
//   kac_lanes.hpp   the lanes scheme: exact Kac processes of cache-sized lanes, dealt anew
//                   every epoch; bit for bit the same for every thread count
// This header holds the public class: construction, checkpoints, observation, run_until.
// Observers are called every `every` time units, never per collision; what they need per
// collision they keep in a tally (Snapshot::tally), which the candidate loop, compiled
// once with and once without it, updates as it collides. The velocity array is advised
// onto transparent huge pages (dsmc/huge_pages.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "hypergas/checkpoint.hpp"
#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/detail/kac_lanes.hpp"
#include "hypergas/dsmc/detail/parallel.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/dsmc/detail/stepping.hpp"
#include "hypergas/dsmc/huge_pages.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/shear.hpp"
#include "hypergas/dsmc/time_unit.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/schedule.hpp"

namespace hypergas::dsmc {

/// The lanes scheme's shape for n particles of `stride` doubles under cfg: the number of
/// lanes L and the lane size M asked for (detail/kac_lanes.hpp); Engine::lanes() and
/// lane_size() of an engine with that configuration.
struct LaneShape {
  std::uint32_t lanes = 0, lane_size = 0;
};
inline LaneShape lane_shape(const Config& cfg, std::uint32_t n, int stride) {
  const std::uint32_t m = detail::lane_size_of(cfg, stride);
  return {detail::LaneLayout::make(n, m).lanes, m};
}

/// The DSMC engine for dimension D, collision model `Model`, particle features F (Features{}
/// or Features{.species = true}). Time in equilibrium mean collision times.
// clang-format off
template <int D, class Model, Features F = Features{}>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
class Engine {
  // clang-format on
 public:
  using Config = dsmc::Config;
  using ParticlesT = Particles<D, F>;
  static constexpr int dim = D;
  static constexpr int stride = ParticlesT::stride;

  /// Samples cfg.n particles in the initial state cfg.init (two species only with
  /// F.species). Throws InvalidInput on a bad configuration.
  explicit Engine(const Config& cfg) : Engine(cfg, initial_particles(cfg), false) {}

  /// Starts from the given particles (velocities in units where the species-0 mass is 1);
  /// cfg.n and cfg.init are ignored. Throws InvalidInput on a bad configuration, if the
  /// velocities are all zero, or if the total momentum is not zero to rounding (|P| >
  /// 1e-9 sqrt(M sum m v^2)): the time unit is defined in the centre-of-mass frame.
  Engine(const Config& cfg, ParticlesT particles) : Engine(cfg, std::move(particles), true) {}

  /// Restores an engine saved by io() (hypergas/checkpoint.hpp); it continues bit for bit as
  /// the saved one would have. Throws InvalidInput if the file holds another engine,
  /// dimension, model or feature set.
  Engine(const Config& cfg, checkpoint::Reader& in);
  Engine(Engine&&) noexcept = default;
  Engine& operator=(Engine&&) noexcept = default;

  /// Saves or restores the complete state: velocities, the epochs' random stream, the
  /// majorant and the counters (the candidates' draws are functions of their number, so the
  /// number of candidates so far is their whole state). The thread count is not state.
  template <class Archive>
  void io(Archive& a);
  /// "dsmc D=3 model=hs species=0": what a checkpoint must match.
  static std::string identity() {
    return "dsmc D=" + std::to_string(D) + " model=" + std::string(Model::name) +
           " species=" + std::to_string(int(F.species));
  }

  /// Calls obs with the current state (velocities, time, counters) and the engine's tally
  /// slot (hypergas/tally/tally.hpp), then installs what obs.request asks for: a tally so
  /// installed is kept up to date by every later collision. Changes nothing in the
  /// trajectory.
  void observe(Observer& obs);

  /// Advances the process to time t (mean collision times; engine_concept.hpp). With an
  /// observer, calls obs->observe at the instants of Schedule::make(time(), t, every)
  /// (schedule.hpp: evenly spaced, the last at t; an instant observed by the previous call
  /// is not observed again). Throws InvalidInput if t is not finite or before
  /// time(), or if obs is set and every is not finite and > 0.
  void run_until(double t, Observer* obs = nullptr, double every = 0.0);

  /// Current time (mean collision times; with restitution < 1 and no drive, of the gas at
  /// its current temperature: dsmc/granular.hpp).
  double time() const { return s_.time; }
  /// Time in mean collision times at the initial temperature (equals time() unless the gas
  /// cools freely, dsmc/granular.hpp, or is sheared without thermostat, dsmc/shear.hpp).
  double real_time() const { return detail::scaled_state(s_) ? s_.real_time : s_.time; }
  /// The shear rate a per mean collision time at kT0 (0: no shear flow; dsmc/shear.hpp).
  double shear_rate() const { return s_.cfg.shear_rate; }
  /// The particles' stored velocities are the true ones divided by exp(log_velocity_scale())
  /// (0 unless the state is scaled: a freely cooling gas, a sheared one without thermostat).
  double log_velocity_scale() const { return s_.log_scale; }
  /// The temperature of the true velocities, sum m v^2 / (D (N - 1)) (energy units).
  double temperature() const {
    return equilibrium_temperature(s_.p) * std::exp(2.0 * s_.log_scale);
  }
  /// The initial temperature kT0 that fixes the time unit (energy units).
  double initial_temperature() const { return s_.kT0; }
  /// The coefficient of normal restitution.
  double restitution() const { return s_.cfg.restitution; }
  /// White-noise kicks so far (drive = white_noise).
  std::uint64_t kicks() const { return s_.kicks; }
  /// Accepted collisions so far.
  std::uint64_t collisions() const { return s_.collisions; }
  /// Candidate pairs tested so far (acceptance ratio = collisions / candidates).
  std::uint64_t candidates() const { return s_.candidates; }
  /// 2 collisions / N: equals time() on average at equilibrium.
  double collisions_per_particle() const {
    return 2.0 * static_cast<double>(s_.collisions) / s_.n;
  }
  /// The particles (velocities in units with species-0 mass 1).
  const ParticlesT& particles() const { return s_.p; }
  /// Bytes of per-particle storage: the velocities (the engine and its thread team store
  /// nothing per particle).
  double bytes_per_particle() const { return s_.p.bytes_per_particle(); }
  /// Rate constant c: pair rate c |g|^a / (N - 1) per mean collision time.
  double rate_constant() const { return s_.c; }
  /// Debug self-check (slow): before each step of the candidate loop, re-tests every
  /// pending candidate of the current batch with the state of that moment and counts the
  /// decisions that differ from the batch's; with threads, also replays every block one
  /// candidate at a time (detail/self_check.hpp). A correct engine counts 0.
  void set_self_check(bool on) { s_.self_check = on; }
  std::uint64_t self_check_failures() const { return s_.check_failures; }
  /// Runs one system on `threads` threads (1 .. 256). The result is bit for bit the same for
  /// every thread count. The lanes scheme shares its lanes out among the threads. The exact
  /// and NTC schemes run the one-thread loop unless `block` (candidates per parallel
  /// block) is given: their block schedule measured slower than one thread
  /// (detail/parallel.hpp); a block size runs it, for its tests.
  void set_threads(int threads, std::uint32_t block = 0) {
    if (threads < 1 || threads > 256)
      throw InvalidInput("DSMC: threads must be in 1..256, got " + std::to_string(threads));
    blocks_.configure(threads, block);
    // the other schemes keep no idle team
    lanes_.configure(s_.cfg.scheme == Scheme::lanes ? threads : 1);
  }
  /// Sets a function called between epochs (exact scheme: every ~2N candidates and at each
  /// bound raise) and between NTC steps, with the engine consistent at time(); it may throw
  /// to stop a run early (run_until then leaves the gas at time() < t, ready to go on).
  /// Calling it changes nothing in the trajectory. Empty: no calls. Not state.
  void set_poll(std::function<void()> poll) { poll_ = std::move(poll); }
  /// The threads asked for by set_threads (block_size() == 0: the exact and NTC schemes
  /// run the one-thread loop).
  int threads() const { return blocks_.threads(); }
  /// The lanes scheme: the number of lanes L and the lane size M asked for (detail/kac_lanes.hpp).
  std::uint32_t lanes() const { return lane_shape(s_.cfg, s_.n, stride).lanes; }
  std::uint32_t lane_size() const { return lane_shape(s_.cfg, s_.n, stride).lane_size; }
  /// The engine's facts in a run's summary (summary.json, docs/design.md): put(key, value)
  /// for each, value a double or std::int64_t: the NTC step dt; the lanes scheme's lanes,
  /// lane size and epoch; the collisions per particle.
  template <class Put>
  void describe(Put&& put) const {
    if (s_.cfg.scheme == Scheme::ntc) put("dt", s_.cfg.dt);
    if (s_.cfg.scheme == Scheme::lanes) {
      put("lanes", std::int64_t{lanes()});
      put("lane_size", std::int64_t{lane_size()});
      put("epoch", s_.cfg.epoch);
    }
    put("collisions_per_particle", collisions_per_particle());
  }
  /// Candidates per parallel block (0: the one-thread loop runs).
  std::uint32_t block_size() const { return blocks_.block(); }
  /// Per thread of the team: ticks spent in each phase of the block schedule
  /// (detail/phase_clock.hpp) since set_threads() or reset_schedule_profile(); empty when
  /// the one-thread loop runs. Not state.
  const std::vector<PhaseTicks>& schedule_profile() const { return blocks_.profile(); }
  void reset_schedule_profile() { blocks_.reset_profile(); }
  /// Current majorant bound G >= |g| (velocity units).
  double bound() const { return s_.bound.bound(); }
  const Config& config() const { return s_.cfg; }
  const Model& model() const { return s_.model; }

 private:
  /// The common start: `given` particles must be at zero total momentum (sampled initial
  /// states are, by construction).
  Engine(const Config& cfg, ParticlesT particles, bool given);
  static ParticlesT initial_particles(const Config& cfg);
  /// The factor (1 + alpha)/2 of the collisions' impulse (State::impulse: derived, not saved).
  static double impulse_of(const Config& cfg) { return restitution_impulse(cfg.restitution); }
  static Model make_model(const Config& cfg) {
    if constexpr (std::is_same_v<Model, VariableHardSpheres>)
      return Model(cfg.vhs_exponent);
    else
      return Model{};
  }
  void advance_to(double t_end) {
    if constexpr (D >= 2)
      if (detail::sheared(s_)) return detail::advance_sheared(s_, poll_, t_end);
    if (s_.cfg.scheme == Scheme::lanes) detail::advance_lanes(s_, lanes_, poll_, t_end);
    else detail::advance_to(s_, blocks_, poll_, t_end);
  }

  detail::State<D, Model, F> s_;
  detail::ParallelBlocks blocks_;  // the thread team and its lanes (not state)
  detail::LaneTeam lanes_;         // the lanes scheme's threads (not state)
  std::function<void()> poll_;     // set_poll (not state)
};

// The members that run the gas, defined out of the class: not inline, so a file that sees
// the engine declared extern (hypergas/engines.hpp) calls the engines library's copy
// instead of compiling the candidate loop again.

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
Engine<D, Model, F>::Engine(const Config& cfg, checkpoint::Reader& in)
    : s_(cfg, make_model(cfg)) {
  io(in);
  validate(s_.cfg);  // a damaged or forged file's configuration is refused, not run
  if (s_.cfg.shear_rate != 0.0 && D < 2) throw InvalidInput("checkpoint: a shear flow in D = 1");
}

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
template <class Archive>
void Engine<D, Model, F>::io(Archive& a) {
  static_assert(std::is_trivially_copyable_v<Rng> && std::is_trivially_copyable_v<Model> &&
                std::is_trivially_copyable_v<Config>);
  a.tag(identity());
  a(s_.cfg, s_.p, s_.model, s_.rng, s_.n, s_.c, s_.lambda, s_.bound, s_.raise_to, s_.time,
    s_.observed_at);
  a(s_.collisions, s_.candidates, s_.since_scan, s_.self_check, s_.check_failures,
    s_.species_w);
  a(s_.log_scale, s_.real_time, s_.kT0, s_.kicks, s_.deals, s_.segments);
  s_.impulse = impulse_of(s_.cfg);
  if (s_.p.size() != s_.n) throw InvalidInput("checkpoint: particle count does not match");
}

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
void Engine<D, Model, F>::observe(Observer& obs) {
  Snapshot snap = make_snapshot(s_.p);
  snap.time = s_.time;
  snap.collisions = s_.collisions;
  snap.collisions_per_particle = collisions_per_particle();
  // A granular or sheared gas's temperature changes between rows, and a sheared gas's
  // collisions do not see its true velocities: their moments come from a pass.
  snap.tally = s_.impulse == 1.0 && !detail::sheared(s_) ? &s_.tally : nullptr;
  snap.log_velocity_scale = s_.log_scale;
  snap.real_time = real_time();
  if constexpr (F.species) {
    int ns = 1;
    for (int k = 0; k < max_species; ++k) s_.species_w[k] = s_.p.species_inv_mass(k);
    for (std::size_t i = 0; i < s_.p.size(); ++i) ns = std::max(ns, s_.p.species(i) + 1);
    snap.species = s_.p.species_data().data();
    snap.species_inv_mass = s_.species_w.data();
    snap.n_species = ns;
  }
  obs.observe(snap);
  tally::Requests r;
  obs.request(r);
  if (snap.tally) s_.tally.apply(r);
}

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
void Engine<D, Model, F>::run_until(double t, Observer* obs, double every) {
  if (obs && !(every > 0.0 && std::isfinite(every)))
    throw InvalidInput("DSMC: observation interval must be finite and > 0");
  if (!std::isfinite(t)) throw InvalidInput("DSMC: end time must be finite");
  if (t < s_.time)
    throw InvalidInput("DSMC: run_until(" + std::to_string(t) + "): the gas is already at t = " +
                       std::to_string(s_.time));
  if (!obs) {
    advance_to(t);
    return;
  }
  const Schedule plan = Schedule::make(s_.time, t, every);
  for (std::uint64_t k = 0; k <= plan.intervals(); ++k) {
    advance_to(plan.time(k));
    if (s_.observed_at != s_.time) {
      observe(*obs);
      s_.observed_at = s_.time;
    }
  }
  advance_to(t);
}

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
Engine<D, Model, F>::Engine(const Config& cfg, ParticlesT particles, bool given)
    : s_(cfg, make_model(cfg), std::move(particles)) {
  s_.cfg.n = s_.p.size();
  validate(s_.cfg);  // also checks 2 <= n < 2^32
  if (given) require_zero_momentum(s_.p);
  s_.n = static_cast<std::uint32_t>(s_.p.size());
  s_.c = dsmc::rate_constant(s_.p, s_.model.exponent());
  s_.kT0 = equilibrium_temperature(s_.p);
  s_.impulse = impulse_of(cfg);
  if (cfg.drive != Drive::none && !Model::supports_drive)
    throw InvalidInput("DSMC: the white-noise drive is defined for hard spheres (--model hs)");
  if (cfg.shear_rate != 0.0 && D < 2)
    throw InvalidInput("DSMC: a shear flow needs D >= 2 (the flow is along x, its gradient along "
                       "y)");
  if (cfg.drive != Drive::none && D < 2)
    throw InvalidInput("DSMC: the white-noise drive needs D >= 2 (its strength comes from the "
                       "Sonine theory of D >= 2)");
  advise_huge_pages(s_.p.velocity_data().data(),
                            s_.p.velocity_data().size() * sizeof(double));
  detail::retune(s_, true);
}

template <int D, class Model, Features F>
  requires Dimension<D> && CollisionModel<Model> && (!F.positions)
auto Engine<D, Model, F>::initial_particles(const Config& cfg) -> ParticlesT {
  validate(cfg);
  ParticlesT p(cfg.n);
  Rng r = Rng(cfg.seed).split(1);
  initialize_velocities(p, cfg.init, r, cfg.initial);
  return p;
}

}  // namespace hypergas::dsmc

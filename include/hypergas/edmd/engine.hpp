// hypergas/edmd/engine.hpp -- event-driven molecular dynamics of hard spheres in D dims:
// the engine class (start, save and run in engine_run.hpp; the kernel of one event,
// collide, cross and reorder in engine_events.hpp; the sheared gas in engine_shear.hpp;
// snapshots in snapshot.hpp).
//
//   edmd::Config cfg;  cfg.n = 32000; cfg.packing = 0.26; cfg.seed = 7;
//   edmd::Engine<3> e(cfg);              // lattice start (+ LS compression if needed)
//   e.run_until(t, &observer, every);    // observer called at t0, t0+every, ... <= t
//   e.pressure_Z(); e.collision_rate();  // over the measurement window (observables.hpp)
//
// Engine<D, F, Scan>: F must have positions; F.species gives two masses. Scan is the
// neighbour-scan policy (scan.hpp); the default AutoScan<D> is the fastest for D
// (docs/benchmarks.md). Units: sigma = m = kT = 1 by default.
//
// Each particle keeps a local clock, two predicted pair events and a cell crossing
// (events.hpp); the earliest is its entry in the calendar queue. A stale pair event (the
// partner collided since) falls back to the runner-up or a new scan. Every
// Config::reorder_interval collisions per particle the particles are renumbered in Z-order
// (trajectories unchanged). Design and correctness: docs/design.md, "The EDMD event loop".
//
// Granular gas: Config::restitution = alpha < 1 makes every collision inelastic
// (restitution.hpp), with the TC model against inelastic collapse (Config::tc_time; the
// collisions it made elastic: tc_elastic_collisions()). The start's Lubachevsky–Stillinger
// compression is elastic; set_restitution changes alpha during a run (e.g. a quench after
// an elastic equilibration). alpha = 1 runs the elastic kernel exactly as without the
// option (one predictable branch per collision); a granular collision leaves the pair
// receding by more than round-off (keep_receding), so that alpha = 0 cannot make the same
// pair collide again at the same instant without end. A cooling gas has no temperature to
// measure a pressure against: pressure_Z and the Helfand tally (contacts()) refuse
// alpha < 1 with InvalidInput (pressure_Z a sheared gas too); collision_rate,
// mean_free_time and temperature stay measured quantities (means over the window, and the
// current kinetic temperature).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hypergas/checkpoint.hpp"
#include "hypergas/collision.hpp"
#include "hypergas/edmd/calendar_queue.hpp"
#include "hypergas/edmd/compression.hpp"
#include "hypergas/edmd/config.hpp"
#include "hypergas/edmd/events.hpp"
#include "hypergas/edmd/lees_edwards.hpp"
#include "hypergas/edmd/observables.hpp"
#include "hypergas/edmd/prediction.hpp"
#include "hypergas/edmd/restitution.hpp"
#include "hypergas/edmd/scan.hpp"
#include "hypergas/edmd/snapshot.hpp"
#include "hypergas/edmd/state.hpp"
#include "hypergas/error.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/schedule.hpp"
#include "hypergas/tally/helfand.hpp"

namespace hypergas::edmd {

/// Hard-sphere EDMD engine (see the file comment). D in 1..6.
template <int D, Features F = Features{.positions = true}, class Scan = AutoScan<D>>
class Engine {
  static_assert(F.positions, "the EDMD engine needs Features{.positions = true}");

 public:
  using Config = edmd::Config;
  using Store = Particles<D, F>;
  static constexpr int dim = D;
  /// The neighbour-scan policy's name: "slab", "horizon", "filtered" or "lists" (scan.hpp).
  static constexpr std::string_view scan_name = Scan::name;

  /// Places cfg.n particles on a lattice at packing cfg.packing, draws velocities in state
  /// cfg.init, compresses (Lubachevsky–Stillinger) if the lattice is too tight, and predicts
  /// all events. Throws InvalidInput for bad parameters or a box below 2 diameters.
  explicit Engine(const Config& cfg);

  /// Starts from a given state (given_state.hpp: positions in a periodic cube, velocities
  /// as given) at time 0: checks it (finite, inside the box, no overlap) and predicts all
  /// events. cfg.n and cfg.packing must be those of the state (the box sets the packing);
  /// cfg.init, start_packing and the lattice are not used. Throws InvalidInput naming the
  /// first problem.
  Engine(const Config& cfg, const GivenState& g);

  /// Restores an engine saved by io() (hypergas/checkpoint.hpp): the same state, the same
  /// event calendar, so that it continues bit for bit as the saved one would have. Throws
  /// InvalidInput if the file holds another engine, dimension or feature set.
  Engine(const Config& cfg, checkpoint::Reader& in);

  /// Saves or restores the complete engine state (every array, the calendar's links, the
  /// counters and the measurement window); the scans' scratch is not state.
  template <class Archive>
  void io(Archive& a);
  /// "edmd D=3 scan=horizon species=0 masses=0 radii=0": what a checkpoint must match
  /// (docs/checkpoints.md; particles have neither masses nor radii of their own).
  static std::string identity() {
    return "edmd D=" + std::to_string(D) + " scan=" + std::string(Scan::name) +
           " species=" + std::to_string(int(F.species)) + " masses=0 radii=0";
  }

  // ---- running ------------------------------------------------------------------------
  /// Processes all events up to time t (sigma sqrt(m/kT)); time() == t afterwards. If obs is
  /// non-null it is called at the instants of Schedule::make(time(), t, every) (schedule.hpp:
  /// evenly spaced from the time at the call, the last at t) with velocities and unwrapped
  /// positions. Throws InvalidInput if t is not finite or t < time(), or if obs is non-null
  /// and `every` is not finite and > 0.
  void run_until(double t, Observer* obs = nullptr, double every = 0.0);
  /// Calls obs with the state at time() (velocities and unwrapped positions, original
  /// numbering); changes nothing.
  void observe(Observer& obs) const;
  /// Processes exactly one event (a collision, a cell crossing or a re-prediction).
  void step();

  /// The Helfand tally's slot (tally/helfand.hpp): a recorder installs a tally through a
  /// snapshot (Snapshot::contacts), and every later collision updates it. Not state: a
  /// checkpoint holds no tally. An equilibrium transport measurement: with restitution < 1
  /// the next run_until or step throws InvalidInput while a tally is installed.
  tally::ContactSlot& contacts() const { return contacts_; }

  // ---- granular gas (restitution.hpp) --------------------------------------------------
  /// Coefficient of normal restitution in effect (1: elastic).
  double restitution() const { return alpha_; }
  /// Sets the restitution for the collisions from now on; returns the previous value.
  /// Throws InvalidInput unless alpha is finite and in [0, 1]. Going from 1 to below 1
  /// starts the TC clocks afresh: no particle counts as having collided before.
  double set_restitution(double alpha) {
    check_restitution(alpha);
    if (alpha < 1.0 && le_.interval > 0.0)
      throw InvalidInput("the isokinetic thermostat holds an elastic gas; restitution " +
                         std::to_string(alpha) + " < 1 reaches its own steady state");
    const double old = alpha_;
    if (alpha < 1.0 && (old == 1.0 || s_.t_last.size() != size()))
      s_.t_last.assign(size(), -never);
    alpha_ = alpha;
    return old;
  }
  /// The TC model's t_c (Config::tc_time), time units.
  double tc_time() const { return tc_; }
  /// Sets t_c for the collisions from now on; throws InvalidInput unless finite and >= 0.
  void set_tc_time(double tc) {
    check_tc_time(tc);
    tc_ = tc;
  }
  /// Collisions the TC rule made elastic since the start (counted while alpha < 1).
  std::uint64_t tc_elastic_collisions() const { return s_.ntc; }

  // ---- uniform shear flow (lees_edwards.hpp) -------------------------------------------
  /// Shear rate per ideal-gas mean collision time at the start (Config::shear_rate; 0: none).
  double shear_rate() const { return le_.on() ? le_.rate / le_.nu0 : 0.0; }
  /// The Lees–Edwards frame and the exact stress sums (integrated to their last update).
  const LeesEdwards<D>& lees_edwards() const { return le_; }
  /// The largest relative deviation from the energy balance E(t) = E(0) - a (int K_xy dt +
  /// W_yx) - (thermostat) seen at an observation (round-off: ~1e-12).
  double energy_balance_residual() const { return le_.residual; }

 private:
  /// Processes the events due at or before t and before `sample` (an event at the instant
  /// of a sample comes after it), in one kernel: with or without the tally.
  template <bool Record>
  void events_until(double t, double sample) {
    for (double te = q_.top_time(); te <= t && te < sample; te = q_.top_time())
      step_event<Record>();
  }

  /// Processes the earliest event (engine_events.hpp).
  template <bool Record>
  void step_event();

 public:

  // ---- observables --------------------------------------------------------------------
  double time() const { return s_.now; }
  std::uint64_t collisions() const { return s_.ncoll; }
  /// Events other than collisions since the start: cell crossings, and stale pair events
  /// (the partner collided with someone else first) that only cost a re-prediction.
  std::uint64_t crossings() const { return s_.ncross; }
  std::uint64_t stale_events() const { return s_.nstale; }
  /// Pair times computed by the scans since the start (the cost measure of the cell lists).
  std::uint64_t pairs_tested() const { return s_.npairs; }
  /// Predictions (neighbour scans) since the start: after collisions, crossings and stale
  /// events whose runner-up was no longer valid.
  std::uint64_t scans() const { return s_.nscan; }
  std::size_t size() const { return s_.size(); }
  double box_side() const { return s_.L; }
  /// Packing fraction at the current diameters.
  double packing() const { return s_.packing(); }
  /// Kinetic temperature kT = sum m c^2 / (D N) (energy units) of the peculiar velocities
  /// c: under shear c = v - u(y) relative to the streaming profile u = a (y - L/2) e_x
  /// (lees_edwards.hpp), otherwise c = v; in a granular gas the granular temperature,
  /// falling with time.
  double temperature() const {
    return 2.0 * peculiar_kinetic_energy() / (D * static_cast<double>(size()));
  }
  /// sum m c^2 / 2 of the peculiar velocities c (temperature()); kinetic_energy() without
  /// shear.
  double peculiar_kinetic_energy() const {
    if (!le_.on()) return kinetic_energy();
    return 0.5 * kinetic_tensor(s_.now).trace();
  }
  /// Kinetic energy of the streaming profile at the particles' heights, sum m u(y_i)^2 / 2
  /// (a^2 L^2 / 24 per particle of unit mass in a uniform gas); 0 without shear.
  double streaming_kinetic_energy() const {
    if (!le_.on()) return 0.0;
    double e = 0.0;
    for (std::size_t i = 0; i < size(); ++i) {
      const double u = flow_at(i, s_.now);
      e += s_.p.mass(i) * u * u;
    }
    return 0.5 * e;
  }
  /// The streaming velocity u(y) (along x) at particle i's height at time t, its position
  /// moved on from its local clock (the sheared gas; engine_shear.hpp).
  double flow_at(std::size_t i, double t) const {
    constexpr int Y = LeesEdwards<D>::y;
    return le_.stream(s_.p.position(i)[Y] + s_.p.velocity(i)[Y] * (t - s_.p.local_time(i)));
  }
  /// sum m v^2 / 2 of the lab velocities v (the streaming flow included under shear).
  double kinetic_energy() const {
    double e = 0.0;
    for (std::size_t i = 0; i < size(); ++i) e += s_.p.mass(i) * s_.p.velocity(i).squaredNorm();
    return 0.5 * e;
  }
  Vec<D> momentum() const {
    Vec<D> m = Vec<D>::Zero();
    for (std::size_t i = 0; i < size(); ++i) m += s_.p.mass(i) * s_.p.velocity(i);
    return m;
  }
  /// Starts a new measurement window for Z, collision rate and mean free time.
  void reset_observables() { win_.reset(s_.now, s_.ncoll); }
  /// Collisions in the current window.
  std::uint64_t window_collisions() const { return win_.collisions(s_.ncoll); }
  /// Whether Z = PV/(N kT) is defined for the gas as it runs now (has_pressure_Z,
  /// observables.hpp: elastic and not sheared).
  bool pressure_Z_defined() const { return has_pressure_Z(alpha_, le_.rate); }
  /// Reduced pressure Z = PV/(N kT) = 1 + sum_coll r_ij . dp_i / (D N kT t) over the window.
  /// An equilibrium measurement: throws InvalidInput while the restitution is below 1 or
  /// the gas is sheared (pressure_Z_defined()).
  double pressure_Z() const {
    if (alpha_ < 1.0)
      throw InvalidInput("pressure_Z: a granular gas (restitution " + std::to_string(alpha_) +
                         " < 1) cools; Z = PV/(N kT) needs equilibrium");
    if (!pressure_Z_defined())
      throw InvalidInput("pressure_Z: a sheared gas is not in equilibrium; its pressure is "
                         "the tensor of the shear flow, not Z = PV/(N kT)");
    return win_.pressure_Z(D, size(), temperature(), s_.now);
  }
  /// pressure_Z() where pressure_Z_defined(), NaN otherwise.
  double pressure_Z_or_nan() const {
    return pressure_Z_defined() ? pressure_Z() : std::numeric_limits<double>::quiet_NaN();
  }
  /// The engine's facts in a run's summary (summary.json, docs/design.md): put(key, value)
  /// for each, value a double, std::int64_t or std::string_view. Z and its contact value
  /// are NaN where Z is undefined (pressure_Z_defined); a sheared gas adds its energy
  /// balance, the ideal gas's collision rate at T0 and the flow's kinetic energy per
  /// particle (which kT leaves out), a granular one the TC model's elastic collisions.
  template <class Put>
  void describe(Put&& put) const {
    const double Z = pressure_Z_or_nan();
    put("packing", packing());
    put("scan", Scan::name);
    put("Z", Z);
    put("collision_rate", collision_rate());
    put("mean_free_time", mean_free_time());
    put("kT", temperature());  // of the peculiar velocities under shear
    put("contact_value_from_Z", contact_value(D, Z, packing()));  // NaN with Z
    if (le_.on()) {
      put("energy_balance_residual", energy_balance_residual());
      put("ideal_collision_rate", le_.nu0);
      put("streaming_kinetic_energy", streaming_kinetic_energy() / static_cast<double>(size()));
    }
    if (alpha_ < 1.0) put("tc_elastic_collisions", static_cast<std::int64_t>(s_.ntc));
  }
  /// Collisions per particle per unit time in the window (2 per collision); in a cooling
  /// granular gas the mean over the window.
  double collision_rate() const { return win_.collision_rate(size(), s_.ncoll, s_.now); }
  /// Mean free time per particle, 1 / collision_rate (sigma sqrt(m/kT)).
  double mean_free_time() const { return 1.0 / collision_rate(); }
  /// The particle store in memory order: the engine renumbers particles by position from
  /// time to time (reorder()); original_id(i) is the number particle i started with, and
  /// snapshots (run_until's observer) always use the original numbering.
  const Store& particles() const { return s_.p; }
  std::size_t original_id(std::size_t i) const { return s_.id[i]; }
  /// original_id of every memory slot (the array the engine keeps; valid until it is
  /// destroyed, its contents change when the engine renumbers).
  const std::vector<std::uint32_t>& original_ids() const { return s_.id; }
  /// Brings every particle's record to time(): afterwards particles().position(i) is where
  /// particle i is now (in the box, up to round-off) and its local clock is time(). Events
  /// and cells are unchanged; later pair times are computed from the moved records, so the
  /// trajectory equals one without the call up to round-off, not bit for bit.
  void synchronize() {
    for (std::uint32_t i = 0; i < size(); ++i) {
      if constexpr (lists) s_.wrap(i);  // list scans let a position leave the box a little
      else s_.advance(i);
    }
  }
  /// Unwrapped position of particle a (original numbering) at the current time (length).
  Vec<D> unwrapped_position(std::size_t a) const {
    const std::size_t i = s_.slot[a];
    Vec<D> x = s_.p.position(i) + s_.p.velocity(i) * (s_.now - s_.p.local_time(i));
    for (int k = 0; k < D; ++k) x[k] += s_.L * s_.image[i * D + k];
    return x;
  }
  /// Persistent bytes per particle of the whole engine state.
  double bytes_per_particle() const {
    return s_.p.bytes_per_particle() + D * sizeof(std::int32_t) + sizeof(Ev) +
           3 * sizeof(std::uint32_t) + CalendarQueue::bytes_per_particle() +
           s_.cells.bytes_per_particle(size()) + scanner_.bytes_per_particle(s_) +
           (s_.t_last.empty() ? 0.0 : sizeof(double));
  }
  int cells_per_side() const { return s_.cells.per_side(); }
  /// Current diameter scale (1 after compression).
  double diameter_scale() const { return s_.diameter_scale(); }
  const Config& config() const { return cfg_; }

  // ---- used by the LS compression (compression.hpp) and the tests ----------------------
  /// Brings every particle to the current time, rebuilds cells for the current diameters
  /// (growth rate `rate` from now on), rescales velocities to kinetic temperature kT if
  /// kT > 0, sets the diameter scale to `exact_scale` if > 0 (only to remove round-off), and
  /// re-predicts every event.
  void restart(double rate, double kT = 0.0, double exact_scale = 0.0) {
    s_.scale_ref = exact_scale > 0.0 ? exact_scale : diameter_scale();
    s_.t_scale = s_.now;
    s_.rate = rate;
    for (std::uint32_t i = 0; i < size(); ++i) s_.advance(i);  // before velocities change
    if (kT > 0.0) {
      const double f = std::sqrt(kT / temperature());
      for (std::size_t i = 0; i < size(); ++i) s_.p.velocity(i) *= f;
    }
    rebuild();
  }
  /// Moves the origin of time to now: t = 0 and zero collisions afterwards (the state and
  /// the diameters are unchanged; every event is predicted again).
  void restart_clock() {
    for (std::uint32_t i = 0; i < size(); ++i) s_.advance(i);
    s_.scale_ref = diameter_scale();
    for (std::size_t i = 0; i < size(); ++i) s_.p.local_time(i) = 0.0;
    for (double& t : s_.t_last) t -= s_.now;  // TC clocks: the same intervals
    s_.now = s_.t_scale = 0.0;
    s_.ncoll = s_.ncross = s_.nstale = s_.npairs = s_.nscan = s_.ntc = next_reorder_ = 0;
    rebuild();
  }
  /// Turns the per-event all-pairs overlap check on or off; returns the previous setting.
  bool set_debug(bool on) {
    const bool old = debug_;
    debug_ = on;
    return old;
  }
  /// Largest diameter scale the current cells allow (State::max_scale_for_cells).
  double max_scale_for_cells() const { return s_.max_scale_for_cells(shell()); }
  /// Checks all pairs (O(N^2)); throws std::logic_error naming an overlapping pair.
  void check_overlaps() const {
    s_.check_overlaps(le_.on(), le_.on() ? le_.delta(s_.now) : 0.0);
  }

 private:
  using Scanner = typename Scan::template Scanner<D, F>;
  /// Whether the scan keeps neighbour lists (scan_lists.hpp): its crossing event renews a
  /// list, and its cells are wider than a contact distance by shell().
  static constexpr bool lists = requires { Scanner::lists; };
  double shell() const {
    if constexpr (lists) return scanner_.shell(s_);
    else return 0.0;
  }

  /// After the particles are placed (setup or setup_given): calendar, compression, clock.
  void begin();
  /// Brings every particle into the box, rebuilds the cells for the current diameters and
  /// predicts every event.
  void rebuild();

  /// Predicts i's pair events and crossing: the one-cell box by scan_small_box, else by the
  /// scan policy (all neighbour cells, or the slab `dir` along `axis` after a crossing for
  /// SlabScan, keeping the earliest pair events if they beat `top`).
  void scan(std::uint32_t i, int axis, int dir, Top2 top) {
    const double sc = s_.diameter_scale();
    if (le_.on()) [[unlikely]] {  // every prediction scans the whole sliding stencil
      scan_sheared(s_, le_, i, sc);
      return;
    }
    if (s_.cells.per_side() == 1) {
      scan_small_box(s_, i, sc);
      return;
    }
    scanner_.scan(s_, i, axis, dir, top, sc);
  }

  /// Prefetches the data of the events due next, in stages, so that it is in cache when
  /// they come: the calendar entries three buckets ahead, the event records two ahead, and
  /// one ahead the particle records (and lists) of the particle and its partner, whose
  /// event record was asked for one event earlier. Changes nothing but timing.
  void look_ahead();

  /// Full prediction for i (advanced to now) and queue update.
  void predict(std::uint32_t i) {
    scan(i, -1, 0, Top2{});
    q_.update(i, std::min(s_.ev[i].t_pair, s_.ev[i].t_cross));
  }

  /// Collides i and j (at now): advances both, updates the velocities, the virial, the
  /// tally (Record) and the collision counters.
  template <bool Record>
  void collide(std::uint32_t i, std::uint32_t j);

  /// The velocity update of a granular collision of i and j (at now, unit normal n from j
  /// to i): inelastic with alpha_, or elastic by the TC rule if either particle collided
  /// less than tc_ ago (never when tc_ = 0); the pair is left receding (keep_receding).
  /// Out of line, so that the elastic event loop's code stays as compact as without it.
  [[gnu::noinline]] void collide_granular(std::uint32_t i, std::uint32_t j, double wi,
                                          double wj, const Vec<D>& n) {
    State<D, F>& s = s_;
    double a = alpha_;
    double& ti = s.t_last[i];
    double& tj = s.t_last[j];
    if (s.now - ti < tc_ || s.now - tj < tc_) a = 1.0, ++s.ntc;
    ti = tj = s.now;
    collide_inelastic<D>(s.p.velocity(i), s.p.velocity(j), wi, wj, n, a);
    keep_receding<D>(s.p.velocity(i), s.p.velocity(j), wi, wj, n);
  }

  /// Moves i into the next cell along its crossing (or renews its list) and predicts again.
  void cross(std::uint32_t i);

  // ---- the sheared gas (lees_edwards.hpp; engine_shear.hpp) ------------------------------
  /// Starts the flow at now: the streaming velocity added, the sums set, events predicted.
  void start_shear();
  /// run_until under Lees–Edwards boundaries: events, shifts, thermostat and samples in
  /// time order.
  void run_sheared(double t, Observer* obs, double every);
  /// The collision of i and j (Engine::collide) in the sliding frame, with the stress sums.
  [[gnu::noinline]] void collide_sheared(std::uint32_t i, std::uint32_t j);
  /// i (at now) passes the top (sgn = -1) or bottom (+1) face: its x moves by sgn delta,
  /// its x velocity by sgn U (its peculiar velocity is kept).
  void through_face(std::uint32_t i, int sgn);
  /// cross() of the y face: through_face, x back into the box, c[0] its new column.
  void slide(std::uint32_t i, std::array<int, D>& c, int sgn);
  /// wrap() in the sliding frame.
  void wrap_sheared(std::uint32_t i);
  /// Makes the shift or the rescaling due before an event at te (the earlier of the two;
  /// an event at the same instant comes first); false if neither is.
  bool frame_step_before(double te);
  /// The column offset moves on: the top and bottom rows scan again.
  void shear_shift(double ts);
  /// Rescales the peculiar velocities (isokinetic thermostat) and predicts every event.
  void thermostat_step(double th);
  /// sum m c c^T at time t (>= every local clock).
  typename LeesEdwards<D>::Mat kinetic_tensor(double t) const;

  /// Renumbers the particles in Z-order of their cells, so that a scan's neighbours lie
  /// near each other in memory (at N = 256000 the state is larger than the caches, and a
  /// random numbering makes nearly every neighbour a cache miss). A pure permutation of
  /// every per-particle array: no particle is advanced and no event re-predicted, so the
  /// trajectories are unchanged bit for bit. Snapshots and error messages report the
  /// original numbering (State::id).
  void reorder();

  void refuse_tally_if_granular() const {
    if (alpha_ < 1.0)
      throw InvalidInput("the Helfand tally measures equilibrium transport; the gas has "
                         "restitution " + std::to_string(alpha_) + " < 1");
  }

  /// Observes the state at time ts (>= every local clock) in the original numbering
  /// (snapshot.hpp).
  void sample(double ts, Observer& obs) const {
    if (le_.on()) [[unlikely]] {
      sample_sheared(ts, obs);
      return;
    }
    observe_state(s_, ts, obs, &contacts_, &win_);
  }
  /// sample() of the sheared gas: the energy balance checked, peculiar velocities and the
  /// stress sums at ts.
  void sample_sheared(double ts, Observer& obs) const;

  ScanState<D, F> s_;        // particles, events, cells, clock, counters (state.hpp) and
                             // the scratch of the scans (prediction.hpp)
  Scanner scanner_;          // the scan policy's own data (scan.hpp)
  CalendarQueue q_;          // one event per particle
  MeasurementWindow win_;    // Z and collision-rate window (observables.hpp)
  std::uint64_t reorder_every_ = 0, next_reorder_ = 0;  // renumbering period (collisions)
  bool debug_ = false;
  Config cfg_;
  double alpha_ = 1.0;  // restitution in effect (1 while compressing the start)
  double tc_ = 0.0;     // TC model's t_c
  mutable tally::ContactSlot contacts_;  // the Helfand tally, if a recorder installed one
  LeesEdwards<D> le_;  // the shear flow (lees_edwards.hpp); off unless shear_rate > 0
};

}  // namespace hypergas::edmd

#include "hypergas/edmd/engine_run.hpp"     // start, save and run: member definitions
#include "hypergas/edmd/engine_events.hpp"  // the event kernel's member definitions
#include "hypergas/edmd/engine_shear.hpp"   // the sheared gas's member definitions

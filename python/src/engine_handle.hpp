// python/src/engine_handle.hpp -- an engine of any dimension, model and feature set behind
// one runtime interface: what the Python module holds.
//
// The factories (make_dsmc, make_edmd) turn validated run options into an engine through
// the project's one dispatch (registry::dispatch); every (D, model, species) combination
// of the command is compiled here too, in one translation unit per dimension
// (handles_dim.cpp.in) so that the module builds in parallel.
//
// Arrays handed out (velocities, positions, ids, species) are the engine's own memory, in
// its memory layout: row i of particle i starts at `data + i * stride` doubles. They stay
// valid as long as the engine lives (the particle count never changes), and their contents
// change when the engine runs.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/edmd/given_state.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/options/run_options.hpp"

namespace hypergas::python {

/// Layout of one per-particle array of doubles: element (i, k) at data[i * stride + k].
struct Rows {
  const double* data = nullptr;
  int stride = 0;
};

/// What every engine offers Python.
class EngineHandle {
 public:
  virtual ~EngineHandle() = default;
  virtual int dim() const = 0;
  virtual std::size_t size() const = 0;
  /// Engine time (DSMC: equilibrium mean collision times; EDMD: sigma sqrt(m/kT)).
  virtual double time() const = 0;
  virtual std::uint64_t collisions() const = 0;
  /// Advances to time t as run_until(t) does (engine_concept.hpp). `poll` is called now and
  /// then with the engine consistent at time(); it may throw to stop early, leaving the
  /// engine at time() < t, ready to go on. Without a throw the trajectory is that of
  /// run_until(t).
  virtual void advance(double t, const std::function<void()>& poll) = 0;
  /// obs.observe(snapshot of now): the snapshot the command's recorders see.
  virtual void observe(Observer& obs) = 0;
  /// The velocities in memory order (velocity units).
  virtual Rows velocities() const = 0;
  /// Per-particle species index (0 or 1), or nullptr with one species.
  virtual const std::uint8_t* species() const = 0;
  /// Mass of each species (species-0 mass 1); one entry with one species.
  virtual std::vector<double> species_masses() const = 0;
  /// Sum of m v^2 / 2 (energy units) and of m v (momentum units), in long double.
  virtual double kinetic_energy() const = 0;
  virtual std::vector<double> momentum() const = 0;
  /// Bytes of engine state per particle.
  virtual double bytes_per_particle() const = 0;
};

/// The DSMC engine (velocity space).
class DsmcHandle : public EngineHandle {
 public:
  /// Threads of the one system (1..256); the trajectory is the same for every count.
  virtual void set_threads(int threads) = 0;
  virtual int threads() const = 0;
  /// Candidate pairs tested so far.
  virtual std::uint64_t candidates() const = 0;
  virtual const char* model() const = 0;
  /// Granular gas (dsmc/granular.hpp): the coefficient of normal restitution (1: elastic).
  virtual double restitution() const = 0;
  /// Time in mean collision times at the initial temperature (time() unless the gas cools
  /// freely, whose time() counts mean collision times at its current temperature).
  virtual double real_time() const = 0;
  /// The stored velocities are the true ones divided by exp(log_velocity_scale()) (0 unless
  /// the gas cools freely).
  virtual double log_velocity_scale() const = 0;
  /// White-noise kicks so far (drive white-noise).
  virtual std::uint64_t kicks() const = 0;
};

/// The EDMD engine (periodic box).
class EdmdHandle : public EngineHandle {
 public:
  /// Brings every record to time() and returns the positions in memory order (in the box
  /// [0, L)^D up to round-off; see edmd::Engine::synchronize).
  virtual Rows positions() = 0;
  /// Original number of the particle in each memory slot.
  virtual const std::uint32_t* ids() const = 0;
  /// Unwrapped positions now, in original numbering (a copy, n * D values).
  virtual std::vector<double> unwrapped_positions() const = 0;
  virtual double box_side() const = 0;
  virtual double packing() const = 0;
  virtual double temperature() const = 0;
  virtual double pressure_Z() const = 0;
  /// pressure_Z() where defined (elastic, not sheared: edmd::has_pressure_Z), NaN otherwise.
  virtual double pressure_Z_or_nan() const = 0;
  virtual double collision_rate() const = 0;
  virtual double mean_free_time() const = 0;
  virtual void reset_observables() = 0;
  /// Granular gas (edmd/restitution.hpp): the restitution in effect, its setter (returns the
  /// previous value; InvalidInput outside [0, 1]), the TC model's time and the collisions
  /// its rule made elastic.
  virtual double restitution() const = 0;
  virtual double set_restitution(double alpha) = 0;
  virtual double tc_time() const = 0;
  virtual std::uint64_t tc_elastic_collisions() const = 0;
};

/// Given initial velocities for a DSMC engine: n rows of o.dim doubles, contiguous, and
/// optionally a species index (0 or 1) per particle, species 1 having mass o.mass_ratio.
struct GivenVelocities {
  const double* v = nullptr;
  std::size_t n = 0;
  const std::uint8_t* species = nullptr;
};

/// Builds the engine that validated options `o` (engine dsmc) describe (its time scheme
/// included); from `given` velocities instead of o's initial state when
/// set. Throws InvalidInput for parameters the engine rejects.
std::unique_ptr<DsmcHandle> make_dsmc(const options::RunOptions& o,
                                      const GivenVelocities* given = nullptr);
/// The same for the EDMD engine (engine edmd); from a `given` state (positions in a periodic
/// cube, velocities: hypergas/edmd/given_state.hpp) instead of the lattice when set.
std::unique_ptr<EdmdHandle> make_edmd(const options::RunOptions& o,
                                      const edmd::GivenState* given = nullptr);

namespace detail {
// Defined in handles.hpp, instantiated once per dimension (handles_dim.cpp.in).
template <int D>
std::unique_ptr<DsmcHandle> make_dsmc_dim(const options::RunOptions& o, const dsmc::Config& cfg,
                                          const GivenVelocities* given);
template <int D>
std::unique_ptr<EdmdHandle> make_edmd_dim(const options::RunOptions& o, const edmd::Config& cfg,
                                          const edmd::GivenState* given);
}  // namespace detail

}  // namespace hypergas::python

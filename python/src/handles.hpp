// python/src/handles.hpp -- the engines behind EngineHandle (engine_handle.hpp): one class
// template per engine, and the per-dimension factories that pick model and features
// through registry::dispatch. Included only by the per-dimension translation units.
#pragma once

#include <chrono>
#include <cmath>
#include <memory>
#include <type_traits>
#include <utility>

#include "engine_handle.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/engines.hpp"

namespace hypergas::python::detail {

/// What both engines implement alike: `Base` is DsmcHandle or EdmdHandle.
template <class Engine, class Base>
class Common : public Base {
  using Store = std::decay_t<decltype(std::declval<const Engine&>().particles())>;

 public:
  template <class Config>
  explicit Common(const Config& cfg) : e_(cfg) {}
  template <class Config, class Store>
  Common(const Config& cfg, Store&& particles) : e_(cfg, std::forward<Store>(particles)) {}
  int dim() const override { return Engine::dim; }
  std::size_t size() const override { return e_.particles().size(); }
  double time() const override { return e_.time(); }
  std::uint64_t collisions() const override { return e_.collisions(); }
  void observe(Observer& obs) override { e_.observe(obs); }
  const std::uint8_t* species() const override {
    if constexpr (Store::features.species)
      return e_.particles().species_data().data();
    else
      return nullptr;
  }
  std::vector<double> species_masses() const override {
    if constexpr (Store::features.species)
      return {1.0 / e_.particles().species_inv_mass(0), 1.0 / e_.particles().species_inv_mass(1)};
    else
      return {1.0};
  }
  double kinetic_energy() const override {
    return static_cast<double>(conserved(e_.particles()).energy);
  }
  std::vector<double> momentum() const override {
    const auto c = conserved(e_.particles());
    return std::vector<double>(c.momentum.begin(), c.momentum.end());
  }
  double bytes_per_particle() const override { return e_.bytes_per_particle(); }
  Rows velocities() const override {
    return {e_.particles().velocity_data().data() + Store::velocity_offset, Store::stride};
  }

 protected:
  Engine e_;
};

template <class Engine>
class Dsmc final : public Common<Engine, DsmcHandle> {
  using Model = typename registry::EngineTraits<Engine>::Model;
  static_assert(SimulationEngine<Engine>);
  using Common<Engine, DsmcHandle>::e_;

 public:
  using Common<Engine, DsmcHandle>::Common;
  void advance(double t, const std::function<void()>& poll) override {
    // The engine calls poll between epochs; the handle clears it however run_until ends.
    struct Clear {
      Engine& e;
      ~Clear() { e.set_poll({}); }
    } clear{e_};
    e_.set_poll(poll);
    e_.run_until(t);
  }
  void set_threads(int threads) override {
    e_.set_threads(threads);
    threads_ = threads;
  }
  int threads() const override { return threads_; }
  std::uint64_t candidates() const override { return e_.candidates(); }
  const char* model() const override { return Model::name.data(); }
  double restitution() const override { return e_.restitution(); }
  double real_time() const override { return e_.real_time(); }
  double log_velocity_scale() const override { return e_.log_velocity_scale(); }
  std::uint64_t kicks() const override { return e_.kicks(); }

 private:
  int threads_ = 1;
};

template <class Engine>
class Edmd final : public Common<Engine, EdmdHandle> {
  static constexpr int D = Engine::dim;
  static_assert(SimulationEngine<Engine>);
  using Common<Engine, EdmdHandle>::e_;

 public:
  using Common<Engine, EdmdHandle>::Common;
  /// The engine's trajectory does not depend on where run_until stops (run_driver.hpp), so
  /// the handle advances in slices of about 50 ms of wall time and polls between them.
  void advance(double t, const std::function<void()>& poll) override {
    using Clock = std::chrono::steady_clock;
    if (!poll || !(t > e_.time())) {
      e_.run_until(t);
      return;
    }
    double slice = std::min(t - e_.time(), 0.01);
    while (e_.time() < t) {
      const auto t0 = Clock::now();
      e_.run_until(std::min(t, e_.time() + slice));
      const double wall = std::chrono::duration<double>(Clock::now() - t0).count();
      slice *= std::clamp(0.05 / std::max(wall, 1e-6), 0.5, 4.0);
      poll();
    }
  }
  Rows positions() override {
    e_.synchronize();
    return {e_.particles().velocity_data().data(), Engine::Store::stride};
  }
  const std::uint32_t* ids() const override { return e_.original_ids().data(); }
  std::vector<double> unwrapped_positions() const override {
    std::vector<double> x(this->size() * D);
    for (std::size_t a = 0; a < this->size(); ++a) {
      const auto r = e_.unwrapped_position(a);
      for (int k = 0; k < D; ++k) x[a * D + k] = r[k];
    }
    return x;
  }
  double box_side() const override { return e_.box_side(); }
  double packing() const override { return e_.packing(); }
  double temperature() const override { return e_.temperature(); }
  double pressure_Z() const override { return e_.pressure_Z(); }
  double pressure_Z_or_nan() const override { return e_.pressure_Z_or_nan(); }
  double collision_rate() const override { return e_.collision_rate(); }
  double mean_free_time() const override { return e_.mean_free_time(); }
  void reset_observables() override { e_.reset_observables(); }
  double restitution() const override { return e_.restitution(); }
  double set_restitution(double alpha) override { return e_.set_restitution(alpha); }
  double tc_time() const override { return e_.tc_time(); }
  std::uint64_t tc_elastic_collisions() const override { return e_.tc_elastic_collisions(); }
};

/// Particles holding `given` (velocities, species with species-1 mass `mass_ratio`).
template <class Store>
Store given_particles(const GivenVelocities& given, double mass_ratio) {
  constexpr int D = Store::dim;
  Store p(given.n);
  for (std::size_t i = 0; i < given.n; ++i)
    for (int k = 0; k < D; ++k) p.velocity(i)[k] = given.v[i * D + k];
  if constexpr (Store::features.species) {
    p.set_species_mass(1, mass_ratio);
    for (std::size_t i = 0; i < given.n; ++i) p.set_species(i, given.species ? given.species[i] : 0);
  }
  return p;
}

template <int D>
std::unique_ptr<DsmcHandle> make_dsmc_dim(const options::RunOptions& o, const dsmc::Config& cfg,
                                          const GivenVelocities* given) {
  return registry::with_engine<D>(
      options::engine_choice(o), [&](auto engine) -> std::unique_ptr<DsmcHandle> {
        using Engine = typename decltype(engine)::type;
        if constexpr (registry::is_dsmc<Engine>) {
          if (!given) return std::make_unique<Dsmc<Engine>>(cfg);
          using Store = Particles<D, registry::EngineTraits<Engine>::features>;
          return std::make_unique<Dsmc<Engine>>(cfg,
                                                given_particles<Store>(*given, o.mass_ratio));
        } else {
          throw InvalidInput("python: an EDMD choice reached the DSMC factory");
        }
      });
}

template <int D>
std::unique_ptr<EdmdHandle> make_edmd_dim(const options::RunOptions& o, const edmd::Config& cfg,
                                          const edmd::GivenState* given) {
  return registry::with_engine<D>(
      options::engine_choice(o), [&](auto engine) -> std::unique_ptr<EdmdHandle> {
        using Engine = typename decltype(engine)::type;
        if constexpr (!registry::is_dsmc<Engine>) {
          if (given) return std::make_unique<Edmd<Engine>>(cfg, *given);
          return std::make_unique<Edmd<Engine>>(cfg);
        }
        else
          throw InvalidInput("python: a DSMC choice reached the EDMD factory");
      });
}

}  // namespace hypergas::python::detail

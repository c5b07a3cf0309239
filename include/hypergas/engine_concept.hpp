// hypergas/engine_concept.hpp -- what every engine is: the seam the command, the studies
// and the bindings program against.
//
// Both dsmc::Engine<D, Model, F> and edmd::Engine<D, F, Scan> satisfy `SimulationEngine`:
//   E::Config                    the run's parameters; `E e(cfg)` samples the initial state
//                                cfg.init with parameters cfg.initial (InitialParams) from
//                                cfg.seed, and throws InvalidInput for a bad configuration;
//   e.run_until(t, obs, every)   advances the gas to time t (time() == t afterwards). With an
//                                observer, obs->observe(snapshot) is called at the instants
//                                of Schedule::make(t0, t, every) (schedule.hpp: evenly
//                                spaced, the last at t), t0 = time() at the call.
//                                Throws InvalidInput if t is not finite or t < time(), or if
//                                obs is set and `every` is not finite and > 0;
//   e.observe(obs)               calls obs.observe with the state at time(), changing
//                                nothing (a driver that picks its own stops uses it);
//   e.time(), e.collisions()     the engine's clock and the accepted collisions so far;
//   e.particles()                the particle store (conserved(e.particles()) gives the
//                                conserved sums, conserved.hpp);
//   E::dim                       the dimension D.
// Time units differ by engine: DSMC counts equilibrium mean collision times, EDMD
// sigma sqrt(m/kT).
#pragma once

#include <concepts>
#include <cstdint>

#include "hypergas/conserved.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/observer.hpp"

namespace hypergas {

template <class E>
concept SimulationEngine = requires(E& e, const E& ce, const typename E::Config& cfg,
                                    Observer* obs, double t) {
  { E::dim } -> std::convertible_to<int>;
  { cfg.seed } -> std::convertible_to<std::uint64_t>;
  { cfg.init } -> std::convertible_to<InitialState>;
  { cfg.initial } -> std::convertible_to<InitialParams>;
  E(cfg);
  e.run_until(t, obs, t);
  e.observe(*obs);
  { ce.time() } -> std::convertible_to<double>;
  { ce.collisions() } -> std::convertible_to<std::uint64_t>;
  conserved(ce.particles());
};

}  // namespace hypergas

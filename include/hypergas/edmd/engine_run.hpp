// hypergas/edmd/engine_run.hpp -- the members of edmd::Engine (engine.hpp) that start, save
// and run the gas: the constructors, begin, io, run_until, observe and step. Defined out of
// the class and not inline, as they were in engine.hpp; engine.hpp includes this header
// after the class, so include engine.hpp.
#pragma once

#include <cmath>
#include <string>

#include "hypergas/edmd/engine.hpp"

namespace hypergas::edmd {

// The members that start, save and run the gas, defined out of the class: not inline, so
// a file that sees the engine declared extern (hypergas/engines.hpp) calls the engines
// library's copy instead of compiling the event loop again.

template <int D, Features F, class Scan>
Engine<D, F, Scan>::Engine(const Config& cfg) : debug_(cfg.debug_overlap), cfg_(cfg) {
  s_.setup(cfg);
  begin();
}

template <int D, Features F, class Scan>
Engine<D, F, Scan>::Engine(const Config& cfg, const GivenState& g)
    : debug_(cfg.debug_overlap), cfg_(cfg) {
  check_given_state<D>(g);
  if (g.n != cfg.n) throw InvalidInput("EDMD start: the state's N differs from the config's");
  s_.setup_given(cfg, g);  // diameter scale 1: no compression
  begin();
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::begin() {
  const std::size_t n = cfg_.n;
  reorder_every_ = cfg_.reorder_interval > 0.0
                       ? static_cast<std::uint64_t>(cfg_.reorder_interval * 0.5 * n) + 1
                       : ~std::uint64_t{0};
  rebuild();
  if (s_.scale_ref < 1.0) {
    compress(*this, 1.0, cfg_);  // elastic: alpha_ is 1 until set below
    restart_clock();  // the compression is preparation: the run starts at t = 0
  }
  tc_ = cfg_.tc_time;
  set_restitution(cfg_.restitution);
  if (cfg_.shear_rate != 0.0 || cfg_.thermostat_interval != 0.0) start_shear();
  reset_observables();
}

template <int D, Features F, class Scan>
Engine<D, F, Scan>::Engine(const Config& cfg, checkpoint::Reader& in)
    : debug_(cfg.debug_overlap), cfg_(cfg) {
  io(in);
}

template <int D, Features F, class Scan>
template <class Archive>
void Engine<D, F, Scan>::io(Archive& a) {
  a.tag(identity());
  a(static_cast<State<D, F>&>(s_), scanner_, q_, win_, reorder_every_, next_reorder_, cfg_,
    alpha_, tc_, le_);
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::run_until(double t, Observer* obs, double every) {
  if (obs && !(every > 0.0 && std::isfinite(every)))
    throw InvalidInput("sampling interval must be finite and > 0");
  if (!std::isfinite(t))
    throw InvalidInput("run_until(" + std::to_string(t) + "): the time must be finite");
  if (!(t >= s_.now))
    throw InvalidInput("run_until(" + std::to_string(t) + "): the gas is already at t = " +
                       std::to_string(s_.now));
  if (le_.on()) [[unlikely]] {
    run_sheared(t, obs, every);
    return;
  }
  const Schedule plan = obs ? Schedule::make(s_.now, t, every) : Schedule{};
  std::uint64_t k = 0;
  double next_sample = obs ? plan.time(0) : never;
  for (;;) {
    const double te = q_.top_time();
    while (obs && next_sample <= te) {
      sample(next_sample, *obs);
      next_sample = ++k <= plan.intervals() ? plan.time(k) : never;
    }
    if (te > t) break;
    // an observer may install a Helfand tally at a sample: the loop then changes kernel
    if (contacts_.helfand) [[unlikely]] {
      refuse_tally_if_granular();
      events_until<true>(t, next_sample);
    } else {
      events_until<false>(t, next_sample);
    }
  }
  s_.now = t;
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::observe(Observer& obs) const {
  sample(s_.now, obs);
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::step() {
  if (le_.on()) [[unlikely]]  // shifts and rescalings due first are done first
    while (frame_step_before(q_.top_time())) {
    }
  if (contacts_.helfand) {
    refuse_tally_if_granular();
    step_event<true>();
  } else {
    step_event<false>();
  }
}

}  // namespace hypergas::edmd

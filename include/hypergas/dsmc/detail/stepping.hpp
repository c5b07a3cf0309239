// hypergas/dsmc/detail/stepping.hpp -- time stepping: the exact scheme's Poisson epochs
// (stopped at a raise of the bound, the clock moved to the stopping candidate's order
// statistic), Bird's NTC steps of dt, and the majorant upkeep both share. Each epoch or
// step hands its candidates to the one-thread loop (lane.hpp) or to the thread team
// (parallel.hpp). docs/design.md, "The exact Kac process (DSMC)", derives the epochs.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <random>
#include <string>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/error.hpp"
#include "hypergas/dsmc/detail/lane.hpp"
#include "hypergas/dsmc/detail/parallel.hpp"
#include "hypergas/dsmc/detail/state.hpp"
#include "hypergas/dsmc/granular.hpp"

namespace hypergas::dsmc::detail {

/// lambda = N c G^a / 2 for the current bound G.
template <int D, class Model, Features F>
void set_lambda(State<D, Model, F>& s) {
  s.lambda = 0.5 * s.n * s.c * s.bound.bound_power(s.model.exponent());
}

/// Resets the majorant from an exact scan (when `force` or after enough candidates).
template <int D, class Model, Features F>
void retune(State<D, Model, F>& s, bool force) {
  if constexpr (!Model::needs_majorant) {
    s.lambda = 0.5 * s.n * s.c;
    return;
  }
  if (force || s.since_scan >= 8ull * s.n) {
    s.bound.rescan(s.p);
    s.since_scan = 0;
  }
  set_lambda(s);
}

/// Processes up to m candidates. Exact: stops after an accepted collision that leaves a
/// speed above the bound and returns the number processed (raise_to holds the new
/// maximum squared speed). NTC: never stops; records the largest such speed.
template <bool Exact, int D, class Model, Features F>
std::uint64_t process(State<D, Model, F>& s, ParallelBlocks& blocks, std::uint64_t m) {
  // Collective fluxes: the one-thread loop (transport runs are small). They are defined for
  // one species and the exact scheme only, and compiled for those engines alone (each hook
  // is another instantiation of the candidate loop, and the command's build time counts).
  if (s.tally.fluxes) {
    if constexpr (Exact && !F.species) {
      Lane lane;
      tally::Fluxes* f = s.tally.fluxes.get();
      std::uint64_t k;
      if (tally::Tally* t = s.tally.tally.get())
        k = run_lane<Exact, false, false>(s, lane, s.candidates, m, s.bound.bound(),
                                          FluxHook<true>{f, t});
      else
        k = run_lane<Exact, false, false>(s, lane, s.candidates, m, s.bound.bound(),
                                          FluxHook<false>{f, nullptr});
      s.collisions += lane.collisions;
      s.raise_to = std::max(s.raise_to, lane.raise_s2);
      s.candidates += k;
      return k;
    } else {
      throw InvalidInput("collective fluxes need one species and the exact scheme");
    }
  }
  std::uint64_t k;
  if (blocks.takes(m)) {
    k = blocks.process<Exact>(s, m);
  } else {
    Lane lane;
    if (s.tally.tally)
      k = run_lane<Exact, false, false>(s, lane, s.candidates, m, s.bound.bound(),
                                        TallyHook{s.tally.tally.get()});
    else
      k = run_lane<Exact, false, false>(s, lane, s.candidates, m, s.bound.bound());
    s.collisions += lane.collisions;
    s.raise_to = std::max(s.raise_to, lane.raise_s2);
  }
  s.candidates += k;
  return k;
}

/// After an epoch (or NTC step) of m candidates from `first` on over [t0, s.time]: the
/// tagged particles of installed fluxes integrate their displacements (tally/fluxes.hpp).
template <int D, class Model, Features F>
void end_epoch(State<D, Model, F>& s, double t0, std::uint64_t first, std::uint64_t m,
               bool last_at_end) {
  if (!s.tally.fluxes || s.tally.fluxes->tagged() == 0) return;
  const double* v = s.p.velocity_data().data();
  s.tally.fluxes->epoch(t0, s.time, first, m, last_at_end, [&](std::uint32_t i) {
    return v + std::size_t(i) * State<D, Model, F>::stride;
  });
}

/// Exact scheme: Poisson epochs of at most ~2N candidates up to t_end.
template <int D, class Model, Features F>
void advance_exact(State<D, Model, F>& s, ParallelBlocks& blocks,
                   const std::function<void()>& poll, double t_end) {
  while (s.time < t_end) {
    granular_upkeep(s);
    retune(s, false);
    const double target = std::min(t_end, next_kick(s));  // t_end without a drive
    double h = target - s.time;
    const double hmax = 2.0 * s.n / s.lambda;  // epochs of ~2N candidates
    const bool capped = h > hmax;
    if (capped) h = hmax;
    // a rate that leaves the clock where it is (a damaged or forged checkpoint) is refused,
    // not run for ever
    if (!(s.time + h > s.time) || !std::isfinite(s.lambda))
      throw InvalidInput("DSMC: the candidate rate " + std::to_string(s.lambda) +
                         " cannot advance the clock from t = " + std::to_string(s.time));
    std::poisson_distribution<std::uint64_t> pois(s.lambda * h);
    const std::uint64_t m = pois(s.rng);
    const double t0 = s.time;
    const std::uint64_t first = s.candidates;
    const std::uint64_t k = process<true>(s, blocks, m);
    s.since_scan += k;
    const bool raised = s.raise_to != 0.0;
    // a raise stops the epoch at its candidate, the m-th included (raise_to is set)
    if (s.raise_to == 0.0) {
      s.time = capped ? s.time + h : target;
    } else {
      // k-th of m uniform order statistics on [time, time + h].
      s.time = std::min(s.time + h * order_statistic(s.rng, k, m), target);
      s.bound.set(s.raise_to);
      s.raise_to = 0.0;
      set_lambda(s);
    }
    end_epoch(s, t0, first, k, raised);
    granular_after(s, t0);
    if (poll) poll();
  }
}

/// NTC scheme: steps of dt (the last one shortened to end at t_end), the bound raised
/// only at the end of a step.
template <int D, class Model, Features F>
void advance_ntc(State<D, Model, F>& s, ParallelBlocks& blocks,
                 const std::function<void()>& poll, double t_end) {
  while (s.time < t_end) {
    granular_upkeep(s);
    retune(s, false);
    const double target = std::min(t_end, next_kick(s));  // t_end without a drive
    double h = s.cfg.dt;
    const bool last = h >= target - s.time;
    if (last) h = target - s.time;
    const auto m = static_cast<std::uint64_t>(std::floor(s.lambda * h + s.rng.uniform()));
    const double t0 = s.time;
    const std::uint64_t first = s.candidates;
    process<false>(s, blocks, m);
    s.since_scan += m;
    if (s.raise_to > 0.0) {  // the bound catches up only at the end of the step
      s.bound.set(s.raise_to);
      s.raise_to = 0.0;
      set_lambda(s);
    }
    s.time = last ? target : s.time + h;
    end_epoch(s, t0, first, m, false);
    granular_after(s, t0);
    if (poll) poll();
  }
}

/// Advances to t_end with the configured scheme.
template <int D, class Model, Features F>
void advance_to(State<D, Model, F>& s, ParallelBlocks& blocks,
                const std::function<void()>& poll, double t_end) {
  if (s.cfg.scheme == Scheme::exact)
    advance_exact(s, blocks, poll, t_end);
  else
    advance_ntc(s, blocks, poll, t_end);
}

}  // namespace hypergas::dsmc::detail

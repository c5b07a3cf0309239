// hypergas/edmd/engine_shear.hpp -- the members of edmd::Engine (engine.hpp) that run the
// uniform shear flow under Lees–Edwards boundaries (lees_edwards.hpp): the start, the loop
// with its shifts and thermostat, the collision with the exact stress sums, the face
// crossing and the observation. Out of the class, inline; engine.hpp includes this header
// after the class, so include engine.hpp.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "hypergas/edmd/engine.hpp"

namespace hypergas::edmd {

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::start_shear() {
  constexpr int Y = LeesEdwards<D>::y;
  const double a = cfg_.shear_rate;
  if (!(std::isfinite(a) && a >= 0.0))
    throw InvalidInput("EDMD shear rate must be finite and >= 0, got " + std::to_string(a));
  if (!(std::isfinite(cfg_.thermostat_interval) && cfg_.thermostat_interval >= 0.0))
    throw InvalidInput("EDMD thermostat interval must be finite and >= 0");
  if (a == 0.0) {
    if (cfg_.thermostat_interval > 0.0)
      throw InvalidInput("EDMD: a thermostat needs a shear flow (shear rate 0)");
    return;
  }
  if constexpr (D < 2) {
    throw InvalidInput("EDMD shear flow needs D >= 2 (flow along x, gradient along y)");
  } else {
    if constexpr (lists)
      throw InvalidInput("EDMD shear flow: the neighbour-list scan (3D packing >= " +
                         std::to_string(list_packing(3)) + ") has no sliding boundaries");
    if (s_.cells.per_side() < 4)
      throw InvalidInput("EDMD shear flow needs at least 4 cells per side (the box has " +
                         std::to_string(s_.cells.per_side()) +
                         "): more particles or a lower packing");
    if (cfg_.thermostat_interval > 0.0 && alpha_ < 1.0)
      throw InvalidInput("the isokinetic thermostat holds an elastic gas; restitution " +
                         std::to_string(alpha_) + " < 1 reaches its own steady state");
    for (std::uint32_t i = 0; i < size(); ++i) s_.advance(i);
    le_ = LeesEdwards<D>{};
    le_.kT0 = temperature();
    le_.nu0 = ideal_collision_frequency(D, packing(), le_.kT0);
    le_.rate = a * le_.nu0;
    le_.L = s_.L;
    le_.w = s_.cells.width();
    le_.m = s_.cells.per_side();
    le_.t_ref = le_.t_start = le_.k_time = s_.now;
    for (std::uint32_t i = 0; i < size(); ++i)
      s_.p.velocity(i)[0] += le_.stream(s_.p.position(i)[Y]);
    le_.K = kinetic_tensor(s_.now);
    le_.E0 = 0.5 * le_.K.trace();
    le_.kT_set = le_.kT0;
    if (cfg_.thermostat_interval > 0.0) {
      le_.interval = cfg_.thermostat_interval / le_.nu0;
      le_.next_thermostat = s_.now + le_.interval;
    }
    rebuild();
  }
}

template <int D, Features F, class Scan>
typename LeesEdwards<D>::Mat Engine<D, F, Scan>::kinetic_tensor(double t) const {
  typename LeesEdwards<D>::Mat K = LeesEdwards<D>::Mat::Zero();
  for (std::uint32_t i = 0; i < size(); ++i) {
    Vec<D> c = s_.p.velocity(i);
    c[0] -= flow_at(i, t);
    K += (c * c.transpose()) / s_.p.inv_mass(i);
  }
  return K;
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::run_sheared(double t, Observer* obs, double every) {
  if (contacts_.helfand)
    throw InvalidInput("the Helfand tally measures equilibrium transport; the gas is sheared");
  const Schedule plan = obs ? Schedule::make(s_.now, t, every) : Schedule{};
  std::uint64_t k = 0;
  double next_sample = obs ? plan.time(0) : never;
  for (;;) {
    const double te = q_.top_time(), ts = le_.next_shift(), th = le_.next_thermostat;
    if (next_sample <= te && next_sample <= ts && next_sample <= th) {
      sample(next_sample, *obs);  // an event at the instant of a sample comes after it
      next_sample = ++k <= plan.intervals() ? plan.time(k) : never;
      continue;
    }
    if (std::min({te, ts, th}) > t) break;
    if (!frame_step_before(te)) step_event<false>();
  }
  s_.now = t;
}

template <int D, Features F, class Scan>
bool Engine<D, F, Scan>::frame_step_before(double te) {
  const double ts = le_.next_shift(), th = le_.next_thermostat;
  if (ts < te && ts <= th) {
    shear_shift(ts);
    return true;
  }
  if (th < te) {
    thermostat_step(th);
    return true;
  }
  return false;
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::shear_shift(double ts) {
  s_.now = ts;
  le_.shift();
  const int m = s_.cells.per_side();
  int rest = 1;  // cells per row: m^(D-1) / m along x
  for (int q = 2; q < D; ++q) rest *= m;
  for (const int row : {0, m - 1}) {
    for (int hi = 0; hi < rest; ++hi) {
      for (int c0 = 0; c0 < m; ++c0) {
        const auto cell = static_cast<std::uint32_t>(c0 + m * (row + m * hi));
        for (std::int32_t i = s_.cells.head(cell); i != Cells<D>::none; i = s_.cells.next(i)) {
          s_.advance(static_cast<std::uint32_t>(i));
          predict(static_cast<std::uint32_t>(i));
        }
      }
    }
  }
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::thermostat_step(double th) {
  constexpr int Y = LeesEdwards<D>::y;
  s_.now = th;
  for (std::uint32_t i = 0; i < size(); ++i) s_.advance(i);
  le_.flow_to(th);
  le_.K = kinetic_tensor(s_.now);  // exact, at th
  const double kT = le_.K.trace() / (D * static_cast<double>(size()));
  // heating over the interval just ended, and the target that centres the next one on kT0
  const double zeta = std::log(kT / le_.kT_set) / (2.0 * le_.interval);
  const double target = le_.kT0 * std::exp(-zeta * le_.interval);
  const double lam = std::sqrt(target / kT);
  for (std::uint32_t i = 0; i < size(); ++i) {
    auto v = s_.p.velocity(i);
    const double u = le_.stream(s_.p.position(i)[Y]);
    v *= lam;
    v[0] += (1.0 - lam) * u;  // c -> lam c at fixed u(y)
  }
  le_.removed += (1.0 - lam * lam) * 0.5 * le_.K.trace();
  le_.K *= lam * lam;
  le_.kT_set = target;
  le_.next_thermostat = th + le_.interval;
  rebuild();  // every trajectory changed
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::collide_sheared(std::uint32_t i, std::uint32_t j) {
  constexpr int Y = LeesEdwards<D>::y;
  State<D, F>& s = s_;
  s.advance(i);
  s.advance(j);
  le_.flow_to(s.now);
  const double L = s.L;
  Vec<D> r = s.p.position(i) - s.p.position(j);
  double sv = 0.0;  // x velocity of j's image relative to j
  if (r[Y] > 0.5 * L) {  // j's image above: x_j + (delta, L), v_j + U
    r[Y] -= L, r[0] -= le_.delta(s.now), sv = le_.velocity();
  } else if (r[Y] < -0.5 * L) {
    r[Y] += L, r[0] += le_.delta(s.now), sv = -le_.velocity();
  }
  for (int k = 0; k < D; ++k)
    if (k != 1) r[k] -= L * std::round(r[k] / L);
  const double rn = r.norm();
  const Vec<D> n = r / rn;
  const double wi = s.p.inv_mass(i), wj = s.p.inv_mass(j);
  const Vec<D> vi0 = s.p.velocity(i), vj0 = s.p.velocity(j);
  s.p.velocity(j)[0] += sv;
  if (alpha_ < 1.0) {
    // the energy the collision dissipates, in the frame of the pair (j's image): the
    // balance's own term, computed from lab velocities and not from the sums
    const auto pair_energy = [&] {
      return 0.5 * (s.p.velocity(i).squaredNorm() / wi + s.p.velocity(j).squaredNorm() / wj);
    };
    const double e0 = pair_energy();
    collide_granular(i, j, wi, wj, n);
    le_.dissipated += e0 - pair_energy();
  } else {
    detail::collide_unchecked<D>(s.p.velocity(i), s.p.velocity(j), wi, wj, n);
  }
  s.p.velocity(j)[0] -= sv;
  const Vec<D> dvi = s.p.velocity(i) - vi0, dvj = s.p.velocity(j) - vj0;
  const Vec<D> dp = dvi / wi;
  win_.virial += dp.dot(r);
  le_.W += r * dp.transpose();
  Vec<D> ci = vi0, cj = vj0;  // peculiar velocities before
  ci[0] -= le_.stream(s.p.position(i)[Y]);
  cj[0] -= le_.stream(s.p.position(j)[Y]);
  const Vec<D> ci1 = ci + dvi, cj1 = cj + dvj;
  le_.K += (ci1 * ci1.transpose() - ci * ci.transpose()) / wi +
           (cj1 * cj1.transpose() - cj * cj.transpose()) / wj;
  ++s.cnt[i];
  ++s.cnt[j];
  ++s.ncoll;
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::through_face(std::uint32_t i, int sgn) {
  s_.p.position(i)[0] += sgn * le_.delta(s_.now);
  s_.p.velocity(i)[0] += sgn * le_.velocity();
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::slide(std::uint32_t i, std::array<int, D>& c, int sgn) {
  through_face(i, sgn);
  s_.wrap_axis(i, 0);
  c[0] = s_.cells.coord(s_.p.position(i)[0]);
  ++s_.cnt[i];  // its partners' events are predicted again (lees_edwards.hpp)
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::wrap_sheared(std::uint32_t i) {
  constexpr int Y = LeesEdwards<D>::y;
  State<D, F>& s = s_;
  s.advance(i);
  auto x = s.p.position(i);
  while (x[Y] >= s.L) {
    x[Y] -= s.L, ++s.image[i * D + Y];
    through_face(i, -1);
  }
  while (x[Y] < 0.0) {
    x[Y] += s.L, --s.image[i * D + Y];
    through_face(i, 1);
  }
  if (x[Y] >= s.L) x[Y] = 0.0;  // -tiny + L rounds to L
  s.wrap(i);  // the other axes
}

template <int D, Features F, class Scan>
void Engine<D, F, Scan>::sample_sheared(double ts, Observer& obs) const {
  LeesEdwards<D> le = le_;
  le.flow_to(ts);
  const typename LeesEdwards<D>::Mat K = kinetic_tensor(ts);
  const double e = 0.5 * K.trace();
  const double balance =
      le.E0 - le.rate * (le.Kint(0, LeesEdwards<D>::y) + le.W(LeesEdwards<D>::y, 0)) -
      le.removed - le.dissipated;
  le_.residual = std::max(le_.residual, std::abs(e - balance) / e);
  std::array<double, D * D> S{}, Ki{}, Kr{};
  for (int a = 0; a < D; ++a)
    for (int b = 0; b < D; ++b) {
      S[a * D + b] = le.Kint(a, b) + le.W(a, b);
      Ki[a * D + b] = le.Kint(a, b);
      Kr[a * D + b] = K(a, b);
    }
  const ShearView<D> view{S.data(), Ki.data(), Kr.data(), ts * le.nu0, &le};
  observe_state(s_, ts, obs, nullptr, &win_, &view);
}

}  // namespace hypergas::edmd

// hypergas/edmd/lees_edwards.hpp -- uniform shear flow in EDMD: the Lees–Edwards sliding
// frame, its neighbour scan, and the exact bookkeeping of the pressure tensor and energy.
//
// The flow is u = a (y - L/2) e_x (x the flow axis 0, y the gradient axis 1). The images of
// the box above it (shift +L along y) slide by delta(t) = a L t (mod L) along x and move
// with the extra velocity U = a L e_x; those below by -delta and -U (Lees & Edwards, J.
// Phys. C 5, 1921 (1972)). A particle leaving through the top face enters at the bottom
// displaced by -delta along x with its velocity less U, so its peculiar velocity
// c = v - u(y) is unchanged; through the bottom, the reverse.
//
// Cells (cells.hpp, m >= 4 per side): across the y faces the neighbour columns are offset by
// k = floor(delta / w) cells, and four columns (not three) cover every image within a cell
// width while delta moves by less than a cell (k fixed). When k changes (a "shift", every
// w / (a L) time units) every particle in the top and bottom rows scans again; nothing else
// depends on k, so the scans of the other particles stay valid. Pair events hold for the
// physical pair whatever representation (cnt is still bumped at a face crossing, so partner
// events are re-predicted; this costs scans, not correctness).
//
// Exact rheology bookkeeping, per particle peculiar velocities c_i = v_i - u(y_i):
//   K = sum_i m_i c_i c_i^T     in free flight dc/dt = -a c_y e_x, so with S = I - a s e_x e_y^T
//                               K(s) = S K S^T, and its time integral is a polynomial in s;
//   W = sum_coll r_ij dp_i^T    the collisional transfer (r_ij = x_i - image of x_j);
// the pressure tensor over [t1, t2] is P = (int K dt + W) / (V (t2 - t1)), exact (no
// sampling). Energy: E = tr K / 2 obeys E(t) = E(0) - a (int K_xy dt + W_yx) - (energy the
// thermostat removed) - (energy inelastic collisions dissipated, each measured in the
// frame of its pair), an identity of every trajectory that the engine checks at every
// observation (energy_balance_residual).
//
// Isokinetic thermostat (thermostat_interval > 0): every interval the peculiar velocities
// are scaled by one factor and every event is predicted again. The target alternates about
// T0: scaled to T0 exp(-zeta Delta) with zeta the heating rate of the interval just ended,
// the temperature then rises to ~T0 exp(zeta Delta), so that its geometric mean over an
// interval is T0 up to O((zeta Delta)^2).
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>

#include "hypergas/edmd/events.hpp"
#include "hypergas/edmd/pair_time.hpp"
#include "hypergas/edmd/state.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::edmd {

/// The Lees–Edwards frame and the shear flow's exact sums (see the file comment).
template <int D>
struct LeesEdwards {
  using Mat = Eigen::Matrix<double, D, D>;
  /// The gradient axis y, 1 (0 in 1D, where no flow starts: the code is never run).
  static constexpr int y = D >= 2 ? 1 : 0;

  double rate = 0.0;        ///< a, 1 / time (engine units); 0: no shear
  double L = 0.0;           ///< box side
  double w = 0.0;           ///< cell width
  int m = 0;                ///< cells per side
  int k = 0;                ///< column offset of the images above, floor(delta / w)
  double offset = 0.0;      ///< delta at t_ref (k w after a shift)
  double t_ref = 0.0;
  double t_start = 0.0;     ///< when the shear started
  double kT0 = 1.0;         ///< temperature at the start (the thermostat's target)
  double nu0 = 1.0;         ///< ideal-gas collision frequency at kT0 (time unit of the rate)
  double interval = 0.0;    ///< thermostat interval (0: no thermostat)
  double next_thermostat = never;
  double kT_set = 1.0;      ///< temperature the thermostat set last
  Mat K = Mat::Zero();      ///< sum m c c^T at k_time
  double k_time = 0.0;
  Mat Kint = Mat::Zero();   ///< int K dt since t_start
  Mat W = Mat::Zero();      ///< sum_coll r dp^T since t_start
  double E0 = 0.0;          ///< tr K / 2 at t_start
  double removed = 0.0;     ///< energy the thermostat removed
  double dissipated = 0.0;  ///< energy inelastic collisions took (restitution < 1)
  /// largest |energy balance| / E seen at an observation (mutable: a const observation
  /// records it)
  mutable double residual = 0.0;

  bool on() const { return rate != 0.0; }
  double velocity() const { return rate * L; }  ///< U: speed of the images above
  double delta(double t) const { return offset + rate * L * (t - t_ref); }
  /// Time at which delta reaches (k + 1) w: the next shift.
  double next_shift() const { return t_ref + ((k + 1) * w - offset) / (rate * L); }
  /// Moves the column offset on by one (at next_shift()).
  void shift() {
    t_ref = next_shift();
    ++k;
    if (k == m) k = 0;
    offset = k * w;
  }
  /// Streaming velocity at height y (x component).
  double stream(double y) const { return rate * (y - 0.5 * L); }

  /// Integrates K from k_time to t (free flight of every particle) into Kint.
  void flow_to(double t) {
    const double s = t - k_time;
    if (s == 0.0) return;
    const double a = rate;
    Mat EK = Mat::Zero();  // e_x e_y^T K + K e_y e_x^T
    EK.row(0) += K.row(y);
    EK.col(0) += K.col(y);
    Kint += K * s - (0.5 * a * s * s) * EK;
    Kint(0, 0) += a * a * K(y, y) * s * s * s / 3.0;
    K += -(a * s) * EK;
    K(0, 0) += a * a * K(y, y) * s * s;
    k_time = t;
  }

  template <class Archive>
  void io(Archive& ar) {
    ar.tag("lees-edwards");
    ar(rate, L, w, m, k, offset, t_ref, t_start, kT0, nu0, interval, next_thermostat, kT_set);
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) ar(K(i, j), Kint(i, j), W(i, j));
    ar(k_time, E0, removed, dissipated, residual);
  }
};

/// Ideal-gas (Boltzmann) collision frequency per particle of spheres of unit diameter and
/// mass at packing eta and temperature kT in D dimensions: nu = 2 n pi^((D-1)/2) sqrt(kT) /
/// Gamma(D/2) = D 2^D eta sqrt(kT / pi). The time unit of Config::shear_rate.
inline double ideal_collision_frequency(int D, double eta, double kT) {
  return D * std::pow(2.0, D) * eta * std::sqrt(kT / std::numbers::pi);
}

/// Prediction of i's pair events and crossing under Lees–Edwards boundaries (see the file
/// comment): the 3^D stencil, with four offset columns across the y faces.
template <int D, Features F>
void scan_sheared(State<D, F>& s, const LeesEdwards<D>& le, std::uint32_t i, double sc) {
  s.predict_crossing(i);
  constexpr int Y = D >= 2 ? 1 : 0;  // the gradient axis (no flow in 1D)
  const auto h = s.cells.coords(s.cells.cell_of(i));
  const int m = s.cells.per_side();
  const double L = s.L;
  const double dl = le.delta(s.now);
  const Vec<D> xi = s.p.position(i), vi = s.p.velocity(i);
  Top2 top;
  std::uint64_t pairs = 0;
  // the offsets of axes 2 .. D-1, as an odometer; axes 0 and 1 below
  constexpr int rest = D - 2;
  int ntail = 1;
  for (int q = 0; q < rest; ++q) ntail *= 3;
  for (int oy = -1; oy <= 1; ++oy) {
    int cy = h[Y] + oy;
    int face = 0;
    if (cy >= m) cy -= m, face = 1;
    else if (cy < 0) cy += m, face = -1;
    const int o_lo = face == 1 ? -2 : -1, o_hi = face == -1 ? 2 : 1;
    const int base = face == 1 ? h[0] - le.k : face == -1 ? h[0] + le.k : h[0];
    for (int ox = o_lo; ox <= o_hi; ++ox) {
      const int u = base + ox;
      const int c0 = ((u % m) + m) % m;
      const double sx = face * dl + static_cast<double>((u - c0) / m) * L;
      for (int tq = 0; tq < ntail; ++tq) {
        std::array<int, D> c{};
        Vec<D> shift = Vec<D>::Zero();
        c[0] = c0, shift[0] = sx;
        c[Y] = cy, shift[Y] = face * L;
        int r = tq;
        for (int a = 2; a < D; ++a) {
          int ca = h[a] + r % 3 - 1;
          r /= 3;
          if (ca >= m) ca -= m, shift[a] = L;
          else if (ca < 0) ca += m, shift[a] = -L;
          c[a] = ca;
        }
        const std::uint32_t cell = s.cells.index(c);
        for (std::int32_t j = s.cells.head(cell); j != Cells<D>::none; j = s.cells.next(j)) {
          if (static_cast<std::uint32_t>(j) == i) continue;
          const auto jj = static_cast<std::size_t>(j);
          const Vec<D> r =
              s.p.position(jj) + s.p.velocity(jj) * (s.now - s.p.local_time(jj)) + shift - xi;
          Vec<D> v = s.p.velocity(jj) - vi;
          v[0] += face * le.velocity();
          const double b = s.base_contact(i, jj);
          ++pairs;
          top.offer(contact_time(r.dot(v), v.squaredNorm(), r.squaredNorm(), b * sc, b * s.rate),
                    j);
        }
      }
    }
  }
  s.npairs += pairs;
  ++s.nscan;
  s.store(i, top);
}

}  // namespace hypergas::edmd

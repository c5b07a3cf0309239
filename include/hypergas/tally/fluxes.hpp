// hypergas/tally/fluxes.hpp -- collective fluxes kept by the collisions: the kinetic stress
// and the kinetic energy flux of a one-species gas, exact and O(1) per collision.
//
// For Green-Kubo transport coefficients (analysis/transport_recorder.hpp) the engine keeps
//   S_ab = sum_i v_ia v_ib   (a <= b: D (D + 1) / 2 sums; the kinetic stress over m)
//   Q_a  = sum_i v_ia |v_i|^2 (D sums; twice the energy flux over m, at zero momentum)
// A collision changes two velocities, so it changes each sum by the terms of the two new
// velocities minus those of the two old ones; the engine reports it as it collides
// (exchange(), called through the engine's collision hook), and a sample of the fluxes costs
// O(D^2), not a pass over the particles.
//
// Exactness. Every term is rounded once to a fixed-point integer (unit 2^-36 of the scaled
// velocities u = c v, c a power of two with c^2 kT in [1, 4)) and the integers are added in
// 128 bits, as ExactSum does (exact_sum.hpp): a flux kept collision by collision equals, bit
// for bit, the same flux summed from the current velocities (add()), whatever the order. A
// term is at most |u|^3 < 2^15 for |u|^2 < 1000 (speeds below ~16 sqrt(kT): the fast
// path, 2^51 units, to_units_fast); the rare collision with a faster particle takes the
// general rounding (nearbyint, the same integers). Sums of 2^31 terms of 2^51 units fit in
// 128 bits with room to spare.
//
// Like the moments tally, the fluxes are not part of the engine's state: a checkpoint does
// not hold them, and the analysis that installed them builds them again from a snapshot.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/rng.hpp"
#include "hypergas/tally/exact_sum.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::tally {

class Fluxes {
 public:
  /// Fixed-point units per unit of a term in scaled velocities.
  static constexpr double unit = 0x1p36;

  Fluxes() = default;
  /// Fluxes of a D-dimensional gas whose temperature is about kT (velocity^2 units); the
  /// scale c is the power of two with c^2 kT in [1, 4).
  Fluxes(int dim, double kT) : dim_(dim) {
    if (dim < 1 || dim > 6) throw InvalidInput("fluxes: dimension must be in 1..6");
    if (!(kT > 0.0 && std::isfinite(kT))) throw InvalidInput("fluxes: kT must be finite and > 0");
    while (c_ * c_ * kT < 1.0) c_ *= 2.0;
    while (c_ * c_ * kT >= 4.0) c_ *= 0.5;
    acc_.assign(std::size_t(components()), int128{0});
  }

  int dim() const { return dim_; }
  /// D (D + 1) / 2 stress sums, then D energy-flux sums.
  int components() const { return dim_ * (dim_ + 1) / 2 + dim_; }
  /// Index of S_ab (a <= b) among the components.
  int stress_index(int a, int b) const {
    if (a > b) std::swap(a, b);
    return a * dim_ - a * (a - 1) / 2 + (b - a);
  }
  /// Index of Q_a.
  int heat_index(int a) const { return dim_ * (dim_ + 1) / 2 + a; }

  /// Adds (sign +1) or removes (-1) a particle with velocity v[0..dim).
  void add(const double* v, int sign) {
    std::array<double, 27> t{};
    const int k = terms(v, t.data());
    for (int c = 0; c < k; ++c) add_term(std::size_t(c), t[std::size_t(c)], sign);
  }

  /// A collision: the particles went from oi, oj to ni, nj.
  template <int D>
  [[gnu::always_inline]] void exchange(const double* oi, const double* oj, const double* ni,
                                       const double* nj) {
    constexpr int K = D * (D + 1) / 2 + D;
    std::array<double, K> a, b, c, d;
    // every term is below 2^51 units when every |u|^2 is below 1000 (|u|^3 < 2^15)
    const double s = fill<D>(ni, a.data()), t = fill<D>(nj, b.data());
    const double p = fill<D>(oi, c.data()), q = fill<D>(oj, d.data());
    if ((s < fast_u2) & (t < fast_u2) & (p < fast_u2) & (q < fast_u2)) [[likely]] {
      for (int k = 0; k < K; ++k)
        acc_[std::size_t(k)] += to_units_fast(a[k]) + to_units_fast(b[k]) -
                                to_units_fast(c[k]) - to_units_fast(d[k]);
    } else {
      for (int k = 0; k < K; ++k) {
        add_term(std::size_t(k), a[k], 1), add_term(std::size_t(k), b[k], 1);
        add_term(std::size_t(k), c[k], -1), add_term(std::size_t(k), d[k], -1);
      }
    }
  }

  /// The same fluxes at zero, with no tagged particles: a thread's share of the changes,
  /// added back by merge() (the lanes scheme, dsmc/detail/kac_lanes.hpp).
  Fluxes delta() const {
    Fluxes d;
    d.dim_ = dim_;
    d.c_ = c_;
    d.acc_.assign(acc_.size(), int128{0});
    return d;
  }
  /// Adds the changes `d` kept (a delta() of these fluxes) and sets d to zero. The sums are
  /// integers, so the order of merges does not matter.
  void merge(Fluxes& d) {
    if (d.dim_ != dim_ || d.c_ != c_ || d.acc_.size() != acc_.size())
      throw InvalidInput("fluxes: merge of fluxes of another gas");
    for (std::size_t k = 0; k < acc_.size(); ++k) acc_[k] += d.acc_[k], d.acc_[k] = 0;
  }

  /// Tags particles `idx` (of n) for exact virtual displacements x = int v dt, from zero
  /// now. Every later collision of a tagged particle must be reported by tagged_collision
  /// with its candidate number and every epoch by epoch().
  void tag(const std::vector<std::uint32_t>& idx, std::size_t n, std::uint64_t seed) {
    tag_of_.assign(idx.empty() ? 0 : n, -1);  // none: tagged_collision returns at once
    for (std::size_t a = 0; a < idx.size(); ++a) tag_of_.at(idx[a]) = static_cast<std::int32_t>(a);
    tagged_ = idx;
    x_.assign(idx.size() * std::size_t(dim_), 0.0);
    last_.assign(idx.size(), 0.0);
    rng_ = Rng(seed).split(0x7a9);
    events_.clear();
  }
  std::size_t tagged() const { return tagged_.size(); }
  /// Displacement of tagged particle a, component d, up to the end of the last epoch.
  double displacement(std::size_t a, int d) const { return x_[a * std::size_t(dim_) + std::size_t(d)]; }

  /// Candidate K collided particles i and j, whose velocities were oi, oj before it.
  [[gnu::always_inline]] void tagged_collision(std::uint64_t K, std::uint32_t i, std::uint32_t j,
                                               const double* oi, const double* oj) {
    if (tag_of_.empty()) return;
    const std::int32_t a = tag_of_[i], b = tag_of_[j];
    if (a >= 0) [[unlikely]] record(K, a, oi);
    if (b >= 0) [[unlikely]] record(K, b, oj);
  }

  /// The end of an epoch of the exact scheme (or an NTC step): candidates first ..
  /// first + m - 1 ran in [t0, t1]; with `last_at_end` the m-th is at t1 and the others
  /// are uniform order statistics of m - 1 on [t0, t1] (an epoch stopped at a raise of the
  /// bound), else all m are uniform order statistics on [t0, t1] (dsmc/detail/stepping.hpp).
  /// Draws the times of the tagged particles' collisions from that law (an own random
  /// stream, in order of rank: U_(r) = U_(r') + (1 - U_(r')) Beta(r - r', M - r + 1)) and
  /// integrates their velocities: v (the current velocities, velocity_of(index)) after
  /// the last collision.
  template <class VelocityOf>
  void epoch(double t0, double t1, std::uint64_t first, std::uint64_t m, bool last_at_end,
             VelocityOf&& velocity_of) {
    if (tagged_.empty()) return;
    const double h = t1 - t0;
    const std::uint64_t M = last_at_end ? m - 1 : m;  // the uniform order statistics
    std::uint64_t r_prev = 0;
    double u_prev = 0.0;
    for (const Event& e : events_) {
      const std::uint64_t r = e.K - first + 1;  // rank among the epoch's candidates
      if (r != r_prev) {
        if (last_at_end && r == m) {
          u_prev = 1.0;
        } else {
          std::gamma_distribution<double> ga(static_cast<double>(r - r_prev)),
              gb(static_cast<double>(M - r + 1));
          const double x = ga(rng_), y = gb(rng_);
          u_prev += (1.0 - u_prev) * (x / (x + y));
        }
        r_prev = r;
      }
      double* x = x_.data() + std::size_t(e.tag) * std::size_t(dim_);
      const double w = (u_prev - last_[std::size_t(e.tag)]) * h;
      for (int d = 0; d < dim_; ++d) x[d] += e.v[std::size_t(d)] * w;
      last_[std::size_t(e.tag)] = u_prev;
    }
    events_.clear();
    for (std::size_t a = 0; a < tagged_.size(); ++a) {
      const double* v = velocity_of(tagged_[a]);
      double* x = x_.data() + a * std::size_t(dim_);
      const double w = (1.0 - last_[a]) * h;
      for (int d = 0; d < dim_; ++d) x[d] += v[d] * w;
      last_[a] = 0.0;
    }
  }

  /// Component k in velocity units: S_ab in v^2, Q_a in v^3.
  double value(int k) const {
    const double scaled = static_cast<double>(acc_[std::size_t(k)]) / unit;
    const bool heat = k >= dim_ * (dim_ + 1) / 2;
    return heat ? scaled / (c_ * c_ * c_) : scaled / (c_ * c_);
  }
  /// Whether two flux sets are equal bit for bit.
  /// (the collective fluxes only)
  bool operator==(const Fluxes& o) const {
    return dim_ == o.dim_ && c_ == o.c_ && acc_ == o.acc_;
  }

 private:
  /// |u|^2 below which every term of a velocity takes the fast rounding.
  static constexpr double fast_u2 = 1000.0;

  /// The terms of one velocity, scaled and in fixed-point units (not yet rounded); returns
  /// |u|^2.
  template <int D>
  [[gnu::always_inline]] double fill(const double* v, double* t) const {
    std::array<double, D> u;
    double u2 = 0.0;
    for (int a = 0; a < D; ++a) u[a] = v[a] * c_, u2 += u[a] * u[a];
    int k = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) t[k++] = u[a] * u[b] * unit;
    const double w = u2 * unit;
    for (int a = 0; a < D; ++a) t[k++] = u[a] * w;
    return u2;
  }
  int terms(const double* v, double* t) const {
    for_dim(dim_, [&](auto dim) { fill<decltype(dim)::value>(v, t); });
    return components();
  }
  /// The general path: round(x) to nearest, ties to even (as `units`), into 128 bits.
  void add_term(std::size_t k, double x, int sign) {
    const double r = std::nearbyint(x);
    if (!(std::fabs(r) < 0x1p100))
      throw InvalidInput("fluxes: a speed above 2^20 sqrt(kT) or not finite");
    acc_[k] += sign * static_cast<int128>(r);
  }

  struct Event {
    std::uint64_t K;
    std::int32_t tag;
    std::array<double, 6> v;  // the velocity before the collision
  };
  void record(std::uint64_t K, std::int32_t tag, const double* v) {
    Event e{K, tag, {}};
    for (int d = 0; d < dim_; ++d) e.v[std::size_t(d)] = v[d];
    events_.push_back(e);
  }

  int dim_ = 0;
  double c_ = 1.0;
  std::vector<int128> acc_;
  // tagged particles: index -> tag (-1: none), their displacements and, within the current
  // epoch, the fraction of it their last collision was at; the epoch's collisions so far
  std::vector<std::int32_t> tag_of_;
  std::vector<std::uint32_t> tagged_;
  std::vector<double> x_, last_;
  std::vector<Event> events_;
  Rng rng_{1};
};

}  // namespace hypergas::tally

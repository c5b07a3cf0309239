// hypergas/tally/helfand.hpp -- the collision-level observer of event-driven MD: Helfand
// moments of momentum and energy, and tagged displacements, advanced event by event.
//
// For hard spheres the microscopic fluxes are impulsive. The Helfand moment of the stress,
// G_ab(t) = int_0^t J_ab dt', with J_ab = sum_i m v_ia v_ib + sum_coll dp_ia r_ij,b delta(t -
// t_coll), is therefore
//   G_ab(t) = int_0^t K_ab dt'  +  sum_{collisions before t} dp_ia r_ij,b,
// where K_ab = sum_i m v_ia v_ib is constant between collisions and r_ij = x_i - x_j is the
// contact vector (minimum image: the moment is then that of the flux, with no jump when a
// particle crosses the periodic boundary; Viscardy & Gaspard, Phys. Rev. E 68, 041204
// (2003)). The energy moment is the same with m v_ia v_ib -> v_ia e_i (e_i = m |v_i|^2 / 2)
// and dp_ia -> de_i, the energy i gained. At zero total momentum (the engine's starts) the
// enthalpy term of the heat flux, h sum_i v_i, vanishes.
//
// The tally keeps K and the energy flux E_a = sum_i v_ia e_i, and, for each interval of a
// grid t0 + k dt, the four increments: int K dt, sum dp r, int E dt, sum de r, plus the
// displacements of `tagged` particles (x = int v dt, exact) and, at the interval's end,
// K, E and the tagged velocities (point samples for Green-Kubo). Every collision integrates
// K and E since the previous one (O(D^2)) and closes the grid intervals it passed. All in
// double: an interval's increments sum a few collisions, and K is replaced by a fresh sum
// over the particles whenever the recorder sees a snapshot (reset_kinetic), so no round-off
// accumulates over a run.
//
// Like the DSMC fluxes, the tally is not engine state (a checkpoint does not hold it): the
// recorder that installs it (analysis/helfand_recorder.hpp) builds it from a snapshot.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/tally/tally.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::tally {

class Helfand {
 public:
  /// A tally for a D-dimensional one-species gas (unit mass) of n particles at time t0 with
  /// velocities v (particle i, component a at v[i * stride + a], original numbering),
  /// intervals of length dt from t0, and the particles `tagged` (original ids).
  Helfand(int dim, double t0, double dt, const double* v, std::size_t n, int stride,
          std::vector<std::uint32_t> tagged)
      : dim_(dim), dt_(dt), t_(t0), next_(t0 + dt), t0_(t0), tagged_(std::move(tagged)) {
    if (dim < 1 || dim > 6) throw InvalidInput("helfand: dimension must be in 1..6");
    if (!(dt > 0.0 && std::isfinite(dt) && std::isfinite(t0)))
      throw InvalidInput("helfand: the grid needs a finite start and dt > 0");
    tag_of_.assign(n, -1);
    for (std::size_t a = 0; a < tagged_.size(); ++a)
      tag_of_.at(tagged_[a]) = static_cast<std::int32_t>(a);
    k_.assign(std::size_t(flux_components()), 0.0);
    inc_.assign(std::size_t(record_size()), 0.0);
    vt_.assign(tagged_.size() * std::size_t(dim_), 0.0);
    tt_.assign(tagged_.size(), t0);
    reset_kinetic(v, n, stride, t0);
  }

  int dim() const { return dim_; }
  double dt() const { return dt_; }
  /// S = D (D + 1) / 2 stress components (a <= b) then D energy-flux components.
  int stress_components() const { return dim_ * (dim_ + 1) / 2; }
  int flux_components() const { return stress_components() + dim_; }
  int stress_index(int a, int b) const {
    if (a > b) std::swap(a, b);
    return a * dim_ - a * (a - 1) / 2 + (b - a);
  }
  std::size_t tagged() const { return tagged_.size(); }
  /// Doubles per closed interval: int K dt (S), sum dp r (S), int E dt (D), sum de r (D),
  /// tagged displacements (T D), then at the interval's end K (S), E (D), tagged
  /// velocities (T D).
  int record_size() const {
    return 2 * flux_components() + 2 * int(tagged_.size()) * dim_ + flux_components();
  }
  /// Offsets within a record.
  int kinetic_stress_at() const { return 0; }
  int collisional_stress_at() const { return stress_components(); }
  int kinetic_heat_at() const { return 2 * stress_components(); }
  int collisional_heat_at() const { return 2 * stress_components() + dim_; }
  int displacement_at() const { return 2 * flux_components(); }
  int point_stress_at() const { return displacement_at() + int(tagged_.size()) * dim_; }
  int point_heat_at() const { return point_stress_at() + stress_components(); }
  int point_velocity_at() const { return point_heat_at() + dim_; }

  /// Collisions seen since the start.
  std::uint64_t collisions() const { return ncoll_; }
  /// The start of the grid.
  double start() const { return t0_; }

  /// A collision at time t of particles with original ids a and b: velocities oi, oj
  /// before, ni, nj after; r = x_a - x_b at contact (minimum image).
  template <int D>
  [[gnu::always_inline]] void collision(double t, std::uint32_t a, std::uint32_t b,
                                        const double* oi, const double* oj, const double* ni,
                                        const double* nj, const double* r) {
    if (t >= next_) [[unlikely]] close_until(t);
    integrate<D>(t);
    constexpr int S = D * (D + 1) / 2;
    double* coll = inc_.data();
    const double ei0 = 0.5 * sq<D>(oi), ej0 = 0.5 * sq<D>(oj);
    const double ei1 = 0.5 * sq<D>(ni), ej1 = 0.5 * sq<D>(nj);
    int k = 0;
    for (int x = 0; x < D; ++x)
      for (int y = x; y < D; ++y, ++k) {
        k_[std::size_t(k)] += ni[x] * ni[y] + nj[x] * nj[y] - oi[x] * oi[y] - oj[x] * oj[y];
        coll[S + k] += (ni[x] - oi[x]) * r[y];
      }
    const double de = ei1 - ei0;
    for (int x = 0; x < D; ++x) {
      k_[std::size_t(S + x)] += ni[x] * ei1 + nj[x] * ej1 - oi[x] * ei0 - oj[x] * ej0;
      coll[2 * S + D + x] += de * r[x];
    }
    if (!tagged_.empty()) {
      const std::int32_t ta = tag_of_[a], tb = tag_of_[b];
      if (ta >= 0) [[unlikely]] retag(ta, ni, t);
      if (tb >= 0) [[unlikely]] retag(tb, nj, t);
    }
    ++ncoll_;
  }

  /// Closes every grid interval that ends at or before t (>= the last collision's time).
  void close_until(double t) {
    while (next_ <= t) {
      integrate_runtime(next_);
      push_record();
      next_ = t0_ + dt_ * static_cast<double>(++closed_ + 1);
    }
  }

  /// Replaces K and E by fresh sums over the velocities at time t (after close_until(t);
  /// t >= the last collision's time), and the tagged velocities.
  void reset_kinetic(const double* v, std::size_t n, int stride, double t) {
    integrate_runtime(t);
    std::fill(k_.begin(), k_.end(), 0.0);
    const int S = stress_components();
    for (std::size_t i = 0; i < n; ++i) {
      const double* w = v + i * std::size_t(stride);
      double w2 = 0.0;
      for (int x = 0; x < dim_; ++x) w2 += w[x] * w[x];
      int k = 0;
      for (int x = 0; x < dim_; ++x)
        for (int y = x; y < dim_; ++y) k_[std::size_t(k++)] += w[x] * w[y];
      for (int x = 0; x < dim_; ++x) k_[std::size_t(S + x)] += 0.5 * w[x] * w2;
    }
    for (std::size_t a = 0; a < tagged_.size(); ++a) {
      double* w = &vt_[a * std::size_t(dim_)];
      move_tagged(a, t);
      for (int x = 0; x < dim_; ++x) w[x] = v[tagged_[a] * std::size_t(stride) + std::size_t(x)];
    }
  }

  /// The closed intervals' records since the last clear_records(), oldest first
  /// (record_size() doubles each).
  const std::vector<double>& records() const { return closed_records_; }
  /// Forgets the closed records (keeping the memory, so that the next ones are written
  /// without reallocation).
  void clear_records() { closed_records_.clear(); }
  /// records(), then clear_records() (a copy; for tests).
  std::vector<double> take() {
    std::vector<double> out = closed_records_;
    closed_records_.clear();
    return out;
  }
  /// Current K and E (S + D values).
  const std::vector<double>& kinetic() const { return k_; }

 private:
  template <int D>
  static double sq(const double* v) {
    double s = 0.0;
    for (int x = 0; x < D; ++x) s += v[x] * v[x];
    return s;
  }
  /// Adds K, E and the tagged velocities times (t - t_) to the open interval.
  template <int D>
  [[gnu::always_inline]] void integrate(double t) {
    constexpr int S = D * (D + 1) / 2;
    const double h = t - t_;
    double* in = inc_.data();
    for (int k = 0; k < S; ++k) in[k] += k_[std::size_t(k)] * h;
    for (int x = 0; x < D; ++x) in[2 * S + x] += k_[std::size_t(S + x)] * h;
    t_ = t;
  }
  void integrate_runtime(double t) {
    for_dim(dim_, [&](auto dim) { integrate<decltype(dim)::value>(t); });
  }
  /// Adds tagged particle a's displacement since its last update, up to t, to the open
  /// interval (each tagged particle moves only at its own collisions and at the grid
  /// points, not at every collision).
  void move_tagged(std::size_t a, double t) {
    double* x = inc_.data() + displacement_at() + a * std::size_t(dim_);
    const double* v = &vt_[a * std::size_t(dim_)];
    const double h = t - tt_[a];
    for (int k = 0; k < dim_; ++k) x[k] += v[k] * h;
    tt_[a] = t;
  }
  void retag(std::int32_t a, const double* v, double t) {
    move_tagged(std::size_t(a), t);
    for (int x = 0; x < dim_; ++x) vt_[std::size_t(a) * std::size_t(dim_) + std::size_t(x)] = v[x];
  }
  void push_record() {
    for (std::size_t a = 0; a < tagged_.size(); ++a) move_tagged(a, next_);
    const int S = stress_components();
    double* in = inc_.data();
    for (int k = 0; k < S; ++k) in[point_stress_at() + k] = k_[std::size_t(k)];
    for (int x = 0; x < dim_; ++x) in[point_heat_at() + x] = k_[std::size_t(S + x)];
    std::copy(vt_.begin(), vt_.end(), in + point_velocity_at());
    closed_records_.insert(closed_records_.end(), inc_.begin(), inc_.end());
    std::fill(inc_.begin(), inc_.end(), 0.0);
  }

  int dim_;
  double dt_, t_, next_, t0_;
  std::uint64_t closed_ = 0, ncoll_ = 0;
  std::vector<std::uint32_t> tagged_;
  std::vector<std::int32_t> tag_of_;
  std::vector<double> k_, inc_, vt_, tt_, closed_records_;
};

/// Where the EDMD engine keeps its Helfand tally (Snapshot::contacts): empty unless a
/// recorder asked for one (Requests::helfand); the recorder keeps a share to read it.
struct ContactSlot {
  std::shared_ptr<Helfand> helfand;

  ContactSlot() = default;
  ContactSlot(ContactSlot&&) noexcept = default;
  ContactSlot& operator=(ContactSlot&&) noexcept = default;
  /// A copied engine starts without a tally (the tally is a recorder's, not state).
  ContactSlot(const ContactSlot&) {}
  ContactSlot& operator=(const ContactSlot&) {
    helfand.reset();
    return *this;
  }
  /// Installs the Helfand tally `r` asks for, if any (Requests).
  void apply(Requests& r) {
    if (r.helfand) helfand = std::move(r.helfand);
  }
};

}  // namespace hypergas::tally

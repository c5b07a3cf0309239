// hypergas/tally/tally.hpp -- the collision-level observer: sums over particles that a
// collision updates in O(1).
//
// A Tally holds additive observables of the velocities, A = sum_i a(v_i, species_i): the
// power sums behind moments.csv and the counts of fine speed histograms. A collision
// changes two velocities, so it changes A by a(new_i) + a(new_j) - a(old_i) - a(old_j);
// the engine reports it as it collides (exchange()), and a row of analysis then costs
// O(bins), not a pass over all particles. Every term is rounded once to a fixed-point
// integer (ExactSum, exact_sum.hpp) and histogram counts are integers, so the sums are
// exact and order-independent: the tally an engine keeps equals, bit for bit, one made from
// scratch from the same velocities (add_snapshot), and per-thread tallies merged in any
// order give the same numbers for every thread count.
//
// Units. Velocities are scaled by a power of two, u = c v (c^2 = Layout::c2, chosen so that
// the mean of u^2 is of order D); each term is multiplied by its own power of two
// (Layout::unit) chosen so that a typical term is ~2^40 fixed-point units. A term's
// rounding error is then ~2^-41 of a typical term, and a sum of N terms is accurate to
// ~2^-41 / sqrt(N) relative (random rounding): better than a plain double sum for N > 100.
// Scaling by powers of two is exact, so nothing depends on the velocity unit (|v| from
// 1e-150 to 1e150).
//
// Cost. exchange() only computes |v|^2 and v_x^2 of the four velocities and queues them;
// every `queue_size` entries fold() turns the queue into terms and histogram bins in one
// vectorised loop (AVX2 where the processor has it, SSE2 otherwise: the same numbers bit
// for bit, no fused multiply-adds), away from the candidate loop's dependency chains.
// Readers fold first. A pass over a snapshot (add_snapshot) queues every particle the
// same way.
//
// The layout (units, histogram ranges) is chosen by the analysis that reads the tally
// (analysis::MomentsRecorder) from a snapshot; the engine only applies changes. What an
// engine keeps is not part of its state: a checkpoint does not hold it, and a restored
// engine's first observation builds it again from the velocities.
#pragma once

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/error.hpp"
#include "hypergas/observer.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/tally/exact_sum.hpp"
#include "hypergas/tally/fluxes.hpp"

namespace hypergas::tally {

/// The power sums, in the (dimensionless) scaled velocities u = c v; w = u sqrt(f) is the
/// mass-weighted velocity, f = m / m_mean.
enum Term : int {
  u2,   ///< |u|^2
  u4,   ///< |u|^4
  u6,   ///< |u|^6
  u8,   ///< |u|^8
  u12,  ///< |u|^12
  x2,   ///< w_x^2
  x4,   ///< w_x^4
  x6,   ///< w_x^6
  x8,   ///< w_x^8
  w4,   ///< |w|^4 (= u4 for one unit mass: summed only in weighted layouts)
  w8,   ///< |w|^8 (= u8 for one unit mass: summed only in weighted layouts)
  n_terms
};

/// f = m / m_mean of a particle of inverse mass w: one expression for every path, so that
/// all give the same terms bit for bit.
inline double mass_fraction(double w, double m_mean) { return 1.0 / (w * m_mean); }

/// What a tally sums and in which units; fixed when it is made.
struct Layout {
  int dim = 0;
  /// Species with their own energy sums and speed histograms (1: none; up to max_species).
  int n_species = 1;
  /// Whether masses differ between particles (then w4, w8 and the energies are summed on
  /// their own; else they equal u4, u8 and u2).
  bool weighted = false;
  double c2 = 1.0;  ///< the velocity scale squared, a power of two: u^2 = c2 v^2
  double m_mean = 1.0;  ///< the mean mass f = m / m_mean refers to (mass units)
  /// Inverse mass of each species (1 for one unit-mass species; per-particle masses of a
  /// snapshot are given with each particle instead).
  std::array<double, max_species> inv_mass{1.0, 1.0, 1.0, 1.0};
  std::array<double, n_terms> unit{};  ///< fixed-point units per term (powers of 2)
  double energy_unit = 0.0;            ///< the same for m |u|^2 (every species)
  /// Fine histograms of speeds: the pooled (mass-weighted) speed sqrt(f) |u|, then, with
  /// several species, each species' |u|; `fine` equal bins on [lo, lo + fine / inv_h)
  /// (u units), plus an underflow and an overflow bin.
  std::uint32_t fine = 0;
  std::array<double, 1 + max_species> lo{}, inv_h{};

  int histograms() const { return n_species > 1 ? 1 + n_species : 1; }
  bool operator==(const Layout&) const = default;
};

/// The additive observables of a set of particles (see the file comment).
class Tally {
 public:
  /// Entries (particle velocities) queued per side before a fold.
  static constexpr int queue_size = 256;

  Tally() = default;
  explicit Tally(const Layout& l)
      : layout_(l), counts_(std::size_t(l.histograms()) * (l.fine + 2), 0) {
    derive();
  }

  const Layout& layout() const { return layout_; }

  /// Adds (sign +1) or removes (-1) one particle: velocity v[0..dim), species index
  /// (0 with one species), inverse mass w (mass units^-1).
  template <int Dim>
  void add(const double* v, int species, double w, int sign) {
    push<Dim>(sign > 0, v, species, mass_fraction(w, layout_.m_mean), 1.0 / w);
  }

  /// A collision of particles i (species si) and j (sj): removes their old velocities oi,
  /// oj and adds the new ones ni, nj. Queued (see the file comment).
  /// Weighted must be layout().weighted (the engine knows it at compile time: whether it
  /// has species); an unweighted queue stores |v|^2 and v_x^2 only.
  template <int Dim, bool Weighted>
  [[gnu::always_inline]] void exchange(const double* oi, const double* oj, const double* ni,
                                       const double* nj, int si, int sj) {
    const double fi = f_[std::size_t(si)], fj = f_[std::size_t(sj)];
    const double mi = m_[std::size_t(si)], mj = m_[std::size_t(sj)];
    if (q_[0].n + 2 > queue_size || q_[1].n + 2 > queue_size) fold();
    put<Dim, Weighted>(q_[0], oi, si, fi, mi);
    put<Dim, Weighted>(q_[0], oj, sj, fj, mj);
    put<Dim, Weighted>(q_[1], ni, si, fi, mi);
    put<Dim, Weighted>(q_[1], nj, sj, fj, mj);
  }

  /// Adds particles [begin, end) of a snapshot (its dim must be layout().dim; species
  /// indices below layout().n_species when there are several; f = m / layout().m_mean by
  /// mass_fraction, with the species masses of the layout or each particle's inverse mass).
  void add_snapshot(const Snapshot& s, std::size_t begin, std::size_t end) {
    if (layout_.dim < min_dim || layout_.dim > max_dim) return add_range<0>(s, begin, end);
    for_dim(layout_.dim, [&](auto dim) { add_range<decltype(dim)::value>(s, begin, end); });
  }

  /// Turns the queued entries into sums and counts (readers call it).
  void fold() const;

  /// Adds another tally of the same layout (a thread's changes).
  void merge(const Tally& o) {
    fold();
    o.fold();
    for (int k = 0; k < n_terms; ++k) term_[std::size_t(k)].merge(o.term_[std::size_t(k)]);
    for (int k = 0; k < max_species; ++k) {
      energy_[std::size_t(k)].merge(o.energy_[std::size_t(k)]);
      count_[std::size_t(k)] += o.count_[std::size_t(k)];
    }
    for (std::size_t b = 0; b < counts_.size(); ++b) counts_[b] += o.counts_[b];
  }
  /// Zero sums and counts, the layout kept.
  void clear() {
    q_[0].n = q_[1].n = 0;
    for (auto& x : term_) x.clear();
    for (auto& x : energy_) x.clear();
    count_.fill(0);
    std::fill(counts_.begin(), counts_.end(), 0);
  }

  /// Sum of term k, in units of u^(power of k) (the fixed-point units divided out).
  double term(Term k) const {
    fold();
    const Term src = layout_.weighted ? k : (k == w4 ? u4 : k == w8 ? u8 : k);
    return term_[std::size_t(src)].value() / layout_.unit[std::size_t(src)];
  }
  /// Sum of m |u|^2 over species k (mass u^2 units), or over all particles for k = -1.
  double energy(int k) const;
  /// Particles of species k (all for -1).
  std::int64_t count(int k = -1) const {
    fold();
    if (k >= 0) return count_[std::size_t(k)];
    std::int64_t n = 0;
    for (auto c : count_) n += c;
    return n;
  }
  /// Fine histogram h (0: pooled, 1 + k: species k): fine + 2 counts, underflow first.
  const std::int64_t* counts(int h) const {
    fold();
    return counts_.data() + std::size_t(h) * (layout_.fine + 2);
  }
  /// Whether two tallies hold the same layout and the same sums and counts, bit for bit.
  bool operator==(const Tally& o) const {
    fold();
    o.fold();
    return layout_ == o.layout_ && term_ == o.term_ && energy_ == o.energy_ &&
           count_ == o.count_ && counts_ == o.counts_;
  }

 private:
  /// Queued entries of one side (0: removed, 1: added): |v|^2, v_x^2, f, m, species.
  struct Queue {
    alignas(32) std::array<double, queue_size> vv{}, xx{}, f{}, m{};
    std::array<std::uint8_t, queue_size> sp{};
    int n = 0;
  };

  template <int Dim, bool Weighted>
  [[gnu::always_inline]] static void put(Queue& q, const double* v, int species, double f,
                                         double m) {
    double vv = 0.0;
    for (int d = 0; d < Dim; ++d) vv += v[d] * v[d];
    const auto k = std::size_t(q.n++);
    q.vv[k] = vv;
    q.xx[k] = v[0] * v[0];
    if constexpr (Weighted) {
      q.f[k] = f;
      q.m[k] = m;
      q.sp[k] = static_cast<std::uint8_t>(species);
    }
  }
  template <int Dim>
  void push(bool added, const double* v, int species, double f, double m) {
    Queue& q = q_[added ? 1 : 0];
    if (q.n == queue_size) fold();
    if constexpr (Dim > 0) {
      put<Dim, true>(q, v, species, f, m);
    } else {
      double vv = 0.0;
      for (int d = 0; d < layout_.dim; ++d) vv += v[d] * v[d];
      const auto k = std::size_t(q.n++);
      q.vv[k] = vv;
      q.xx[k] = v[0] * v[0];
      q.f[k] = f;
      q.m[k] = m;
      q.sp[k] = static_cast<std::uint8_t>(species);
    }
  }

  template <int Dim>
  void add_range(const Snapshot& s, std::size_t begin, std::size_t end) {
    const auto stride = static_cast<std::size_t>(s.stride);
    for (std::size_t i = begin; i < end; ++i) {
      const int sp = s.species ? s.species[i] : 0;
      if (s.inv_mass) {
        const double w = s.inv_mass[i];
        push<Dim>(true, s.velocities + i * stride, sp, mass_fraction(w, layout_.m_mean),
                  1.0 / w);
      } else {
        push<Dim>(true, s.velocities + i * stride, sp, f_[std::size_t(sp)],
                  m_[std::size_t(sp)]);
      }
    }
  }

  /// The per-species f and m of the layout, and the |u|^2 below which no term of a
  /// velocity reaches fast_limit (for the u terms; the w and x ones from f |u|^2), with a
  /// margin of a factor 2.
  void derive() {
    for (int k = 0; k < max_species; ++k) {
      const double w = layout_.inv_mass[std::size_t(k)];
      f_[std::size_t(k)] = mass_fraction(w, layout_.m_mean);
      m_[std::size_t(k)] = 1.0 / w;
    }
    const auto below = [&](Term k, double power) {
      const double u = layout_.unit[std::size_t(k)];
      return u > 0.0 ? std::pow(fast_limit / 2.0 / u, 1.0 / power) : 0.0;
    };
    fast_q2_ = std::min({below(u2, 1), below(u4, 2), below(u6, 3), below(u8, 4), below(u12, 6)});
    fast_q2_w_ = std::min({below(x2, 1), below(x4, 2), below(x6, 3), below(x8, 4)});
    if (layout_.weighted) fast_q2_w_ = std::min({fast_q2_w_, below(w4, 2), below(w8, 4)});
  }

 public:
  /// Index into a histogram's counts of a speed (u units) in histogram h: 0 underflow,
  /// 1..fine, fine + 1 overflow.
  std::size_t bin(double s, int h) const {
    const double y = (s - layout_.lo[std::size_t(h)]) * layout_.inv_h[std::size_t(h)];
    if (y < 0.0) return 0;
    if (y >= static_cast<double>(layout_.fine)) return layout_.fine + 1;
    return static_cast<std::size_t>(y) + 1;
  }
  /// fold() for one side's queue; the vectorised and the general path (detail).
  template <bool Fast>
  void fold_side(const Queue& q, int sign) const;

 private:
  Layout layout_;
  std::array<double, max_species> f_{}, m_{};
  double fast_q2_ = 0.0, fast_q2_w_ = 0.0;
  mutable std::array<Queue, 2> q_;
  mutable std::array<ExactSum, n_terms> term_;
  mutable std::array<ExactSum, max_species> energy_;  // m |u|^2 per species (weighted)
  mutable std::array<std::int64_t, max_species> count_{};
  mutable std::vector<std::int64_t> counts_;  // histograms() x (fine + 2)
};

inline double Tally::energy(int k) const {
  if (!layout_.weighted) return k <= 0 ? term(u2) : 0.0;
  fold();
  if (k >= 0) return energy_[std::size_t(k)].value() / layout_.energy_unit;
  ExactSum all;
  for (const auto& e : energy_) all.merge(e);
  return all.value() / layout_.energy_unit;
}

namespace detail {
using v4d = double __attribute__((vector_size(32)));
using v4l = std::int64_t __attribute__((vector_size(32)));
using v4i = std::int32_t __attribute__((vector_size(16)));
}  // namespace detail

/// One side's queue: terms, energies, counts and histogram bins, sign +1 (added) or -1.
/// Fast: every entry is below the fast bounds (the lanes of four entries at a time in
/// 64-bit integers; < 2^51 each, 256 entries: no overflow).
template <bool Fast>
[[gnu::always_inline]] inline void Tally::fold_side(const Queue& q, int sign) const {
  using detail::v4d;
  using detail::v4l;
  using detail::v4i;
  const Layout& L = layout_;
  const int n = q.n;
  const int K = L.weighted ? n_terms : w4;
  std::int64_t* c = counts_.data();
  const std::size_t row = L.fine + 2;
  if constexpr (Fast) {
    constexpr double magic = 0x1.8p52;
    const v4l magic_bits = v4l{} + std::bit_cast<std::int64_t>(magic);
    std::array<v4l, n_terms> acc{};
    alignas(16) std::array<std::int32_t, queue_size> idx;
    const v4d top = v4d{} + static_cast<double>(L.fine);
    for (int e = 0; e < n; e += 4) {
      v4d vv, xx, f = v4d{} + f_[0];
      std::memcpy(&vv, q.vv.data() + e, sizeof vv);  // entries past n: ignored below
      std::memcpy(&xx, q.xx.data() + e, sizeof xx);
      if (L.weighted) std::memcpy(&f, q.f.data() + e, sizeof f);
      if (e + 4 > n) {  // the last partial group: zero terms
        for (int l = n - e; l < 4; ++l) vv[l] = xx[l] = 0.0, f[l] = 1.0;
      }
      const v4d a2 = vv * L.c2, a4 = a2 * a2, a6 = a4 * a2;
      const v4d b2 = xx * L.c2 * f, b4 = b2 * b2;
      const auto put = [&](Term k, const v4d& t) {
        acc[std::size_t(k)] += (v4l)(t * L.unit[std::size_t(k)] + magic) - magic_bits;
      };
      put(u2, a2);
      put(u4, a4);
      put(u6, a6);
      put(u8, a4 * a4);
      put(u12, a6 * a6);
      put(x2, b2);
      put(x4, b4);
      put(x6, b4 * b2);
      put(x8, b4 * b4);
      if (L.weighted) {
        const v4d c4 = a4 * f * f;
        put(w4, c4);
        put(w8, c4 * c4);
      }
      // bin() of the pooled speeds sqrt(f |u|^2)
      const v4d af = a2 * f;
      v4d sp{std::sqrt(af[0]), std::sqrt(af[1]), std::sqrt(af[2]), std::sqrt(af[3])};
      v4d y = (sp - L.lo[0]) * L.inv_h[0];
      y = y < 0.0 ? v4d{} - 1.0 : y;
      y = y < top ? y : top;
      const v4i b = __builtin_convertvector(y, v4i) + 1;
      std::memcpy(idx.data() + e, &b, sizeof b);
    }
    for (int k = 0; k < K; ++k) {
      const v4l a = acc[std::size_t(k)];
      for (int l = 0; l < 4; ++l) term_[std::size_t(k)].add_units(sign * a[l]);
    }
    for (int e = 0; e < n; ++e) c[idx[std::size_t(e)]] += sign;
  } else {
    for (int e = 0; e < n; ++e) {
      const double a2 = q.vv[std::size_t(e)] * L.c2, a4 = a2 * a2, a6 = a4 * a2;
      const double fe = L.weighted ? q.f[std::size_t(e)] : f_[0];
      const double b2 = q.xx[std::size_t(e)] * L.c2 * fe, b4 = b2 * b2;
      std::array<double, n_terms> t{a2, a4, a6, a4 * a4, a6 * a6, b2, b4, b4 * b2, b4 * b4,
                                    0.0, 0.0};
      if (L.weighted) t[w4] = a4 * fe * fe, t[w8] = t[w4] * t[w4];
      for (int k = 0; k < K; ++k)
        term_[std::size_t(k)].add(t[std::size_t(k)] * L.unit[std::size_t(k)], sign);
      c[bin(std::sqrt(a2 * fe), 0)] += sign;
    }
  }
  if (!L.weighted && L.n_species == 1) {  // one unit-mass species: no per-entry work left
    count_[0] += sign * n;
    return;
  }
  std::array<std::int64_t, max_species> cnt{};
  for (int e = 0; e < n; ++e) {
    const std::size_t sp = q.sp[std::size_t(e)];
    ++cnt[sp];
    const double a2 = q.vv[std::size_t(e)] * L.c2;
    if (L.weighted) energy_[sp].add(a2 * q.m[std::size_t(e)] * L.energy_unit, sign);
    if (L.n_species > 1) c[row * (1 + sp) + bin(std::sqrt(a2), 1 + int(sp))] += sign;
  }
  for (int k = 0; k < max_species; ++k) count_[std::size_t(k)] += sign * cnt[std::size_t(k)];
}

inline void Tally::fold() const {
  for (int side = 0; side < 2; ++side) {
    Queue& q = q_[std::size_t(side)];
    if (q.n == 0) continue;
    const int sign = side == 0 ? -1 : 1;
    // entries that may reach fast_limit (rare) take the general path on their own; the
    // last entry takes their place (the sums do not depend on the order)
    bool fast = true;
    for (int e = 0; e < q.n; ++e) {
      const double a = q.vv[std::size_t(e)] * layout_.c2;
      fast &= (a < fast_q2_) & (a * (layout_.weighted ? q.f[std::size_t(e)] : f_[0]) < fast_q2_w_);
    }
    for (int e = 0; !fast && e < q.n;) {
      const auto k = std::size_t(e);
      const double a = q.vv[k] * layout_.c2;
      const double fk = layout_.weighted ? q.f[k] : f_[0];
      if ((a < fast_q2_) & (a * fk < fast_q2_w_)) {
        ++e;
        continue;
      }
      Queue one;
      one.n = 1;
      one.vv[0] = q.vv[k], one.xx[0] = q.xx[k], one.f[0] = q.f[k], one.m[0] = q.m[k];
      one.sp[0] = q.sp[k];
      fold_side<false>(one, sign);
      const auto last = std::size_t(--q.n);
      q.vv[k] = q.vv[last], q.xx[k] = q.xx[last], q.f[k] = q.f[last], q.m[k] = q.m[last];
      q.sp[k] = q.sp[last];
    }
    fold_side<true>(q, sign);
    q.n = 0;
  }
}

class Helfand;  // helfand.hpp

/// What the observers of one snapshot ask the engine to keep from then on
/// (Observer::request), each built from the snapshot it saw. The engine applies the requests
/// after every observer has returned, so a snapshot does not change while it is observed.
/// One observer per item: a second one asking for the same item is an error, not a silent
/// replacement.
struct Requests {
  bool replace_tally = false;        ///< set the engine's tally to `tally` (nullptr: drop it)
  std::unique_ptr<Tally> tally;      ///< moments and histograms (DSMC)
  std::unique_ptr<Fluxes> fluxes;    ///< collective fluxes to install (DSMC transport)
  std::shared_ptr<Helfand> helfand;  ///< a Helfand tally to install (EDMD), shared with its reader

  /// Asks for `t` as the engine's tally (nullptr: keep none).
  void set_tally(std::unique_ptr<Tally> t) {
    if (replace_tally) conflict("tally");
    replace_tally = true;
    tally = std::move(t);
  }
  void set_fluxes(std::unique_ptr<Fluxes> f) {
    if (fluxes) conflict("collective fluxes");
    fluxes = std::move(f);
  }
  void set_helfand(std::shared_ptr<Helfand> h) {
    if (helfand) conflict("Helfand tally");
    helfand = std::move(h);
  }

 private:
  [[noreturn]] static void conflict(const char* what) {
    throw InvalidInput(std::string("two observers of one snapshot ask for the engine's ") +
                       what + "; an engine keeps one");
  }
};

/// Where an engine keeps what an analysis asked it to keep per collision (Snapshot::tally):
/// a tally (moments, histograms) and/or collective fluxes (transport, fluxes.hpp) built from
/// a snapshot's velocities; the engine applies every later collision to them until they are
/// replaced or dropped.
struct Slot {
  std::unique_ptr<Tally> tally;
  std::unique_ptr<Fluxes> fluxes;

  /// Installs what `r` asks for (Requests).
  void apply(Requests& r) {
    if (r.replace_tally) tally = std::move(r.tally);
    if (r.fluxes) fluxes = std::move(r.fluxes);
  }
};

}  // namespace hypergas::tally

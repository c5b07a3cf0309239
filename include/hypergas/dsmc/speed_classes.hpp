// hypergas/dsmc/speed_classes.hpp -- the exact Kac process with per-particle speed-class
// bounds: efficient when a few particles are far faster than the rest.
//
// Usage (same time unit, models and initial states as dsmc/engine.hpp):
//   dsmc::ClassEngine<3, dsmc::HardSpheres> e(cfg);     // cfg.scheme is ignored (exact)
//   e.run_until(1.0);  e.collisions(); e.candidates(); e.acceptance();
//
// Why. The global majorant of dsmc/engine.hpp tests pairs at the rate N c G^a / 2 with
// G = 2 max|v|. One particle at 1e6 times the temperature of the others has a speed 1e3
// times theirs, so almost every candidate (a pair of cold particles, |g| ~ G / 1e3) is
// rejected: the acceptance collapses to ~1e-3 and the cost per collision grows 1e3-fold.
//
// The scheme. Each particle i carries a bound B_i >= |v_i| taken from geometric speed
// classes, B_k = Btop 2^((k - K + 1)/2), k = 0..K-1 (so B_i < sqrt(2) |v_i| unless i is in
// the lowest class); Btop^2 = 2 E max(1/m) (1 + 1e-9) bounds any particle's speed, since no
// particle can hold more than the total energy E. As |g| <= |v_i| + |v_j| and x^a is
// subadditive for 0 <= a <= 1, |g|^a <= (B_i + B_j)^a <= B_i^a + B_j^a. Candidates are
// drawn as ordered pairs: i with probability B_i^a / W (W = sum_i B_i^a), j uniform among
// the N - 1 others, at total rate c W, so the unordered pair {i, j} is a candidate at rate
// c (B_i^a + B_j^a) / (N - 1) and, accepted with probability |g|^a / (B_i^a + B_j^a), collides
// at exactly the Kac rate c |g|^a / (N - 1). W changes only when an accepted collision moves
// a particle to another class; between such changes candidates form a Poisson process of
// constant rate, so exponential waiting times c W give the exact process (no time step).
// A particle is drawn by choosing its class with probability n_k B_k^a / W (a scan over the
// occupied classes, ~10-20), then a uniform member of the class.
//
// Cost per candidate: an exponential variate and the class scan; the acceptance stays ~0.3-
// 0.5 (hard spheres) whatever the spread of speeds. Storage: 9 extra bytes per particle
// (class index, position in its class list, the class list entry).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "hypergas/dsmc/config.hpp"
#include "hypergas/dsmc/models.hpp"
#include "hypergas/dsmc/time_unit.hpp"
#include "hypergas/dsmc/update.hpp"
#include "hypergas/error.hpp"
#include "hypergas/initial_state.hpp"
#include "hypergas/particles.hpp"
#include "hypergas/rng.hpp"

namespace hypergas::dsmc {

/// Exact DSMC (Kac process) with speed-class bounds, dimension D, model `Model` (hard
/// spheres or VHS: a model with a majorant), features F (Features{} or {.species = true}).
/// Time in equilibrium mean collision times (dsmc/time_unit.hpp).
template <int D, class Model, Features F = Features{}>
  requires Dimension<D> && CollisionModel<Model> && (Model::needs_majorant) && (!F.positions) &&
           (!F.masses) && (!F.radii)
class ClassEngine {
 public:
  using ParticlesT = Particles<D, F>;
  /// Number of speed classes; speeds below Btop 2^(-(K-1)/2) share the lowest class.
  static constexpr int K = 96;

  /// Samples cfg.n particles in state cfg.init (as dsmc::Engine). Throws InvalidInput.
  explicit ClassEngine(const Config& cfg) : ClassEngine(cfg, initial(cfg)) {}

  /// Starts from the given particles (velocities with species-0 mass 1, zero momentum).
  ClassEngine(const Config& cfg, ParticlesT particles)
      : cfg_(cfg), p_(std::move(particles)), model_(make_model(cfg)), rng_(Rng(cfg.seed).split(3)) {
    validate(cfg_);
    if (p_.size() < 2 || p_.size() > 0xffffffffULL)
      throw InvalidInput("DSMC: the number of particles must be in [2, 2^32 - 1]");
    n_ = static_cast<std::uint32_t>(p_.size());
    a_ = model_.exponent();
    c_ = dsmc::rate_constant(p_, a_);
    double e2 = 0.0, wmax = 0.0;  // sum m |v|^2 = 2 E, largest inverse mass
    for (std::size_t i = 0; i < p_.size(); ++i) {
      e2 += p_.velocity(i).squaredNorm() / p_.inv_mass(i);
      wmax = std::max(wmax, p_.inv_mass(i));
    }
    const double btop = std::sqrt(e2 * wmax * (1.0 + 1e-9));
    if (!std::isfinite(btop) || !(btop > 0.0))
      throw InvalidInput("DSMC speed classes: the energy must be finite and > 0");
    for (int k = 0; k < K; ++k) {
      // 1e-6 relative margin: covers round-off of |g| and of denormal squared speeds.
      bound_[k] = btop * std::sqrt(std::ldexp(1.0, k - (K - 1))) * (1.0 + 1e-6);
      weight_[k] = a_ == 1.0 ? bound_[k] : std::pow(bound_[k], a_);
    }
    btop2_ = btop * btop;
    cls_.resize(n_);
    pos_.resize(n_);
    for (std::uint32_t i = 0; i < n_; ++i) insert(i, class_of(p_.velocity(i).squaredNorm()));
    recompute_weight();
  }

  /// Advances the exact process to time t (mean collision times).
  void run_until(double t) {
    if (!std::isfinite(t)) throw InvalidInput("DSMC: end time must be finite");
    double* v = p_.velocity_data().data();
    constexpr int S = ParticlesT::stride;
    using Map = Eigen::Map<Vec<D>>;
    while (time_ < t) {
      const double dt = rng_.exponential() / (c_ * total_);
      if (time_ + dt >= t) {  // memoryless: the pending candidate is discarded
        time_ = t;
        break;
      }
      time_ += dt;
      ++candidates_;
      const std::uint32_t i = draw_weighted();
      std::uint32_t j = static_cast<std::uint32_t>(rng_.below(n_ - 1));
      j += (j >= i);
      Map vi(v + std::size_t(i) * S), vj(v + std::size_t(j) * S);
      const Vec<D> g = vi - vj;
      const double g2 = g.squaredNorm();
      const double bsum = weight_[cls_[i]] + weight_[cls_[j]];
      const double u = rng_.uniform();
      if constexpr (Model::kind == ModelKind::hs) {
        if (!(u * u * bsum * bsum < g2)) continue;
      } else {
        if (!(u * bsum < std::pow(g2, 0.5 * a_))) continue;
      }
      const double gn = std::sqrt(g2);
      const Vec<D> delta = Model::template deflect<D>(g, gn, rng_) - g;
      apply_deflection<D>(p_, i, j, vi, vj, delta);  // the shared kernel (update.hpp)
      ++collisions_;
      const bool moved_i = reclass(i, vi.squaredNorm());
      const bool moved_j = reclass(j, vj.squaredNorm());
      if (moved_i || moved_j) recompute_weight();
    }
  }

  /// Current time (mean collision times).
  double time() const { return time_; }
  /// Accepted collisions so far.
  std::uint64_t collisions() const { return collisions_; }
  /// Candidate pairs tested so far.
  std::uint64_t candidates() const { return candidates_; }
  /// collisions / candidates (0 before the first candidate).
  double acceptance() const {
    return candidates_ ? static_cast<double>(collisions_) / static_cast<double>(candidates_) : 0.0;
  }
  /// 2 collisions / N: equals time() on average at equilibrium.
  double collisions_per_particle() const { return 2.0 * static_cast<double>(collisions_) / n_; }
  /// The particles (velocities with species-0 mass 1).
  const ParticlesT& particles() const { return p_; }
  /// Rate constant c (pair rate c |g|^a / (N - 1)), as dsmc::Engine.
  double rate_constant() const { return c_; }
  const Model& model() const { return model_; }
  /// Bytes per particle: particle storage plus the class bookkeeping.
  double bytes_per_particle() const {
    return p_.bytes_per_particle() + sizeof(std::uint8_t) + 2.0 * sizeof(std::uint32_t);
  }
  /// Number of classes that hold at least one particle.
  int occupied_classes() const {
    int k = 0;
    for (const auto& m : members_) k += !m.empty();
    return k;
  }

 private:
  static ParticlesT initial(const Config& cfg) {
    validate(cfg);
    ParticlesT p(cfg.n);
    Rng r = Rng(cfg.seed).split(1);
    initialize_velocities(p, cfg.init, r, cfg.initial);
    return p;
  }
  static Model make_model(const Config& cfg) {
    if constexpr (Model::kind == ModelKind::vhs) return Model(cfg.vhs_exponent);
    else return Model{};
  }

  /// Class of a particle with squared speed v2: the smallest k with v2 <= B_k^2.
  int class_of(double v2) const {
    if (!(v2 > 0.0)) return 0;
    int e;
    std::frexp(v2 / btop2_, &e);  // v2 / btop2 < 2^e
    return std::clamp(e + (K - 1), 0, K - 1);
  }
  void insert(std::uint32_t i, int k) {
    cls_[i] = static_cast<std::uint8_t>(k);
    pos_[i] = static_cast<std::uint32_t>(members_[k].size());
    members_[k].push_back(i);
    lo_ = std::min(lo_, k);
    hi_ = std::max(hi_, k);
  }
  /// Moves particle i to the class of squared speed v2; true if its class changed.
  bool reclass(std::uint32_t i, double v2) {
    const int k = class_of(v2), old = cls_[i];
    if (k == old) return false;
    auto& m = members_[old];
    const std::uint32_t last = m.back();
    m[pos_[i]] = last;
    pos_[last] = pos_[i];
    m.pop_back();
    insert(i, k);
    return true;
  }
  /// W = sum_k n_k B_k^a over the occupied range (exact re-summation, no drift).
  void recompute_weight() {
    while (members_[lo_].empty() && lo_ < hi_) ++lo_;
    while (members_[hi_].empty() && hi_ > lo_) --hi_;
    double w = 0.0;
    for (int k = lo_; k <= hi_; ++k) w += static_cast<double>(members_[k].size()) * weight_[k];
    total_ = w;
  }
  /// A particle drawn with probability B_i^a / W.
  std::uint32_t draw_weighted() {
    double x = rng_.uniform() * total_;
    for (int k = hi_; k > lo_; --k) {
      const double wk = static_cast<double>(members_[k].size()) * weight_[k];
      if (x < wk) return members_[k][rng_.below(members_[k].size())];
      x -= wk;
    }
    return members_[lo_][rng_.below(members_[lo_].size())];
  }

  Config cfg_;
  ParticlesT p_;
  Model model_;
  Rng rng_;
  std::uint32_t n_ = 0;
  double a_ = 1.0, c_ = 0.0, btop2_ = 0.0, total_ = 0.0, time_ = 0.0;
  std::array<double, K> bound_{}, weight_{};
  std::array<std::vector<std::uint32_t>, K> members_;
  std::vector<std::uint8_t> cls_;
  std::vector<std::uint32_t> pos_;
  int lo_ = K - 1, hi_ = 0;
  std::uint64_t collisions_ = 0, candidates_ = 0;
};

}  // namespace hypergas::dsmc

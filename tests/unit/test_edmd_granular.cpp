// Unit tests of the granular (inelastic) EDMD: the inelastic kernel, every collision of an
// engine run checked against the energy-loss formula in D = 1..6 with one and two masses,
// alpha = 1 identical to the elastic engine, the TC model of inelastic collapse, checkpoints,
// the refusals of equilibrium measurements, and Haff's law of homogeneous cooling in 3D.
#include <catch2/catch.hpp>

#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "hypergas/checkpoint.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/restitution.hpp"

using namespace hypergas;
using namespace hypergas::edmd;

namespace {

constexpr double eps = std::numeric_limits<double>::epsilon();
constexpr Features kOne{.positions = true};
constexpr Features kMix{.positions = true, .species = true};

/// Keeps the last snapshot's velocities and unwrapped positions (original numbering).
struct LastState : Observer {
  std::vector<double> v, x;
  void observe(const Snapshot& s) override {
    v.clear(), x.clear();
    for (std::size_t i = 0; i < s.n; ++i)
      for (int k = 0; k < s.dim; ++k) {
        v.push_back(s.velocities[i * s.stride + k]);
        x.push_back(s.positions[i * s.stride + k]);
      }
  }
};

/// A fresh folder under the system temporary folder, removed at scope exit.
struct ScratchDir {
  std::filesystem::path path;
  ScratchDir() {
    std::string p = (std::filesystem::temp_directory_path() / "hypergas_gran_XXXXXX").string();
    REQUIRE(::mkdtemp(p.data()) != nullptr);
    path = p;
  }
  ~ScratchDir() {
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
};

/// A small gas below the lattice capacity (no compression) for the per-collision checks.
Config small_config(int D, double alpha) {
  Config cfg;
  cfg.n = D == 1 ? 40 : (D <= 3 ? 120 : 150);
  cfg.packing = D == 1 ? 0.3 : (D <= 3 ? 0.1 : 0.04);
  cfg.seed = 21;
  cfg.restitution = alpha;
  cfg.tc_time = 0.0;
  cfg.reorder_interval = 0.0;
  return cfg;
}

/// Steps the engine event by event over `K` collisions. At each collision exactly two
/// particles i, j change velocity; from their velocities before, their positions at contact
/// and their masses, the test computes the normal n = (x_i - x_j)/|x_i - x_j| (minimum
/// image), g.n = (v_j - v_i).n and checks: pair momentum conserved to round-off, the
/// velocity changes along n, the pair's kinetic energy drop equal to
/// (1 - alpha^2)/2 mu (g.n)^2 to round-off, and the engine's total kinetic energy drop equal
/// to it. Summed over the run, the formula gives the engine's total loss.
template <int D, Features F>
void per_collision_check(double alpha, bool two_masses, std::uint64_t K) {
  Config cfg = small_config(D, alpha);
  if (two_masses) cfg.initial.mass_ratio = 3.0;
  Engine<D, F> e(cfg);
  REQUIRE(e.diameter_scale() == 1.0);
  REQUIRE(e.restitution() == alpha);
  const std::size_t n = e.size();
  const double L = e.box_side();
  // velocities and masses in the original numbering (the engine renumbers its slots)
  std::vector<Vec<D>> before(n), after(n);
  std::vector<double> mass(n);
  auto read = [&](std::vector<Vec<D>>& v) {
    for (std::size_t s = 0; s < n; ++s) {
      v[e.original_id(s)] = e.particles().velocity(s);
      mass[e.original_id(s)] = e.particles().mass(s);
    }
  };
  const double E_start = e.kinetic_energy();
  double formula_sum = 0.0;
  std::uint64_t unequal = 0;
  while (e.collisions() < K) {
    read(before);
    const double E0 = e.kinetic_energy();
    const std::uint64_t c0 = e.collisions();
    e.step();
    read(after);
    std::vector<std::size_t> moved;
    for (std::size_t a = 0; a < n; ++a)
      if (after[a] != before[a]) moved.push_back(a);
    if (e.collisions() == c0) {
      REQUIRE(moved.empty());  // crossings and stale events change no velocity
      continue;
    }
    REQUIRE(moved.size() == 2);
    const std::size_t i = moved[0], j = moved[1];
    const Vec<D> xi = e.unwrapped_position(i), xj = e.unwrapped_position(j);
    Vec<D> r = xi - xj;
    for (int k = 0; k < D; ++k) r[k] -= L * std::round(r[k] / L);
    REQUIRE(std::abs(r.norm() - 1.0) < 1e-9);  // at contact
    const Vec<D> nrm = r / r.norm();
    // This normal, from unwrapped positions, differs from the engine's (from positions in
    // the box) by round-off of the coordinates' size.
    const double tol_n =
        8 * eps * (std::max(xi.cwiseAbs().maxCoeff(), xj.cwiseAbs().maxCoeff()) + L);
    const double mi = mass[i], mj = mass[j];
    unequal += mi != mj;
    const double mu = mi * mj / (mi + mj);
    const double gn = (before[j] - before[i]).dot(nrm);
    REQUIRE(gn > 0.0);  // approaching
    const double loss = 0.5 * (1.0 - alpha * alpha) * mu * gn * gn;
    REQUIRE(loss == Approx(inelastic_energy_loss(1.0 / mi, 1.0 / mj, gn, alpha))
                        .epsilon(1e-13).margin(1e-300));
    const Vec<D> vi = after[i], vj = after[j];
    const double scale_p = mi * before[i].norm() + mj * before[j].norm();
    INFO("D = " << D << ", collision " << e.collisions() << ", alpha " << alpha);
    REQUIRE((mi * vi + mj * vj - mi * before[i] - mj * before[j]).norm() <= 16 * eps * scale_p);
    const Vec<D> dvi = vi - before[i];
    const double g = (before[j] - before[i]).norm();
    REQUIRE((dvi - dvi.dot(nrm) * nrm).norm() <=
            tol_n * dvi.norm() + 16 * eps * (vi.norm() + before[i].norm() + dvi.norm()));
    // normal relative velocity reversed and scaled by alpha
    REQUIRE((vj - vi).dot(nrm) ==
            Approx(-alpha * gn).margin(2 * tol_n * g + 64 * eps * (vi.norm() + vj.norm() + g)));
    const double Eb = 0.5 * (mi * before[i].squaredNorm() + mj * before[j].squaredNorm());
    const double Ea = 0.5 * (mi * vi.squaredNorm() + mj * vj.squaredNorm());
    const double tol_e = 32 * eps * Eb + 2 * mu * gn * g * tol_n;
    REQUIRE(std::abs((Eb - Ea) - loss) <= tol_e);
    REQUIRE(std::abs((E0 - e.kinetic_energy()) - loss) <= tol_e + 32 * eps * E0);
    formula_sum += loss;
  }
  const double E_end = e.kinetic_energy();
  INFO("D = " << D << ": E " << E_start << " -> " << E_end << ", formula " << formula_sum);
  REQUIRE(E_end < (alpha < 1.0 ? 0.9 : 1.0 + 1e-12) * E_start);  // the gas did cool
  REQUIRE(std::abs((E_start - E_end) - formula_sum) <= 1e-11 * E_start);
  if (two_masses) REQUIRE(unequal > K / 10);
  REQUIRE(e.tc_elastic_collisions() == 0);  // tc_time = 0
  const Vec<D> P = e.momentum();
  REQUIRE(P.norm() <= 1e-12 * std::sqrt(2.0 * E_start * static_cast<double>(n)));
}

}  // namespace

TEST_CASE("inelastic kernel: alpha = 1 is the elastic kernel, alpha < 1 loses the formula",
          "[edmd][granular]") {
  // alpha == 1 calls detail::collide_unchecked itself: identical bits, 1D swap included.
  const Vec<3> n3 = Vec<3>(1.0, 2.0, -0.5).normalized();
  Vec<3> a1(0.3, -1.2, 0.7), a2(-0.4, 0.9, 1.1), b1 = a1, b2 = a2;
  detail::collide_unchecked<3>(a1, a2, 1.0, 0.25, n3);
  collide_inelastic<3>(b1, b2, 1.0, 0.25, n3, 1.0);
  REQUIRE(a1 == b1);
  REQUIRE(a2 == b2);
  Vec<1> u1(0.7), u2(-0.2);
  collide_inelastic<1>(u1, u2, 1.0, 1.0, Vec<1>(1.0), 1.0);
  REQUIRE(u1[0] == -0.2);  // equal masses swap exactly
  REQUIRE(u2[0] == 0.7);
  // 1D, equal masses, alpha < 1: no swap; relative velocity reversed and scaled, both signs
  // of n give the same result.
  for (double s : {1.0, -1.0}) {
    Vec<1> w1(0.7), w2(-0.2);
    collide_inelastic<1>(w1, w2, 1.0, 1.0, Vec<1>(s), 0.5);
    REQUIRE(w1[0] + w2[0] == Approx(0.5).epsilon(1e-15));
    REQUIRE(w2[0] - w1[0] == Approx(0.5 * 0.9).epsilon(1e-14));
  }
  // alpha = 0: equal normal velocities afterwards (3D, masses 1 and 4).
  Vec<3> c1(0.3, -1.2, 0.7), c2(-0.4, 0.9, 1.1);
  collide_inelastic<3>(c1, c2, 1.0, 0.25, n3, 0.0);
  REQUIRE((c2 - c1).dot(n3) == Approx(0.0).margin(1e-15));
  // Parameter checks.
  REQUIRE_NOTHROW(check_restitution(0.0));
  REQUIRE_NOTHROW(check_restitution(1.0));
  REQUIRE_THROWS_AS(check_restitution(1.0 + 1e-15), InvalidInput);
  REQUIRE_THROWS_AS(check_restitution(-0.1), InvalidInput);
  REQUIRE_THROWS_AS(check_restitution(std::nan("")), InvalidInput);
  REQUIRE_NOTHROW(check_tc_time(0.0));
  REQUIRE_THROWS_AS(check_tc_time(-1e-9), InvalidInput);
  REQUIRE_THROWS_AS(check_tc_time(std::numeric_limits<double>::infinity()), InvalidInput);
}

TEST_CASE("the engine refuses a bad restitution or TC time", "[edmd][granular]") {
  Config cfg = small_config(3, 0.8);
  cfg.restitution = 1.5;
  REQUIRE_THROWS_AS(Engine<3>(cfg), InvalidInput);
  cfg.restitution = std::nan("");
  REQUIRE_THROWS_AS(Engine<3>(cfg), InvalidInput);
  cfg.restitution = 0.8;
  cfg.tc_time = -1.0;
  REQUIRE_THROWS_AS(Engine<3>(cfg), InvalidInput);
  cfg.tc_time = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(Engine<3>(cfg), InvalidInput);
  cfg.tc_time = 0.0;
  Engine<3> e(cfg);
  REQUIRE_THROWS_AS(e.set_restitution(-0.5), InvalidInput);
  REQUIRE_THROWS_AS(e.set_tc_time(-0.5), InvalidInput);
  REQUIRE(e.restitution() == 0.8);
}

TEMPLATE_TEST_CASE_SIG("every inelastic collision conserves momentum and loses "
                       "(1 - alpha^2)/2 mu (g.n)^2, one and two masses",
                       "[edmd][granular]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  per_collision_check<D, kOne>(0.8, false, 1500);
  per_collision_check<D, kMix>(0.8, true, 1500);
  per_collision_check<D, kMix>(0.4, true, 600);
}

TEMPLATE_TEST_CASE_SIG("alpha = 0 runs without overlap and conserves momentum",
                       "[edmd][granular]", ((int D), D), 1, 2, 3) {
  // alpha = 0 leaves a pair touching with zero normal relative velocity to round-off; the
  // engine keeps it receding by more than round-off (keep_receding), else the pair would
  // be collided again at the same instant, without end once the change rounds away. The
  // all-pairs overlap check runs after every event. Without TC (tc_time = 0) alpha = 0
  // collapses at once (bursts of collisions at one instant), but the run goes on.
  for (double tc : {0.0, 1e-5}) {
    Config cfg = small_config(D, 0.0);
    cfg.tc_time = tc;
    cfg.debug_overlap = true;
    Engine<D> e(cfg);
    const double E0 = e.kinetic_energy();
    REQUIRE_NOTHROW([&] {
      while (e.collisions() < 3000) e.step();
    }());
    INFO("tc_time " << tc << ": E/E0 = " << e.kinetic_energy() / E0 << " at t = " << e.time());
    REQUIRE(e.time() > 0.5);
    REQUIRE(e.kinetic_energy() < (tc > 0.0 ? 0.1 : 0.5) * E0);
    REQUIRE(e.momentum().norm() <= 1e-12 * std::sqrt(2.0 * E0 * static_cast<double>(cfg.n)));
  }
}

TEMPLATE_TEST_CASE_SIG("restitution 1 gives the default (elastic) trajectories bit for bit",
                       "[edmd][granular]", ((int D), D), 1, 3, 6) {
  // The engine's alpha = 1 branch is the elastic kernel detail::collide_unchecked, called
  // as before the option existed (collide_inelastic with alpha == 1 is that same call); a
  // run with restitution = 1 set explicitly, and one whose restitution was switched to
  // 0.5 and back to 1 before any collision, must equal the default run bit for bit.
  Config def;
  def.n = D == 6 ? 800 : 1000;
  def.packing = D == 6 ? 0.05 : 0.3;
  def.seed = 4;
  def.reorder_interval = 0.5;
  Config one = def;
  one.restitution = 1.0;
  one.tc_time = 3.0;  // ignored while alpha = 1
  Engine<D> a(def), b(one), c(def);
  c.set_restitution(0.5);
  REQUIRE(c.set_restitution(1.0) == 0.5);
  LastState sa, sb, sc;
  double t = 0.0;
  while (a.collisions() < 3 * def.n) a.run_until(t += 0.5);
  a.run_until(t + 0.5, &sa, 1.0);
  b.run_until(t + 0.5, &sb, 1.0);
  c.run_until(t + 0.5, &sc, 1.0);
  REQUIRE(a.collisions() == b.collisions());
  REQUIRE(sa.v == sb.v);
  REQUIRE(sa.x == sb.x);
  REQUIRE(sa.v == sc.v);
  REQUIRE(sa.x == sc.x);
  REQUIRE(b.tc_elastic_collisions() == 0);
  REQUIRE(a.pressure_Z() == b.pressure_Z());
}

TEST_CASE("TC rule: tc_time above every inter-collision time makes the run elastic",
          "[edmd][granular]") {
  // A collision is elastic when either particle collided less than tc_time ago; a
  // particle's first collision after dissipation is switched on has no previous one, so a
  // collision between two particles that have not collided yet is inelastic (at most N/2).
  Config cfg;
  cfg.n = 500;
  cfg.packing = 0.1;
  cfg.seed = 8;
  cfg.restitution = 0.5;
  cfg.tc_time = 1e9;
  Engine<3> e(cfg);
  const double E0 = e.kinetic_energy();
  while (e.collisions() < 20 * cfg.n) e.step();  // ~40 collisions per particle: all collided
  const std::uint64_t c1 = e.collisions(), tc1 = e.tc_elastic_collisions();
  const double E1 = e.kinetic_energy();
  REQUIRE(c1 - tc1 <= cfg.n / 2);
  REQUIRE(c1 - tc1 > 0);
  REQUIRE(E1 < E0);  // the first collisions were inelastic
  e.run_until(e.time() + 20.0);
  const std::uint64_t c2 = e.collisions(), tc2 = e.tc_elastic_collisions();
  REQUIRE(c2 - c1 > 10 * cfg.n);
  REQUIRE(tc2 - tc1 == c2 - c1);  // every later collision elastic by the TC rule
  REQUIRE(std::abs(e.kinetic_energy() - E1) <= 64 * eps * std::sqrt(double(c2 - c1)) * E1);

  // tc_time = 0: the rule never applies, every collision loses energy.
  cfg.tc_time = 0.0;
  Engine<3> f(cfg);
  f.run_until(10.0);
  REQUIRE(f.collisions() > 2 * cfg.n);
  REQUIRE(f.tc_elastic_collisions() == 0);
  REQUIRE(f.kinetic_energy() < 0.5 * E0);
}

namespace {
struct CollapseRun {
  double t = 0.0;               // time reached
  std::uint64_t collisions = 0, tc_elastic = 0;
  std::size_t burst = 0;        // most collisions within any time span of 1e-6
};
/// A dense 2D gas (N = 400, packing 0.4) at alpha = 0.3 with TC time tc, for at most
/// `max_events` events or until t = 20.
CollapseRun collapse_run(double tc, std::uint64_t max_events) {
  Config cfg;
  cfg.n = 400;
  cfg.packing = 0.4;
  cfg.seed = 2;
  cfg.restitution = 0.3;
  cfg.tc_time = tc;
  Engine<2> e(cfg);
  CollapseRun r;
  std::deque<double> recent;  // times of the collisions within 1e-6 of the last one
  for (std::uint64_t k = 0; k < max_events && e.time() < 20.0; ++k) {
    const std::uint64_t c = e.collisions();
    e.step();
    if (e.collisions() == c) continue;
    recent.push_back(e.time());
    while (recent.front() < e.time() - 1e-6) recent.pop_front();
    r.burst = std::max(r.burst, recent.size());
  }
  r.t = e.time();
  r.collisions = e.collisions();
  r.tc_elastic = e.tc_elastic_collisions();
  return r;
}
}  // namespace

TEST_CASE("inelastic collapse: without TC the clock stalls, with TC the run goes on",
          "[edmd][granular]") {
  // At alpha = 0.3 a dense 2D gas collapses: a group of disks collides infinitely often in
  // finite time. Without the TC model the clock nearly stops: thousands of collisions fall
  // within 1e-6 of time (the initial mean free time is ~0.1), until round-off separates
  // the disks (Engine keeps a collided pair receding by at least ~64 eps |v|). With
  // tc_time = 1e-4 the same gas reaches t = 20 with a tenth of the collision rate, no
  // burst, and some collisions made elastic by the rule.
  const CollapseRun no = collapse_run(0.0, 100000);
  const CollapseRun tc = collapse_run(1e-4, 100000);
  INFO("no TC: t = " << no.t << " after " << no.collisions << " collisions, burst "
                     << no.burst << "; TC: t = " << tc.t << " after " << tc.collisions
                     << " collisions, burst " << tc.burst << ", " << tc.tc_elastic
                     << " elastic by the rule");
  REQUIRE(no.burst > 1000);
  REQUIRE(double(no.collisions) / no.t > 5.0 * double(tc.collisions) / tc.t);
  REQUIRE(no.tc_elastic == 0);
  REQUIRE(tc.t >= 20.0);
  REQUIRE(tc.collisions < 50000);
  REQUIRE(tc.burst < 100);
  REQUIRE(tc.tc_elastic > 0);
}

TEST_CASE("a granular engine restored from a checkpoint continues bit for bit",
          "[edmd][granular]") {
  // alpha = 0.7 with a TC time that matters (t_c ~ 0.3 of the mean free time at the start,
  // so the per-particle collision times are state), renumbered every collision per
  // particle (the collision times are permuted with the particles).
  Config cfg;
  cfg.n = 800;
  cfg.packing = 0.2;
  cfg.seed = 12;
  cfg.restitution = 0.7;
  cfg.tc_time = 0.05;
  cfg.reorder_interval = 1.0;
  Engine<3> a(cfg);
  a.run_until(3.0);
  REQUIRE(a.tc_elastic_collisions() > 0);
  ScratchDir dir;
  const std::string file = (dir.path / "granular.hgck").string();
  {
    checkpoint::Writer out(file);
    a.io(out);
    out.commit();
  }
  Config other;  // the checkpoint holds the configuration: restitution and t_c come back
  checkpoint::Reader in(file);
  Engine<3> b(other, in);
  in.finish();
  REQUIRE(b.restitution() == 0.7);
  REQUIRE(b.tc_time() == 0.05);
  REQUIRE(b.config().restitution == 0.7);
  REQUIRE(b.tc_elastic_collisions() == a.tc_elastic_collisions());
  LastState sa, sb;
  a.run_until(8.0, &sa, 5.0);
  b.run_until(8.0, &sb, 5.0);
  REQUIRE(a.collisions() == b.collisions());
  REQUIRE(a.tc_elastic_collisions() == b.tc_elastic_collisions());
  REQUIRE(sa.v == sb.v);
  REQUIRE(sa.x == sb.x);
  // The control: a different t_c changes the trajectory, so the comparison can fail.
  checkpoint::Reader again(file);
  Engine<3> c(other, again);
  c.set_tc_time(0.0);
  LastState sc;
  c.run_until(8.0, &sc, 5.0);
  REQUIRE(sc.v != sa.v);
}

TEST_CASE("renumbering a granular gas leaves every trajectory unchanged", "[edmd][granular]") {
  // The per-particle times of last collision (TC rule) are permuted with the particles by
  // Engine::reorder: with renumbering every 0.5 collisions per particle the run equals the
  // one without, bit for bit. t_c is ~0.3 of the initial mean free time, so that a
  // mismatched time changes which collisions are elastic.
  Config cfg;
  cfg.n = 1000;
  cfg.packing = 0.2;
  cfg.seed = 6;
  cfg.restitution = 0.7;
  cfg.tc_time = 0.05;
  cfg.reorder_interval = 0.0;
  Engine<3> plain(cfg);
  cfg.reorder_interval = 0.5;
  Engine<3> sorted(cfg);
  LastState a, b;
  plain.run_until(6.0, &a, 6.0);
  sorted.run_until(6.0, &b, 6.0);
  REQUIRE(plain.collisions() > 4 * cfg.n);
  REQUIRE(plain.tc_elastic_collisions() > 100);
  REQUIRE(plain.collisions() == sorted.collisions());
  REQUIRE(plain.tc_elastic_collisions() == sorted.tc_elastic_collisions());
  REQUIRE(a.v == b.v);
  REQUIRE(a.x == b.x);
}

TEST_CASE("equilibrium measurements refuse a granular gas; compression stays elastic",
          "[edmd][granular]") {
  // The start needs a compression (lattice gap < 10% of a diameter at packing 0.6): it runs
  // elastically, so its final kinetic temperature is the initial one, and alpha applies
  // from t = 0.
  Config cfg;
  cfg.n = 500;
  cfg.packing = 0.6;
  cfg.seed = 9;
  cfg.restitution = 0.5;
  Engine<3> e(cfg);
  REQUIRE(e.packing() == Approx(0.6).epsilon(1e-12));
  REQUIRE(e.restitution() == 0.5);
  REQUIRE(e.temperature() == Approx(1.0).epsilon(1e-12));
  REQUIRE(e.collisions() == 0);
  e.run_until(0.5);
  REQUIRE(e.temperature() < 0.9);
  REQUIRE_THROWS_AS(e.pressure_Z(), InvalidInput);
  REQUIRE(e.collision_rate() > 0.0);  // a measured mean, still available
  // A compression of a granular engine is elastic too, and gives alpha back.
  Config grow = cfg;
  grow.growth_rate = 0.05;
  const double T0 = e.temperature();
  compress(e, 1.005, grow);
  REQUIRE(e.temperature() == Approx(T0).epsilon(1e-12));
  REQUIRE(e.restitution() == 0.5);
  // The Helfand tally is an equilibrium transport measurement.
  const std::vector<double> v0(cfg.n * 3, 0.0);
  e.contacts().helfand =
      std::make_shared<tally::Helfand>(3, e.time(), 0.1, v0.data(), cfg.n, 3,
                                       std::vector<std::uint32_t>{});
  REQUIRE_THROWS_AS(e.run_until(e.time() + 0.1), InvalidInput);
  REQUIRE_THROWS_AS(e.step(), InvalidInput);
}

TEST_CASE("homogeneous cooling in 3D follows Haff's law", "[edmd][granular]") {
  // For a Maxwellian gas the normal relative speed u of colliding pairs has density
  // ~ u exp(-mu u^2 / (2 kT)), so <u^2> = 2 kT / mu and a collision loses on average
  // (1 - alpha^2)/2 mu <u^2> = (1 - alpha^2) kT, in every D. With N nu / 2 collisions per
  // unit time (nu per particle) and E = N D kT / 2:
  //     d kT / dt = -zeta kT,   zeta = (1 - alpha^2) nu / D,
  // and with nu = nu0 sqrt(T / T0) (nu ~ mean speed at fixed density) Haff's law
  //     T(t) = T0 / (1 + t / t0)^2,   1 / t0 = zeta0 / 2 = (1 - alpha^2) nu0 / (2 D).
  // nu0 is the collision rate the engine measures in an elastic equilibration at T0, so
  // chi(sigma) is not needed. Deviations: the first Sonine coefficient of the homogeneous
  // cooling state, a2 = -0.015 at alpha = 0.9 in 3D, changes zeta / nu by a2 / 4 (~0.4%);
  // nu0 has a statistical error ~1/sqrt(collisions) ~ 0.5%; T(t) of N = 4000 fluctuates by
  // ~1%. The test allows 3% on sqrt(T0 / T) - 1 = t / t0 (and 3% on ln(T) per collision).
  // Dilute (packing 0.01) and L ~ 5 mean free paths: below the clustering instability.
  Config cfg;
  cfg.n = 4000;
  cfg.packing = 0.01;
  cfg.seed = 31;
  const double alpha = 0.9;
  Engine<3> e(cfg);
  e.run_until(60.0);  // forget the lattice (~8 collisions per particle)
  e.reset_observables();
  e.run_until(260.0);
  const double nu0 = e.collision_rate();
  const double T0 = e.temperature();
  e.set_restitution(alpha);
  e.set_tc_time(0.0);
  const double t_start = e.time();
  const std::uint64_t c_start = e.collisions();
  const double inv_t0 = (1.0 - alpha * alpha) * nu0 / (2.0 * 3);
  for (double x : {1.0, 3.0, 9.0}) {  // t / t0 predicted; T falls by 4, 16, 100
    e.run_until(t_start + x / inv_t0);
    const double T = e.temperature();
    const double measured = std::sqrt(T0 / T) - 1.0;
    const double per_particle = 2.0 * double(e.collisions() - c_start) / double(cfg.n);
    // per collision: ln(T/T0) = -(1 - alpha^2) c / D, c collisions per particle
    const double lnT = -(1.0 - alpha * alpha) * per_particle / 3.0;
    INFO("t/t0 = " << x << ": measured " << measured << ", T = " << T << ", ln T/T0 "
                   << std::log(T / T0) << " vs " << lnT << " from " << per_particle
                   << " collisions per particle; nu0 = " << nu0);
    REQUIRE(measured == Approx(x).epsilon(0.03));
    REQUIRE(std::log(T / T0) == Approx(lnT).epsilon(0.03));
  }
}

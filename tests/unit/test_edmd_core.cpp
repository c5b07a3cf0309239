// Unit tests of the EDMD building blocks: the stable contact-time root, the event queue, the
// cell stencil, the lattice, and short runs with the all-pairs overlap check in every D.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

#include "hypergas/edmd/engine.hpp"
#include "hypergas/registry.hpp"

using namespace hypergas;
using namespace hypergas::edmd;

TEST_CASE("contact time: head-on, miss, receding, touching", "[edmd]") {
  // r = (3, 0), v = (-1, 0), sigma = 1: contact after 2.
  REQUIRE(contact_time(-3.0, 1.0, 9.0, 1.0) == Approx(2.0).epsilon(1e-15));
  // receding
  REQUIRE(contact_time(3.0, 1.0, 9.0, 1.0) == never);
  // impact parameter 1.5 > sigma: miss. r = (3, 1.5), v = (-1, 0).
  REQUIRE(contact_time(-3.0, 1.0, 9.0 + 2.25, 1.0) == never);
  // overlapping by round-off while approaching: collide now, never tunnel
  REQUIRE(contact_time(-1.0, 1.0, 1.0 - 1e-15, 1.0) == 0.0);
  REQUIRE(contact_time(1.0, 1.0, 1.0 - 1e-15, 1.0) == never);
}

TEST_CASE("contact time is accurate for nearly touching and nearly grazing pairs", "[edmd]") {
  // Nearly touching: r = (1 + d, 0), v = (-1, 0); exact time d. The textbook root
  // (-b - sqrt(disc)) / v^2 loses all digits of d when d ~ 1e-12; the stable form keeps them.
  for (double d : {1e-6, 1e-10, 1e-13}) {
    const double rx = 1.0 + d;
    const double exact = rx - 1.0;  // d as represented after rounding 1 + d
    REQUIRE(contact_time(-rx, 1.0, rx * rx, 1.0) == Approx(exact).epsilon(1e-9));
  }
  // Nearly grazing: r = (10, y), v = (-1, 0), y = 1 - e; exact time 10 - sqrt(1 - y^2).
  // Grazing is ill-conditioned in the data (r.r = 100 + y^2 carries an absolute error
  // ~ eps 100, so disc = 1 - y^2 does too): the bound is that conditioning, |dt| <=
  // 4 eps b^2 / (2 sqrt(disc)) with b^2 = 100, and the pair must never be reported as missing.
  for (double e : {1e-4, 1e-8, 1e-12}) {
    const double y = 1.0 - e;
    const double disc = (1.0 - y) * (1.0 + y);
    const double exact = 10.0 - std::sqrt(disc);
    const double t = contact_time(-10.0, 1.0, 100.0 + y * y, 1.0);
    const double eps = std::numeric_limits<double>::epsilon();
    REQUIRE(std::abs(t - exact) <= 4.0 * eps * 100.0 / (2.0 * std::sqrt(disc)) + 4 * eps * 10);
  }
  // Growing spheres (LS): r = 3, v = 0, s = 1 growing at a = 1: contact when 3 = 1 + t.
  REQUIRE(contact_time(0.0, 0.0, 9.0, 1.0, 1.0) == Approx(2.0).epsilon(1e-14));
}

TEST_CASE("batched contact times equal contact_time bit for bit", "[edmd]") {
  // contact_times (the scans' branch-free, two-at-a-time form) must give exactly the
  // scalar root: random pairs (approaching, receding, missing, overlapping), with and
  // without growth (Lubachevsky-Stillinger) and at several contact distances, plus the edge
  // cases (touching, exactly grazing, zero relative velocity, odd n for the scalar tail).
  std::mt19937_64 gen(17);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<double> rv, vv, rr;
  for (int c = 0; c < 20001; ++c) {
    const double r0 = u(gen), r1 = u(gen), v0 = u(gen), v1 = u(gen);
    rv.push_back(r0 * v0 + r1 * v1), vv.push_back(v0 * v0 + v1 * v1);
    rr.push_back(r0 * r0 + r1 * r1);
  }
  const double edge[][3] = {{-1.0, 1.0, 1.0}, {1.0, 1.0, 1.0},  {0.0, 0.0, 4.0},
                            {-3.0, 1.0, 10.0}, {-0.0, 0.0, 1.0}, {-1.0, 0.0, 0.5}};
  for (const auto& e : edge) rv.push_back(e[0]), vv.push_back(e[1]), rr.push_back(e[2]);
  const std::size_t n = rv.size();
  std::vector<double> t(n);
  int finite = 0, instant = 0;
  for (double rate : {0.0, 0.05}) {
    for (double sc : {0.9, 1.0, 2.1}) {
      contact_times(n, rv.data(), vv.data(), rr.data(), sc, rate, t.data());
      for (std::size_t c = 0; c < n; ++c) {
        const double ref = contact_time(rv[c], vv[c], rr[c], sc, rate);
        INFO("pair " << c << ": rv " << rv[c] << ", vv " << vv[c] << ", rr " << rr[c]);
        REQUIRE(std::memcmp(&t[c], &ref, sizeof ref) == 0);
        finite += std::isfinite(ref) && ref > 0.0;
        instant += ref == 0.0;
      }
    }
  }
  REQUIRE(finite > 1000);  // the sample holds every case
  REQUIRE(instant > 100);
}

TEST_CASE("calendar queue gives the minimum under EDMD-like updates", "[edmd]") {
  // The EDMD contract: new times are never earlier than the current top. Each step moves
  // the top particle to a later time and re-times a few others (partners, stale events),
  // with leads spread over four decades (so the calendar rebuilds, and the overflow list is
  // used) and some entries "never". Checked against a brute-force minimum every step.
  std::mt19937_64 g(7);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double inf = std::numeric_limits<double>::infinity();
  for (const std::size_t n : {std::size_t(1), std::size_t(2), std::size_t(17), std::size_t(1000)}) {
    std::vector<double> t(n);
    for (auto& x : t) x = u(g) < 0.05 ? inf : std::pow(10.0, 4.0 * u(g) - 2.0);
    CalendarQueue cq;
    cq.build(t);
    for (int k = 0; k < 20000; ++k) {
      const double mn = *std::min_element(t.begin(), t.end());
      REQUIRE(cq.top_time() == mn);
      REQUIRE(t[cq.top()] == mn);
      const double now = std::isfinite(mn) ? mn : 0.0;
      auto retime = [&](std::uint32_t id) {
        const double r = u(g);
        t[id] = r < 0.02 ? inf : now + std::pow(10.0, 4.0 * u(g) - 3.0);
        cq.update(id, t[id]);
      };
      // Others are re-timed before or after the top (before: the cached minimum must
      // follow insertions into the current bucket).
      const bool top_first = g() % 2;
      const auto top = cq.top();
      if (top_first) retime(top);
      const int others = static_cast<int>(g() % 4);
      for (int m = 0; m < others; ++m) {
        retime(static_cast<std::uint32_t>(g() % n));
        REQUIRE(cq.top_time() == *std::min_element(t.begin(), t.end()));
      }
      if (!top_first) retime(top);
    }
  }
  // All entries "never": the top is still a valid particle with time +inf.
  CalendarQueue q;
  q.build(std::vector<double>(5, inf));
  REQUIRE(q.top() < 5);
  REQUIRE(q.top_time() == inf);
  q.update(q.top(), 1.0);
  REQUIRE(q.top_time() == 1.0);
}

TEST_CASE("lattice sites are at least `nearest` apart (periodic)", "[edmd]") {
  Rng rng(3);
  auto check = [&](auto tag) {
    constexpr int D = decltype(tag)::value;
    const double L = 5.3;
    auto s = lattice_sites<D>(100, L, rng);
    double dmin = 1e300;
    for (std::size_t i = 0; i < s.x.size(); ++i)
      for (std::size_t j = i + 1; j < s.x.size(); ++j) {
        Vec<D> r = s.x[i] - s.x[j];
        for (int k = 0; k < D; ++k) r[k] -= L * std::round(r[k] / L);
        dmin = std::min(dmin, r.norm());
      }
    REQUIRE(dmin >= s.nearest * (1 - 1e-12));
  };
  for_each_dim(check);
}

namespace {
/// N that gives a box of side about `side` at packing eta in D dims.
std::size_t n_for_side(int D, double eta, double side) {
  return static_cast<std::size_t>(std::ceil(eta * std::pow(side, D) / ball_volume(D, 1.0)));
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("debug run: no pair ever overlaps, tiny (2 cells) and small boxes",
                       "[edmd]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  // Boxes of side ~2.4 sigma (2 cells per side: all cells neighbours, two images) and
  // ~3.2 sigma (3 cells: 3^D stencil with periodic shifts); the all-pairs check (O(N^2))
  // runs after every event (and at each stage of the Lubachevsky–Stillinger compression
  // from the lattice), and throws on any overlap beyond 1e-9 relative.
  // At most ~250 particles (the check is O(N^2) per event): lower packing in big D.
  for (double side : {2.4, 3.2}) {
    // Tiny boxes start below the lattice capacity (no compression: LS compression of
    // N < 10 spheres in a 2.4-sigma box was seen to stall, see the engine report).
    const double eta0 = D == 1 ? 0.5 : (side < 3 ? 0.15 : 0.4) * jamming_packing(D);
    const double eta = std::min(eta0, 250.0 * ball_volume(D, 1.0) / std::pow(side, D));
    Config cfg;
    cfg.n = std::max<std::size_t>(4, n_for_side(D, eta, side));
    cfg.packing = eta;
    cfg.seed = 11;
    cfg.debug_overlap = true;
    cfg.max_compression_collisions = 2000000;  // a tiny box may jam below the bulk value
    Engine<D> e(cfg);
    INFO("D = " << D << ", n = " << cfg.n << ", cells per side " << e.cells_per_side());
    // D <= 2: N >= 4 rules the box size; D = 6: the cell cap (2 per particle) gives 2 cells.
    if (D >= 3 && D <= 5) REQUIRE(e.cells_per_side() == (side < 3 ? 1 : 3));  // < 3 cells: one cell, all images
    const double E0 = e.kinetic_energy();
    const std::uint64_t target = e.collisions() + 2000;
    REQUIRE_NOTHROW([&] {
      while (e.collisions() < target) e.step();
    }());
    REQUIRE(std::abs(e.kinetic_energy() - E0) <= 1e-12 * E0);
  }
}

namespace {
template <int D>
void conservation_run(std::uint64_t K) {
  // Round-off per collision is a few eps in each velocity; its random walk over K
  // collisions stays below 64 eps sqrt(K) (relative), which is the bound asserted.
  Config cfg;
  cfg.n = D <= 4 ? 2000 : 4000;  // D = 5, 6: dilute, so the box has >= 4 cells per side
  cfg.packing = D == 1 ? 0.5 : (D <= 4 ? 0.5 * jamming_packing(D) : 0.05);
  cfg.seed = 3;
  Engine<D> e(cfg);
  const double E0 = e.kinetic_energy();
  const Vec<D> P0 = e.momentum();
  const std::uint64_t c0 = e.collisions();
  while (e.collisions() - c0 < K) e.step();
  const double eps = std::numeric_limits<double>::epsilon();
  const double bound = 64.0 * eps * std::sqrt(static_cast<double>(K));
  INFO("D = " << D << ": dE/E = " << (e.kinetic_energy() - E0) / E0
              << ", |dP| = " << (e.momentum() - P0).norm());
  REQUIRE(std::abs(e.kinetic_energy() - E0) <= bound * E0);
  REQUIRE((e.momentum() - P0).norm() <= bound * std::sqrt(2.0 * E0 * cfg.n));
  REQUIRE(e.bytes_per_particle() < 300.0);
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("energy to round-off and momentum conserved over 1e5 collisions",
                       "[edmd]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  conservation_run<D>(100000);
}

TEMPLATE_TEST_CASE_SIG("energy and momentum conserved over 1e6 collisions", "[edmd][long]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  conservation_run<D>(1000000);
}

namespace {
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
}  // namespace

namespace {
template <int D, class Scan>
void renumbering_check() {
  // Engine::reorder permutes all per-particle arrays in Z-order of the cells and re-maps
  // event partners; it advances nothing, so the run with a renumbering every 0.5
  // collisions per particle must match the run without any renumbering bit for bit, in
  // the original numbering of the snapshots. A wrong partner re-map, a lost event or a
  // snapshot in memory order instead of original order breaks the equality.
  Config cfg;
  cfg.n = D == 6 ? 800 : 1500;
  cfg.packing = D == 6 ? 0.05 : 0.3 * jamming_packing(D);
  cfg.seed = 5;
  cfg.reorder_interval = 0.0;
  Engine<D, Features{.positions = true}, Scan> plain(cfg);
  cfg.reorder_interval = 0.5;
  Engine<D, Features{.positions = true}, Scan> sorted(cfg);
  LastState a, b;
  double t = 0.0;
  while (plain.collisions() < 3 * cfg.n) plain.run_until(t += 0.25);
  plain.run_until(t + 0.25, &a, 1.0);  // snapshots at both ends (one interval); a keeps the last
  sorted.run_until(t);
  sorted.run_until(t + 0.25, &b, 1.0);
  REQUIRE(plain.collisions() == sorted.collisions());
  REQUIRE(sorted.collisions() > 3 * cfg.n);  // renumbered every n/4 collisions: > 12 times
  REQUIRE(a.v == b.v);
  REQUIRE(a.x == b.x);
  bool moved = false;  // the renumbering did move particles in memory
  for (std::size_t i = 0; i < cfg.n; ++i) moved = moved || sorted.original_id(i) != i;
  REQUIRE(moved);
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("renumbering particles by position leaves every trajectory unchanged",
                       "[edmd]", ((int D), D), 2, 3, 6) {
  renumbering_check<D, AutoScan<D>>();
  // the lists are renamed and their rows moved (6D: this box is one list cell, not renumbered)
  if constexpr (D <= 3) renumbering_check<D, ListScan>();
}

TEST_CASE("the automatic scan policy is slab in D <= 2, horizon in 3D, filtered from 4D",
          "[edmd]") {
  STATIC_REQUIRE(std::is_same_v<AutoScan<1>, SlabScan>);
  STATIC_REQUIRE(std::is_same_v<AutoScan<2>, SlabScan>);
  STATIC_REQUIRE(std::is_same_v<AutoScan<3>, HorizonScan>);
  STATIC_REQUIRE(std::is_same_v<AutoScan<4>, FilteredScan>);
  STATIC_REQUIRE(std::is_same_v<AutoScan<6>, FilteredScan>);
  STATIC_REQUIRE(Engine<2>::scan_name == "slab");
  STATIC_REQUIRE(Engine<3>::scan_name == "horizon");
  STATIC_REQUIRE(Engine<5>::scan_name == "filtered");
}

TEST_CASE("the automatic scan follows the density: lists from packing 0.43 in 3D only",
          "[edmd]") {
  STATIC_REQUIRE(std::is_same_v<DenseScan<3>, ListScan>);
  STATIC_REQUIRE(std::is_same_v<DenseScan<2>, AutoScan<2>>);
  STATIC_REQUIRE(std::is_same_v<DenseScan<6>, AutoScan<6>>);
  REQUIRE(registry::regime(3, 0.45).index == 1);
  REQUIRE(registry::regime(3, 0.2618).index == 0);
  REQUIRE(registry::regime(6, 0.45).index == 0);
  using Dense = registry::RegimeScan<std::true_type, 3>;
  STATIC_REQUIRE(std::is_same_v<Dense, ListScan>);
}

TEST_CASE("lists through a compression and a dense crystal: no overlap, energy to round-off",
          "[edmd]") {
  // 3D fcc at packing 0.6: the lattice gap is below 10% of a diameter, so the engine starts
  // from 0.9 of it and grows the diameters back (Lubachevsky-Stillinger), with the lists
  // made for the growing diameters (listing distance = cell width); the all-pairs overlap
  // check runs at each compression stage and then after every event.
  Config cfg;
  cfg.n = 500;
  cfg.packing = 0.6;
  cfg.seed = 9;
  cfg.debug_overlap = true;
  Engine<3, Features{.positions = true}, ListScan> e(cfg);
  REQUIRE(e.cells_per_side() >= 3);
  REQUIRE(e.packing() == Approx(0.6).epsilon(1e-12));
  const double E0 = e.kinetic_energy();
  const std::uint64_t x0 = e.crossings(), target = e.collisions() + 5000;
  REQUIRE_NOTHROW([&] {
    while (e.collisions() < target) e.step();
  }());
  REQUIRE(e.crossings() > x0);  // lists were renewed in the run
  REQUIRE(std::abs(e.kinetic_energy() - E0) <= 1e-12 * E0);
}

TEST_CASE("run_until rejects a past or non-finite time and a bad sampling interval",
          "[edmd]") {
  // Observed at t0 + k every while <= t, and time() == t afterwards.
  struct Times : Observer {
    std::vector<double> t;
    void observe(const Snapshot& s) override { t.push_back(s.time); }
  } obs;
  Config cfg;
  cfg.n = 200;
  cfg.packing = 0.1;
  Engine<3> e(cfg);
  e.run_until(0.5);
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  REQUIRE_THROWS_AS(e.run_until(0.25), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(inf), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(nan), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(1.0, &obs, 0.0), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(1.0, &obs, inf), InvalidInput);
  REQUIRE_THROWS_AS(e.run_until(1.0, &obs, nan), InvalidInput);
  REQUIRE(obs.t.empty());
  REQUIRE(e.time() == 0.5);
  e.run_until(1.0, &obs, 0.125);
  REQUIRE(e.time() == 1.0);
  REQUIRE(obs.t == std::vector<double>{0.5, 0.625, 0.75, 0.875, 1.0});
  e.run_until(1.0, nullptr, nan);  // no observer: `every` is not used
  REQUIRE(e.time() == 1.0);
}

TEMPLATE_TEST_CASE_SIG("horizon, filtered, list and slab scans give the same collisions",
                       "[edmd]", ((int D), D), 2, 3, 4, 5, 6) {
  // The horizon scan (HorizonScan, scan.hpp) skips stencil cells that cannot hold a
  // partner before the particle's next crossing, the filtered scan also skips particles
  // whose path boxes are too far, the list scan tests only the particles listed near the
  // particle and renews its list as an event; the slab scan skips nothing. All must find every collision, so from the
  // same start they run the same trajectory, apart from round-off (scans at different
  // times compute a pair time from positions advanced differently): after one collision
  // per particle that difference is ~1e-14, far below the 1e-8 asserted, while one missed
  // or spurious collision changes the count and moves particles by O(1). The first case is
  // large enough for a real stencil (>= 5 cells per side, where the path-box filter works);
  // the second repeats a short run with the all-pairs overlap check after every event.
  for (const bool check : {false, true}) {
    Config cfg;
    // 5 cells per side in the filtered run (at most 1.5 cells per particle there)
    cfg.n = check ? 300 : (D == 6 ? 10500 : D == 5 ? 2100 : 2000);
    // Lattice starts without Lubachevsky-Stillinger compression (in 6D, eta = 0.05 at
    // N = 4000 needs one, whose own chaotic run would already separate the two starts).
    cfg.packing = D == 6 ? (check ? 0.01 : 0.03) : 0.3 * jamming_packing(D);
    cfg.seed = 21;
    cfg.debug_overlap = check;
    Engine<D, Features{.positions = true}, SlabScan> slab(cfg);
    Engine<D, Features{.positions = true}, HorizonScan> horizon(cfg);
    Engine<D, Features{.positions = true}, FilteredScan> filtered(cfg);
    Engine<D, Features{.positions = true}, ListScan> lists(cfg);
    REQUIRE(slab.scan_name == "slab");
    REQUIRE(lists.scan_name == "lists");
    REQUIRE(horizon.scan_name == "horizon");
    REQUIRE(filtered.scan_name == "filtered");
    INFO("D = " << D << ", n = " << cfg.n << ", cells per side " << slab.cells_per_side()
                << " (filtered: " << filtered.cells_per_side() << ")");
    REQUIRE(slab.cells_per_side() >= 3);
    if (!check) REQUIRE(filtered.cells_per_side() >= 5);
    LastState a, b, c, d;
    double tau = 0.0;
    while (slab.collisions() < 2 * cfg.n) slab.run_until(tau += 0.05);  // ~4 per particle
    slab.run_until(tau + 0.01, &a, 1.0);
    horizon.run_until(tau);
    horizon.run_until(tau + 0.01, &b, 1.0);
    filtered.run_until(tau);
    filtered.run_until(tau + 0.01, &c, 1.0);
    lists.run_until(tau);
    lists.run_until(tau + 0.01, &d, 1.0);
    REQUIRE(slab.collisions() == horizon.collisions());
    REQUIRE(slab.collisions() == filtered.collisions());
    REQUIRE(slab.collisions() == lists.collisions());
    // the lists were renewed (each renewal is a crossing event): ~0.3-0.5 per collision
    if (lists.cells_per_side() >= 3) REQUIRE(lists.crossings() > slab.collisions() / 10);
    REQUIRE(a.x.size() == b.x.size());
    REQUIRE(a.x.size() == c.x.size());
    REQUIRE(a.x.size() == d.x.size());
    double dmax = 0.0;
    for (std::size_t k = 0; k < a.x.size(); ++k)
      dmax = std::max({dmax, std::abs(a.x[k] - b.x[k]) + std::abs(a.v[k] - b.v[k]),
                       std::abs(a.x[k] - c.x[k]) + std::abs(a.v[k] - c.v[k]),
                       std::abs(a.x[k] - d.x[k]) + std::abs(a.v[k] - d.v[k])});
    INFO("largest position + velocity difference " << dmax);
    REQUIRE(dmax < 1e-8);
    // the horizon scan did skip pairs, and the filter skipped more where it works (>= 5
    // cells per side): 0.76 of the horizon scan's pairs in 2D, 0.3 or less in D >= 4
    REQUIRE(horizon.pairs_tested() < slab.pairs_tested());
    if (filtered.cells_per_side() >= 5) {
      INFO("pairs tested: horizon " << horizon.pairs_tested() << ", filtered "
                                    << filtered.pairs_tested());
      REQUIRE(filtered.pairs_tested() < (D >= 4 ? 0.5 : 1.0) * horizon.pairs_tested());
    }
  }
}

// Uniform shear flow in EDMD under Lees–Edwards boundaries (edmd/lees_edwards.hpp).
//
//  * The sliding face: two spheres that meet only through the face collide exactly once,
//    with the elastic rule applied to the image's velocity, before and after the sliding
//    columns shift (ESPResSo's first Lees–Edwards code counted such pairs twice,
//    espressomd/espresso #2051).
//  * No overlap, D = 2..6, at a high shear rate: every column shift and face crossing of
//    thousands is exercised, and an all-pairs check with the sliding images runs every
//    0.1 mean collision times (a missed collision leaves an overlap for ~1/|g| ~ 0.5 time
//    units, 0.05-2 mean collision times at these packings).
//  * The energy balance E(t) = E(0) - a (int K_xy dt + W_yx) (- the thermostat's share, -
//    the inelastic collisions' loss in their pairs' frames) is an identity of every
//    trajectory: round-off only (1e-10 allows 1e6 collisions).
//  * The isokinetic thermostat holds the interval-mean temperature at T0 to O((zeta dt)^2).
//  * The rheology of the dilute gas against the DSMC engine's Boltzmann hard spheres: the
//    [long] case (docs/validation.md, "Uniform shear flow", the two-engine table).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/analysis/pressure_tensor_recorder.hpp"
#include "hypergas/edmd/engine.hpp"

using namespace hypergas;
using namespace hypergas::edmd;

namespace {

/// Runs to `until`, checking all pairs for overlap every `every` time units.
template <int D>
void run_checked(Engine<D>& e, double until, double every) {
  while (e.time() < until) {
    e.run_until(std::min(until, e.time() + every));
    REQUIRE_NOTHROW(e.check_overlaps());
  }
}

template <int D>
void no_overlap(std::size_t n, double eta, double a, double thermostat, double until,
                double alpha = 1.0) {
  Config c;
  c.restitution = alpha;
  c.n = n;
  c.packing = eta;
  c.seed = 11 + D;
  c.shear_rate = a;
  c.thermostat_interval = thermostat;
  Engine<D> e(c);
  REQUIRE(e.cells_per_side() >= 4);
  const LeesEdwards<D>& le = e.lees_edwards();
  const double shift_time = le.w / le.velocity();
  run_checked(e, until / le.nu0, 0.1 / le.nu0);
  INFO("D = " << D << ", " << e.collisions() << " collisions, shift every " << shift_time);
  CHECK(e.collisions() > n);
  // at least 10 shifts of the sliding columns happened
  CHECK(e.time() > 10 * shift_time);
  CHECK(e.energy_balance_residual() < 1e-10);
}

}  // namespace

TEST_CASE("Lees-Edwards face: a pair meeting through the face collides once", "[edmd][shear]") {
  // 2D box of side 12 (8 cells per side): particle 0 at height L - 0.7 - s moving up,
  // particle 1 at 0.7 + s moving down; they meet only as images across the y face, where
  // the image of 1 above is at x1 + delta(t) + (v1x + U) t. Cases: s = 0 with the image
  // straight above (contact at delta ~ 0.2, column offset k = 0) and beside it, and s = 2
  // with x1 aimed so that they meet at t ~ 2.2, after delta passed a cell width (k = 1).
  const double L = 12.0;
  struct Case {
    double s, aim;
  };
  for (const Case cs : {Case{0.0, 0.0}, Case{0.0, 0.3}, Case{2.0, 0.2}}) {
    const double y0 = L - 0.7 - cs.s, y1 = 0.7 + cs.s, gap = y1 + L - y0;
    Config c;
    c.n = 2;
    c.packing = packing_fraction(2, 2, L);
    c.shear_rate = 2.0;
    // the unit: the ideal-gas collision frequency at the start's kT0 = (1 + 1) / (D N) = 0.5
    const double rate = c.shear_rate * ideal_collision_frequency(2, c.packing, 0.5);
    // relative x velocity of the image: v1x + a L - v0x = a (y1 - y0 + L)
    const double ux = rate * gap;
    const double dx0 = cs.s > 0.0 ? cs.aim - ux * (cs.s + 0.2) : cs.aim;
    std::vector<double> x{6.0, y0, 6.0 + dx0, y1};
    std::vector<double> v{0.0, 1.0, 0.0, -1.0};  // peculiar; the flow is added at the start
    GivenState g;
    g.positions = x.data(), g.velocities = v.data(), g.n = 2, g.box = L;
    Engine<2> e(c, g);
    const LeesEdwards<2>& le = e.lees_edwards();
    REQUIRE(e.cells_per_side() >= 4);
    REQUIRE(le.rate == Approx(rate).epsilon(1e-14));
    // contact: (dx0 + ux t)^2 + (gap - 2t)^2 = 1, the smaller root
    const double A = ux * ux + 4.0, B = 2.0 * dx0 * ux - 4.0 * gap,
                 C = dx0 * dx0 + gap * gap - 1.0;
    REQUIRE(B * B - 4.0 * A * C > 0.0);
    const double tc = (-B - std::sqrt(B * B - 4.0 * A * C)) / (2.0 * A);
    INFO("s = " << cs.s << ", contact at t = " << tc << ", delta = " << le.delta(tc)
                << ", cell width " << le.w);
    if (cs.s > 0.0) CHECK(le.delta(tc) > le.w);  // the columns have shifted
    e.run_until(0.5 * tc);
    REQUIRE(e.collisions() == 0);
    e.run_until(tc + 3.0);
    CHECK(e.collisions() == 1);
    // the elastic rule in the image frame: the normal relative velocity is reversed
    const double nx = -(dx0 + ux * tc), ny = -(gap - 2.0 * tc);  // 0 minus the image
    const double un = -ux * nx + 2.0 * ny;                         // (v0 - v_img) . n < 0
    REQUIRE(un < 0.0);
    const auto& p = e.particles();
    const std::size_t i0 = e.original_id(0) == 0 ? 0 : 1, i1 = 1 - i0;
    const double v0x = rate * (y0 - 0.5 * L);
    CHECK(p.velocity(i0)[1] == Approx(1.0 - un * ny).epsilon(1e-12));
    CHECK(p.velocity(i1)[1] == Approx(-1.0 + un * ny).epsilon(1e-12));
    CHECK(p.velocity(i0)[0] == Approx(v0x - un * nx).epsilon(1e-12));
    CHECK(e.energy_balance_residual() < 1e-12);
  }
}

TEST_CASE("Lees-Edwards: no overlap and an exact energy balance, D = 2..6", "[edmd][shear]") {
  no_overlap<2>(400, 0.02, 2.0, 0.0, 15.0);
  no_overlap<3>(600, 0.02, 2.0, 0.1, 10.0);
  no_overlap<4>(600, 0.02, 2.0, 0.0, 6.0, 0.8);  // granular: the balance's dissipated term
  no_overlap<5>(1100, 0.02, 1.5, 0.1, 4.0);
  no_overlap<6>(2800, 0.02, 2.0, 0.0, 2.0);
}

TEST_CASE("Lees-Edwards: the isokinetic thermostat holds T0 on average", "[edmd][shear]") {
  // 3D, a = 1 per mean collision time: the gas heats at 2 zeta ~ 0.3 per mean collision
  // time; the interval-mean temperature from the exact kinetic integral stays at T0 within
  // 1e-3 (the bias is (zeta dt)^2 / 6 ~ 4e-5; the rows' T fluctuates by ~1e-3 / sqrt(rows))
  Config c;
  c.n = 4000;
  c.packing = 0.01;
  c.seed = 5;
  c.shear_rate = 1.0;
  c.thermostat_interval = 0.1;
  Engine<3> e(c);
  const double nu0 = e.lees_edwards().nu0;
  analysis::PressureTensorRecorder rec(3, c.shear_rate, 1.0);
  e.run_until(30.0 / nu0, &rec, 0.5 / nu0);
  double s = 0.0;
  int k = 0;
  for (std::size_t r = 1; r < rec.rows().size(); ++r, ++k) s += rec.rows()[r][2];
  CHECK(s / k == Approx(1.0).margin(1e-3));
  CHECK(e.energy_balance_residual() < 1e-10);
  // the gas did heat between rescalings: without the thermostat T would be e^(2 zeta t)
  CHECK(e.lees_edwards().removed > 1.0 * e.lees_edwards().E0);
}

TEST_CASE("Lees-Edwards: refusals", "[edmd][shear]") {
  Config c;
  c.n = 30;
  c.packing = 0.3;  // 3D: 3 cells per side, too few for the sliding stencil
  c.shear_rate = 1.0;
  CHECK_THROWS_AS(Engine<3>(c), InvalidInput);
  c.packing = 0.01;
  c.shear_rate = -1.0;
  CHECK_THROWS_AS(Engine<3>(c), InvalidInput);
  c.shear_rate = 0.0;
  c.thermostat_interval = 0.1;
  CHECK_THROWS_AS(Engine<3>(c), InvalidInput);
  c.shear_rate = 1.0;
  c.restitution = 0.9;
  CHECK_THROWS_AS(Engine<3>(c), InvalidInput);
  c.n = 100;
  c.restitution = 1.0;
  c.thermostat_interval = 0.0;
  CHECK_THROWS_AS(Engine<1>(c), InvalidInput);
}

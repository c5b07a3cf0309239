// The lanes scheme (dsmc/detail/kac_lanes.hpp): its exact mean law, its invariance under
// the thread count and a checkpoint, conservation, and its equilibrium.
//
// 1. Maxwell molecules, equal masses: the mean anisotropy A = sum_i (v_ix^2 - |v_i|^2/D)
//    and the lanes' momentum anisotropy q = sum_l (P_lx^2 - |P_l|^2/D)/M obey a closed
//    linear law (docs/validation.md, "The lanes scheme"): dA/dt = -r (A - q) within an
//    epoch, r = M/(2(M-1)); deal 0 gives E q = (N-M)/(M(N-1)) A; deal k >= 1 gives
//    E q' = gamma q + A/(2(M-1)), gamma = (L-2)/(2(L-1)) - 1/(2(M-1)). With lanes of M = 4
//    the law differs from the exact N-particle law A0 exp(-N t/(2(N-1))) by 0.05 A0 at t = 4.
//    R = 32 replicas of N = 8192 from the two-beam start: the mean of A(t)/A(0) at t = 1, 2,
//    3, 4 must be within t(1e-5, 31 dof) replica standard errors of the lanes law (false
//    failure < 4e-5 for the four points), and the exact law must lie more than 10 se away
//    (the test can tell the two apart: measured separation ~40 se at t = 4).
// 2. The gas after every call is bit for bit the same for T = 1, 2, 3, 4, 7 threads (hard
//    spheres with two species, Maxwell molecules, VHS; D = 2, 3, 6; observation cuts inside
//    epochs), conserves energy and momentum to round-off, and a checkpoint taken inside an
//    epoch continues bit for bit. Deterministic: any difference is a defect.
// 3. Hard spheres in lanes of 64 relax to the Maxwell-Boltzmann law: KS p > 1e-5 (false
//    failure 1e-5) and <v^4>/<v^2>^2 = (D+2)/D within 5 se of the particle average.
// 4. Hard spheres from two beams, lanes of 4096 (8 lanes) against the exact scheme at the
//    same N = 32768: the anisotropy and the kurtosis at t = 0.5, 1, 2, 4, means of 12
//    replicas each, agree within t(1e-5, 22 dof) combined standard errors (false failure
//    8e-5 for the 8 comparisons). The lanes' bias there is ~1e-4 relative (the Maxwell
//    law), the resolution ~3e-3.
#include <catch2/catch.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "hypergas/analysis/transport_recorder.hpp"
#include "hypergas/checkpoint.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "physics/test_dsmc_common.hpp"
#include "unit/test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;

namespace {

template <class E>
double anisotropy(const E& e) {
  const auto& p = e.particles();
  double a = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto v = p.velocity(i);
    a += v[0] * v[0] - v.squaredNorm() / E::dim;
  }
  return a;
}

/// The lanes law of E A(t) / A(0) for N = L M particles in equal lanes, epochs of length E.
double lanes_law(double N, double M, double epoch, double t) {
  const double L = N / M, r = M / (2.0 * (M - 1.0));
  const double gamma = (L - 2.0) / (2.0 * (L - 1.0)) - 1.0 / (2.0 * (M - 1.0));
  double A = 1.0, q = (N - M) / (M * (N - 1.0)), now = 0.0;
  for (int k = 1;; ++k) {
    const double end = std::min(k * epoch, t);
    A = q + (A - q) * std::exp(-r * (end - now));
    now = end;
    if (now >= t) return A;
    q = gamma * q + A / (2.0 * (M - 1.0));
  }
}

template <class E>
std::vector<std::uint64_t> bits(const E& e) {
  std::vector<std::uint64_t> out;
  const auto& p = e.particles();
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int d = 0; d < E::dim; ++d) out.push_back(std::bit_cast<std::uint64_t>(p.velocity(i)[d]));
    if constexpr (E::ParticlesT::features.species) out.push_back(std::uint64_t(p.species(i)));
  }
  return out;
}

struct Times : Observer {
  std::vector<double> seen;
  void observe(const Snapshot& s) override {
    seen.push_back(s.time);
    seen.push_back(static_cast<double>(s.collisions));
  }
};

template <int D, class Model, Features F = Features{}>
void require_thread_invariant(Config cfg) {
  cfg.scheme = Scheme::lanes;
  struct Out {
    std::vector<std::uint64_t> v;
    std::vector<double> seen;
    std::uint64_t collisions = 0, candidates = 0;
  };
  const auto run = [&](int T) {
    Engine<D, Model, F> e(cfg);
    e.set_threads(T);
    const auto c0 = conserved(e.particles());
    Times obs;
    e.run_until(1.3, &obs, 0.35);  // observations and the end fall inside epochs
    e.run_until(3.0);
    const auto c1 = conserved(e.particles());
    REQUIRE(energy_rel_drift(c0, c1) < 1e-13);
    REQUIRE(momentum_drift(c0, c1) < 1e-13);
    return Out{bits(e), obs.seen, e.collisions(), e.candidates()};
  };
  const Out ref = run(1);
  REQUIRE(ref.collisions > 5000);
  for (int T : {2, 3, 4, 7}) {
    INFO("D = " << D << ", model " << Model::name << ", T = " << T);
    const Out o = run(T);
    REQUIRE(o.collisions == ref.collisions);
    REQUIRE(o.candidates == ref.candidates);
    REQUIRE(o.seen == ref.seen);
    REQUIRE(o.v == ref.v);
  }
}

}  // namespace

TEST_CASE("lanes: Maxwell anisotropy follows the lanes' exact mean law", "[dsmc][lanes]") {
  constexpr int R = 32;
  const double N = 8192, M = 4, epoch = 1.0;
  const std::vector<double> ts{1.0, 2.0, 3.0, 4.0};
  std::vector<std::vector<double>> ratio(ts.size(), std::vector<double>(R));
  for (int r = 0; r < R; ++r) {
    Config c;
    c.n = static_cast<std::size_t>(N);
    c.scheme = Scheme::lanes;
    c.lane_size = static_cast<std::uint32_t>(M);
    c.epoch = epoch;
    c.init = InitialState::beams;
    c.seed = 900 + static_cast<std::uint64_t>(r);
    Engine<3, MaxwellMolecules> e(c);
    const double a0 = anisotropy(e);
    REQUIRE(a0 > 0.5 * N);
    for (std::size_t k = 0; k < ts.size(); ++k) {
      e.run_until(ts[k]);
      ratio[k][std::size_t(r)] = anisotropy(e) / a0;
    }
  }
  const double tq = dsmc_test::t_threshold(1e-5, R);
  for (std::size_t k = 0; k < ts.size(); ++k) {
    const auto [m, se] = dsmc_test::mean_se(ratio[k]);
    const double law = lanes_law(N, M, epoch, ts[k]);
    const double exact = std::exp(-N / (2.0 * (N - 1.0)) * ts[k]);
    INFO("t = " << ts[k] << ": measured " << m << " +- " << se << ", lanes law " << law
                << ", exact process " << exact);
    CHECK(std::abs(m - law) < tq * se);
    if (ts[k] >= 3.0) CHECK(std::abs(m - exact) > 10.0 * se);
  }
}

TEST_CASE("lanes: the gas is the same for every thread count", "[dsmc][lanes]") {
  Config c;
  c.n = 6000;
  c.lane_size = 500;
  c.epoch = 0.5;
  c.seed = 41;
  c.init = InitialState::beams;
  require_thread_invariant<3, HardSpheres>(c);
  require_thread_invariant<6, HardSpheres>(c);
  require_thread_invariant<2, MaxwellMolecules>(c);
  c.lane_size = 400;  // an odd number of lanes (L = 15) of unequal sizes (400 and 401)
  c.n = 6001;
  require_thread_invariant<3, VariableHardSpheres>(c);
  c.n = 6000;
  c.initial.mass_ratio = 3.0;
  c.initial.fraction = 0.3;
  c.init = InitialState::maxwell;
  require_thread_invariant<3, HardSpheres, Features{.species = true}>(c);
}

TEST_CASE("lanes: a checkpoint inside an epoch continues bit for bit", "[dsmc][lanes]") {
  Config c;
  c.n = 3000;
  c.scheme = Scheme::lanes;
  c.lane_size = 256;
  c.epoch = 0.8;
  c.seed = 5;
  c.init = InitialState::beams;
  Engine<3, HardSpheres> a(c);
  a.run_until(1.3);
  test::TempDir dir;
  const std::string path = (dir.path / "lanes.ckpt").string();
  {
    checkpoint::Writer w(path);
    a.io(w);
    w.commit();
  }
  checkpoint::Reader r(path);
  Engine<3, HardSpheres> b(c, r);
  r.finish();
  b.set_threads(3);
  a.run_until(4.1);
  b.run_until(4.1);
  REQUIRE(bits(a) == bits(b));
  REQUIRE(a.collisions() == b.collisions());
  REQUIRE(a.candidates() == b.candidates());
}

TEST_CASE("lanes: hard spheres in small lanes relax to Maxwell-Boltzmann", "[dsmc][lanes]") {
  Config c;
  c.n = 20000;
  c.scheme = Scheme::lanes;
  c.lane_size = 64;
  c.seed = 77;
  c.init = InitialState::beams;
  Engine<3, HardSpheres> e(c);
  e.run_until(15.0);
  const auto& p = e.particles();
  const double kT = equilibrium_temperature(p);
  const auto [dist, pv] = dsmc_test::ks_maxwell(p, kT);
  INFO("KS distance " << dist << ", p " << pv);
  CHECK(pv > 1e-5);
  // <v^4> / <v^2>^2 = (D + 2) / D: per-particle terms, se from their scatter
  std::vector<double> v4;
  for (std::size_t i = 0; i < p.size(); ++i) v4.push_back(std::pow(p.velocity(i).squaredNorm(), 2));
  const auto [m4, se4] = dsmc_test::mean_se(v4);
  const double m2 = dsmc_test::moment(p, 1);
  CHECK(std::abs(m4 / (m2 * m2) - 5.0 / 3.0) < 5.0 * se4 / (m2 * m2));
}

TEST_CASE("lanes: hard spheres relax from two beams as the exact process does", "[dsmc][lanes]") {
  constexpr int R = 12;
  const std::vector<double> ts{0.5, 1.0, 2.0, 4.0};
  const auto run = [&](Scheme scheme, std::uint64_t seed0) {
    std::vector<std::vector<double>> a(ts.size()), k(ts.size());
    for (int r = 0; r < R; ++r) {
      Config c;
      c.n = 32768;
      c.scheme = scheme;
      c.lane_size = 4096;
      c.init = InitialState::beams;
      c.seed = seed0 + static_cast<std::uint64_t>(r);
      Engine<3, HardSpheres> e(c);
      const double a0 = anisotropy(e);
      for (std::size_t q = 0; q < ts.size(); ++q) {
        e.run_until(ts[q]);
        a[q].push_back(anisotropy(e) / a0);
        const double m2 = dsmc_test::moment(e.particles(), 1);
        k[q].push_back(dsmc_test::moment(e.particles(), 2) / (m2 * m2));
      }
    }
    return std::pair{a, k};
  };
  const auto [la, lk] = run(Scheme::lanes, 500);
  const auto [ea, ek] = run(Scheme::exact, 600);
  const double tq = gsl_cdf_tdist_Qinv(0.5e-5, 2.0 * R - 2.0);
  for (std::size_t q = 0; q < ts.size(); ++q) {
    const auto [lam, lase] = dsmc_test::mean_se(la[q]);
    const auto [eam, ease] = dsmc_test::mean_se(ea[q]);
    const auto [lkm, lkse] = dsmc_test::mean_se(lk[q]);
    const auto [ekm, ekse] = dsmc_test::mean_se(ek[q]);
    INFO("t = " << ts[q] << ": anisotropy " << lam << " +- " << lase << " (lanes), " << eam
                << " +- " << ease << " (exact); kurtosis " << lkm << " +- " << lkse << ", "
                << ekm << " +- " << ekse);
    CHECK(std::abs(lam - eam) < tq * std::hypot(lase, ease));
    CHECK(std::abs(lkm - ekm) < tq * std::hypot(lkse, ekse));
  }
}

// 5. Green-Kubo under lanes (--transport with --scheme lanes: the collective stress and heat
//    flux, kept collision by collision through per-thread exact sums). Maxwell molecules in
//    3D, N = 4096 in lanes of M = 1024, epoch 2: within an epoch a lane's traceless stress
//    relaxes at r = M/(2(M-1)) towards its frozen momentum part (P_l P_l^T)°/M
//    (docs/validation.md, "The lanes scheme"), which holds a fraction 1/M of C(0); so the
//    stress rate and integral are the exact ones, r and C(0)/r, up to about 1e-3, and the
//    heat flux's likewise with rate (D-1)/(2D) M/(M-1). The run's 32 stretches give standard
//    errors of ~0.5-1 %: each of the four comparisons at 4 se (Student t, 31 dof: false
//    failure 3e-4 each, 1.2e-3 for the case) with the 1e-3 bias a tenth of the tolerance.
//    A shorter run on 1 and 3 threads gives the same coefficients bit for bit.
namespace {
std::vector<analysis::TransportCoefficient> lanes_transport(double until, int threads,
                                                            double max_lag) {
  Config cfg;
  cfg.n = 4096;
  cfg.seed = 91;
  cfg.init = InitialState::maxwell;
  cfg.scheme = Scheme::lanes;
  cfg.lane_size = 1024;
  analysis::TransportSettings ts;
  ts.dt = 0.05;
  ts.max_lag = max_lag;
  ts.tagged = 0;  // lanes move particles between slots: no self-diffusion
  ts.warmup = 5.0;
  Engine<3, MaxwellMolecules> e(cfg);
  e.set_threads(threads);
  const auto frames = static_cast<std::uint64_t>(std::llround((until - ts.warmup) / ts.dt)) + 1;
  analysis::TransportRecorder rec(ts, 3, cfg.n, frames, {0.0, true});
  for (double t = 0.0; t < until;) {
    t = std::min(until, t + 1000.0);
    e.run_until(t, &rec, ts.dt);
  }
  REQUIRE(rec.frames() == frames);
  return rec.finish();
}
}  // namespace

TEST_CASE("lanes: Green-Kubo stress and heat flux of Maxwell molecules", "[dsmc][lanes]") {
  const auto r = lanes_transport(20000.0, 2, 30.0);
  REQUIRE(r.size() == 2);  // no tagged particles: viscosity and conductivity only
  const double M = 1024.0, f = M / (M - 1.0);
  const double exact[2] = {0.5 * f, 2.0 / 6.0 * f};
  for (int g = 0; g < 2; ++g) {
    const auto& c = r[std::size_t(g)];
    INFO(c.name << ": rate " << c.rate << " +- " << c.rate_error << " (exact " << exact[g]
                << "), integral " << c.value << " +- " << c.error << " (C(0)/rate "
                << c.c0 / exact[g] << ")");
    CHECK(c.rate_error < 0.02 * exact[g]);
    CHECK(std::abs(c.rate - exact[g]) < 4.0 * c.rate_error);
    CHECK(std::abs(c.value - c.c0 / exact[g]) < 4.0 * c.error);
    CHECK(std::abs(c.ratio - 1.0) < 4.0 * c.ratio_error + 5.0 / M);
  }
  const auto a = lanes_transport(1500.0, 1, 10.0), b = lanes_transport(1500.0, 3, 10.0);
  REQUIRE(a.size() == b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    REQUIRE(a[k].value == b[k].value);
    REQUIRE(a[k].stretches == b[k].stretches);
  }
}

// The Helfand tally of the EDMD engine (tally/helfand.hpp) against an independent
// recomputation from the states between events: the time integral of the kinetic stress
// and energy flux, the collisional sums dp r and de r with the minimum-image contact
// vector, and the exact tagged displacements, to round-off; and a trajectory the tally
// does not change.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "hypergas/edmd/engine.hpp"
#include "hypergas/tally/helfand.hpp"

using namespace hypergas;

namespace {

/// Copies a snapshot (positions, velocities in the original numbering).
struct Copy final : Observer {
  std::vector<double> x, v;
  void observe(const Snapshot& s) override {
    x.assign(s.n * std::size_t(s.dim), 0.0), v.assign(s.n * std::size_t(s.dim), 0.0);
    for (std::size_t i = 0; i < s.n; ++i)
      for (int a = 0; a < s.dim; ++a) {
        x[i * std::size_t(s.dim) + std::size_t(a)] = s.positions[i * std::size_t(s.stride) + std::size_t(a)];
        v[i * std::size_t(s.dim) + std::size_t(a)] = s.velocities[i * std::size_t(s.stride) + std::size_t(a)];
      }
  }
};

template <int D>
void check_tally(double packing, std::size_t n) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = packing;
  cfg.seed = 11;
  edmd::Engine<D> e(cfg);
  e.run_until(2.0);
  Copy c;
  e.observe(c);
  const double t0 = e.time(), dt = 0.25;
  const std::uint64_t coll_start = e.collisions();
  const std::vector<std::uint32_t> tagged{0, 3, static_cast<std::uint32_t>(n - 1)};
  tally::ContactSlot& slot = e.contacts();
  slot.helfand = std::make_shared<tally::Helfand>(D, t0, dt, c.v.data(), n, D, tagged);
  const tally::Helfand& H = *slot.helfand;
  const int S = H.stress_components();
  // the reference: K and E from every velocity after each event, integrated exactly
  std::vector<double> ref(std::size_t(2 * S + 2 * D + int(tagged.size()) * D), 0.0);
  const auto kinetic = [&](const std::vector<double>& v, std::vector<double>& k) {
    k.assign(std::size_t(S + D), 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double* w = &v[i * D];
      double w2 = 0;
      for (int a = 0; a < D; ++a) w2 += w[a] * w[a];
      int m = 0;
      for (int a = 0; a < D; ++a)
        for (int b = a; b < D; ++b) k[std::size_t(m++)] += w[a] * w[b];
      for (int a = 0; a < D; ++a) k[std::size_t(S + a)] += 0.5 * w[a] * w2;
    }
  };
  std::vector<double> K;
  kinetic(c.v, K);
  const double t_end = t0 + 40 * dt;
  double t = t0;
  std::uint64_t coll = 0;
  std::vector<double> v_old = c.v;
  const double L = e.box_side();
  while (true) {
    Copy before;
    e.observe(before);
    // the next event's time: step, then look
    const std::uint64_t c0 = e.collisions();
    e.step();
    if (e.time() > t_end) break;  // (the engine passed t_end: compare below at the grid)
    const double h = e.time() - t;
    for (int m = 0; m < S; ++m) ref[std::size_t(m)] += K[std::size_t(m)] * h;
    for (int a = 0; a < D; ++a) ref[std::size_t(2 * S + a)] += K[std::size_t(S + a)] * h;
    for (std::size_t k = 0; k < tagged.size(); ++k)
      for (int a = 0; a < D; ++a)
        ref[std::size_t(2 * S + 2 * D) + k * D + std::size_t(a)] += before.v[tagged[k] * D + std::size_t(a)] * h;
    t = e.time();
    if (e.collisions() == c0) continue;
    ++coll;
    Copy after;
    e.observe(after);
    std::vector<std::size_t> moved;
    for (std::size_t i = 0; i < n; ++i)
      for (int a = 0; a < D; ++a)
        if (after.v[i * D + std::size_t(a)] != before.v[i * D + std::size_t(a)]) {
          moved.push_back(i);
          break;
        }
    REQUIRE(moved.size() == 2);
    const std::size_t i = moved[0], j = moved[1];
    double r[D], dp[D];
    double ei0 = 0, ei1 = 0;
    for (int a = 0; a < D; ++a) {
      r[a] = after.x[i * D + std::size_t(a)] - after.x[j * D + std::size_t(a)];
      r[a] -= L * std::round(r[a] / L);
      dp[a] = after.v[i * D + std::size_t(a)] - before.v[i * D + std::size_t(a)];
      ei0 += 0.5 * before.v[i * D + std::size_t(a)] * before.v[i * D + std::size_t(a)];
      ei1 += 0.5 * after.v[i * D + std::size_t(a)] * after.v[i * D + std::size_t(a)];
    }
    int m = 0;
    for (int a = 0; a < D; ++a)
      for (int b = a; b < D; ++b) ref[std::size_t(S + m++)] += dp[a] * r[b];
    for (int a = 0; a < D; ++a) ref[std::size_t(2 * S + D + a)] += (ei1 - ei0) * r[a];
    kinetic(after.v, K);
    v_old = after.v;
  }
  // the tail up to t_end, with the velocities after the last event before it
  {
    const double h = t_end - t;
    for (int m = 0; m < S; ++m) ref[std::size_t(m)] += K[std::size_t(m)] * h;
    for (int a = 0; a < D; ++a) ref[std::size_t(2 * S + a)] += K[std::size_t(S + a)] * h;
    for (std::size_t k = 0; k < tagged.size(); ++k)
      for (int a = 0; a < D; ++a)
        ref[std::size_t(2 * S + 2 * D) + k * D + std::size_t(a)] += v_old[tagged[k] * D + std::size_t(a)] * h;
  }
  slot.helfand->close_until(t_end);
  const std::vector<double> rec = slot.helfand->take();
  const std::size_t R = std::size_t(H.record_size());
  REQUIRE(rec.size() == 40 * R);
  REQUIRE(H.collisions() == e.collisions() - coll_start);  // (the last one is past t_end)
  REQUIRE(coll > 50);
  std::vector<double> sum(ref.size(), 0.0);
  for (std::size_t off = 0; off < rec.size(); off += R)
    for (std::size_t k = 0; k < ref.size(); ++k) sum[k] += rec[off + k];
  for (std::size_t k = 0; k < ref.size(); ++k)
    CHECK(sum[k] == Approx(ref[k]).margin(1e-9 * (1.0 + std::fabs(ref[k]))));
  // the kinetic sums at the last grid point equal the fresh sum after the last event
  for (int m = 0; m < S + D; ++m)
    CHECK(rec[rec.size() - R + std::size_t(H.point_stress_at() + m)] ==
          Approx(K[std::size_t(m)]).margin(1e-9));
}

}  // namespace

TEST_CASE("Helfand tally: event-by-event sums equal a recomputation from the states",
          "[helfand]") {
  check_tally<2>(0.3, 64);
  check_tally<3>(0.3, 64);
  check_tally<6>(0.1, 80);
}

TEST_CASE("Helfand tally: the trajectory is the same with and without it", "[helfand]") {
  edmd::Config cfg;
  cfg.n = 256;
  cfg.packing = 0.35;
  cfg.seed = 5;
  edmd::Engine<3> a(cfg), b(cfg);
  a.run_until(1.0), b.run_until(1.0);
  Copy c;
  b.observe(c);
  b.contacts().helfand = std::make_shared<tally::Helfand>(3, b.time(), 0.1, c.v.data(), cfg.n, 3,
                                                     std::vector<std::uint32_t>{1});
  a.run_until(5.0), b.run_until(5.0);
  REQUIRE(a.collisions() == b.collisions());
  Copy ca, cb;
  a.observe(ca), b.observe(cb);
  CHECK(ca.v == cb.v);
  CHECK(ca.x == cb.x);
}

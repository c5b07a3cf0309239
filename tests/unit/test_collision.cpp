// Tests of the seed's collision kernel (include/hypergas/collision.hpp) in D = 1..6.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "hypergas/collision.hpp"
#include "hypergas/sampling.hpp"

using namespace hypergas;

namespace {
constexpr double eps = std::numeric_limits<double>::epsilon();

// Kinetic energy and momentum in long double (64-bit mantissa) so that the check itself adds
// no error comparable to the double-precision kernel's.
template <int D>
long double energy(const Vec<D>& v1, const Vec<D>& v2, double m1, double m2) {
  long double e1 = 0, e2 = 0;
  for (int k = 0; k < D; ++k) {
    e1 += static_cast<long double>(v1[k]) * v1[k];
    e2 += static_cast<long double>(v2[k]) * v2[k];
  }
  return 0.5L * m1 * e1 + 0.5L * m2 * e2;
}

// Random mass with log10(m) uniform in [-6, 6], so m1/m2 spans 1e-12..1e12.
double random_mass(Rng& rng) {
  return std::pow(10.0, -6.0 + 12.0 * rng.uniform());
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("kernel conserves momentum and energy for mass ratios 1e-12..1e12",
                       "[collision]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(12345, D);
  for (int trial = 0; trial < 20000; ++trial) {
    const double m1 = random_mass(rng), m2 = random_mass(rng);
    Vec<D> v1 = normal_vector<D>(rng), v2 = normal_vector<D>(rng);
    const Vec<D> n = unit_vector<D>(rng);
    const Vec<D> p0 = m1 * v1 + m2 * v2;
    const double pscale = m1 * v1.norm() + m2 * v2.norm();
    const long double e0 = energy<D>(v1, v2, m1, m2);
    collide<D>(v1, v2, 1.0 / m1, 1.0 / m2, n);
    REQUIRE(v1.allFinite());
    REQUIRE(v2.allFinite());
    // Momentum: each component is a sum of two products, each rounded once in the kernel
    // (weights, g.n, the update) -- a few ulps of the momentum scale m1|v1| + m2|v2|, and the
    // post-collision scale is at most 3x the pre-collision one. 64 eps leaves a margin of 4x
    // over the worst observed.
    const double pscale1 = pscale + m1 * v1.norm() + m2 * v2.norm();
    REQUIRE((m1 * v1 + m2 * v2 - p0).norm() <= 64 * eps * pscale1);
    // Energy: the relative error is bounded by a few ulps per component times the
    // condition of the exchange; 1e-14 (about 45 eps) is the bound the foundation issue
    // asks for and holds with margin for the heavy-light pairs that dominate the error.
    const long double e1 = energy<D>(v1, v2, m1, m2);
    REQUIRE(std::abs(static_cast<double>((e1 - e0) / e0)) <= 1e-14);
  }
}

TEMPLATE_TEST_CASE_SIG("an infinite mass is a wall: normal velocity reflected exactly",
                       "[collision]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(99, D);
  for (int trial = 0; trial < 1000; ++trial) {
    // Axis normals make the reflection exact in floating point: v - 2 v = -v exactly.
    const int axis = static_cast<int>(rng.below(D));
    const Vec<D> n = Vec<D>::Unit(axis);
    Vec<D> wall = Vec<D>::Zero();
    Vec<D> v = normal_vector<D>(rng);
    const Vec<D> v0 = v;
    collide<D>(wall, v, 0.0, 1.0 / random_mass(rng), n);
    REQUIRE(wall == Vec<D>::Zero());
    for (int k = 0; k < D; ++k) REQUIRE(v[k] == (k == axis ? -v0[k] : v0[k]));
  }
  // A moving wall and a random normal: the relative normal velocity reverses to round-off
  // and the wall keeps its velocity bit for bit.
  for (int trial = 0; trial < 1000; ++trial) {
    const Vec<D> n = unit_vector<D>(rng);
    const Vec<D> w0 = normal_vector<D>(rng);
    Vec<D> wall = w0, v = normal_vector<D>(rng);
    const double gn0 = (v - wall).dot(n);
    collide<D>(v, wall, 1.0, 0.0, n);
    REQUIRE(wall == w0);
    REQUIRE((v - wall).dot(n) == Approx(-gn0).margin(16 * eps * (v.norm() + wall.norm())));
  }
}

TEMPLATE_TEST_CASE_SIG("relative normal velocity reverses, tangential parts unchanged",
                       "[collision]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(7, D);
  for (int trial = 0; trial < 5000; ++trial) {
    const double m1 = random_mass(rng), m2 = random_mass(rng);
    const Vec<D> n = unit_vector<D>(rng);
    Vec<D> v1 = normal_vector<D>(rng), v2 = normal_vector<D>(rng);
    const Vec<D> a1 = v1, a2 = v2;
    collide<D>(v1, v2, 1.0 / m1, 1.0 / m2, n);
    const double scale = a1.norm() + a2.norm() + v1.norm() + v2.norm();
    const double gn0 = (a2 - a1).dot(n), gn1 = (v2 - v1).dot(n);
    REQUIRE(std::abs(gn1 + gn0) <= 32 * eps * scale);
    // Tangential components: the change of each velocity is parallel to n.
    const Vec<D> d1 = v1 - a1, d2 = v2 - a2;
    REQUIRE((d1 - d1.dot(n) * n).norm() <= 32 * eps * scale);
    REQUIRE((d2 - d2.dot(n) * n).norm() <= 32 * eps * scale);
  }
}

TEMPLATE_TEST_CASE_SIG("relabelling the particles and flipping n gives the same result",
                       "[collision]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(8, D);
  for (int trial = 0; trial < 5000; ++trial) {
    const double w1 = 1.0 / random_mass(rng), w2 = 1.0 / random_mass(rng);
    const Vec<D> n = unit_vector<D>(rng);
    const Vec<D> v1 = normal_vector<D>(rng), v2 = normal_vector<D>(rng);
    auto [p1, p2] = collided<D>(v1, v2, w1, w2, n);
    auto [q2, q1] = collided<D>(v2, v1, w2, w1, Vec<D>(-n));
    const double scale = v1.norm() + v2.norm();
    REQUIRE((p1 - q1).norm() <= 8 * eps * scale);
    REQUIRE((p2 - q2).norm() <= 8 * eps * scale);
  }
}

TEST_CASE("D = 1 with equal masses swaps velocities exactly", "[collision]") {
  Rng rng(3);
  for (int trial = 0; trial < 10000; ++trial) {
    const double m = random_mass(rng);
    // Velocities of wildly different size: a naive v1 + (v2 - v1) would lose the small one.
    const double a = rng.normal() * std::pow(10.0, rng.uniform() * 40 - 20);
    const double b = rng.normal() * std::pow(10.0, rng.uniform() * 40 - 20);
    Vec<1> v1{a}, v2{b};
    collide<1>(v1, v2, 1.0 / m, 1.0 / m, Vec<1>{trial % 2 ? 1.0 : -1.0});
    REQUIRE(v1[0] == b);
    REQUIRE(v2[0] == a);
  }
}

TEMPLATE_TEST_CASE_SIG("extreme magnitudes 1e-150 and 1e150 stay finite and conserving",
                       "[collision]", ((int D), D), 1, 2, 3, 4, 5, 6) {
  Rng rng(11, D);
  for (double scale : {1e-150, 1e150}) {
    for (int trial = 0; trial < 2000; ++trial) {
      const double m1 = random_mass(rng), m2 = random_mass(rng);
      const Vec<D> n = unit_vector<D>(rng);
      Vec<D> v1 = scale * normal_vector<D>(rng), v2 = scale * normal_vector<D>(rng);
      // Conservation checked on the scaled-back velocities (energy itself would overflow:
      // m v^2 ~ 1e12 * 1e300).
      const Vec<D> u1 = v1 / scale, u2 = v2 / scale;
      const Vec<D> p0 = m1 * u1 + m2 * u2;
      const long double e0 = energy<D>(u1, u2, m1, m2);
      collide<D>(v1, v2, 1.0 / m1, 1.0 / m2, n);
      REQUIRE(v1.allFinite());
      REQUIRE(v2.allFinite());
      const Vec<D> r1 = v1 / scale, r2 = v2 / scale;
      REQUIRE(r1.norm() > 0.0);  // no underflow to zero
      const double pscale = m1 * (u1.norm() + r1.norm()) + m2 * (u2.norm() + r2.norm());
      REQUIRE((m1 * r1 + m2 * r2 - p0).norm() <= 64 * eps * pscale);
      REQUIRE(std::abs(static_cast<double>((energy<D>(r1, r2, m1, m2) - e0) / e0)) <= 1e-14);
    }
  }
}

TEMPLATE_TEST_CASE_SIG("bad normals and masses are rejected with InvalidInput", "[collision]",
                       ((int D), D), 1, 2, 3, 4, 5, 6) {
  Vec<D> v1 = Vec<D>::Ones(), v2 = -Vec<D>::Ones();
  const Vec<D> b1 = v1, b2 = v2;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  REQUIRE_THROWS_AS(collide<D>(v1, v2, 1.0, 1.0, Vec<D>::Zero()), InvalidInput);
  REQUIRE_THROWS_WITH(collide<D>(v1, v2, 1.0, 1.0, Vec<D>::Zero()), Catch::Contains("zero"));
  REQUIRE_THROWS_AS(collide<D>(v1, v2, 1.0, 1.0, Vec<D>::Constant(nan)), InvalidInput);
  REQUIRE_THROWS_AS(collide<D>(v1, v2, 1.0, 1.0, Vec<D>::Constant(inf)), InvalidInput);
  REQUIRE_THROWS_WITH(collide<D>(v1, v2, 1.0, 1.0, Vec<D>(2.0 * Vec<D>::Unit(0))),
                      Catch::Contains("unit length"));
  const Vec<D> n = Vec<D>::Unit(0);
  REQUIRE_THROWS_AS(collide<D>(v1, v2, 0.0, 0.0, n), InvalidInput);
  REQUIRE_THROWS_AS(collide<D>(v1, v2, -1.0, 1.0, n), InvalidInput);
  REQUIRE_THROWS_AS(collide<D>(v1, v2, nan, 1.0, n), InvalidInput);
  REQUIRE_THROWS_AS(collide<D>(v1, v2, inf, 1.0, n), InvalidInput);
  // A rejected collision leaves the velocities untouched.
  REQUIRE(v1 == b1);
  REQUIRE(v2 == b2);
}

TEMPLATE_TEST_CASE_SIG("relative-velocity form equals the normal form for a reflection",
                       "[collision]", ((int D), D), 2, 3, 4, 5, 6) {
  // exchange_relative with dg = g' - g, g' = g - 2 (g.n) n (g = v1 - v2) must reproduce the
  // seed's normal form to a few ulps: both are the same update, grouped differently.
  Rng rng(21, D);
  for (int trial = 0; trial < 5000; ++trial) {
    const double w1 = 1.0 / random_mass(rng), w2 = 1.0 / random_mass(rng);
    const Vec<D> n = unit_vector<D>(rng);
    const Vec<D> v1 = normal_vector<D>(rng), v2 = normal_vector<D>(rng);
    const auto [p1, p2] = collided<D>(v1, v2, w1, w2, n);
    const Vec<D> g = v1 - v2;
    const Vec<D> dg = -2.0 * g.dot(n) * n;
    Vec<D> q1 = v1, q2 = v2;
    detail::exchange_relative<D>(q1, q2, w1, w2, dg);
    const double scale = v1.norm() + v2.norm();
    REQUIRE((p1 - q1).norm() <= 16 * eps * scale);
    REQUIRE((p2 - q2).norm() <= 16 * eps * scale);
    Vec<D> e1 = v1, e2 = v2;
    detail::exchange_relative<D, true>(e1, e2, 1.0, 1.0, dg);
    const auto [r1, r2] = collided<D>(v1, v2, 1.0, 1.0, n);
    REQUIRE((e1 - r1).norm() <= 16 * eps * scale);
    REQUIRE((e2 - r2).norm() <= 16 * eps * scale);
  }
}

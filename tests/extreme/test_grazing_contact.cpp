// Grazing collisions, pairs starting exactly in contact, and degenerate normals, for the
// EDMD kernel (edmd/pair_time.hpp contact root + the impulse collision of collision.hpp).
//
// Grazing: sphere i moves at speed u along e1 towards j at rest, impact parameter
// b = sigma (1 - eps). Exactly, the contact time is tau = (d - sqrt(sigma^2 - b^2)) / u, the
// contact normal has the component n1 = -sqrt(1 - (b/sigma)^2) ~ -sqrt(2 eps) along e1, and
// the momentum transfer is m u |n1| along n (equal masses; the energy transfer ~ n1^2). Checked for eps = 1e-12, 1e-14 in
// every D >= 2: the root agrees with the closed form to its conditioning (~1e-16 /
// sqrt(eps) relative), the distance at contact is sigma to round-off, energy and
// momentum are conserved to round-off, the pair separates afterwards and is never
// predicted to collide again, and b = sigma (1 + 1e-12) misses.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "hypergas/collision.hpp"
#include "hypergas/edmd/pair_time.hpp"

using namespace hypergas;
using hypergas::edmd::contact_time;
using hypergas::edmd::never;

namespace {
template <int D>
double predict(const Vec<D>& xi, const Vec<D>& vi, const Vec<D>& xj, const Vec<D>& vj) {
  const Vec<D> r = xj - xi, v = vj - vi;
  return contact_time(r.dot(v), v.squaredNorm(), r.squaredNorm(), 1.0);
}
}  // namespace

TEMPLATE_TEST_CASE_SIG("grazing collisions within 1e-12 of sigma", "[edmd][extreme]",
                       ((int D), D), 2, 3, 4, 5, 6) {
  const double sigma = 1.0, u = 1.3, d = 2.0;
  for (double eps : {1e-12, 1e-14}) {
    const double b = sigma * (1.0 - eps);
    Vec<D> xi = Vec<D>::Zero(), vi = Vec<D>::Zero(), xj = Vec<D>::Zero(), vj = Vec<D>::Zero();
    xi[0] = -d;
    xi[1] = b;
    vi[0] = u;
    const double tau = predict<D>(xi, vi, xj, vj);
    const double half_chord = std::sqrt((sigma - b) * (sigma + b));  // exact for the double b
    const double exact = (d - half_chord) / u;
    INFO("D = " << D << ", eps = " << eps << ": tau = " << tau << ", exact " << exact);
    REQUIRE(std::isfinite(tau));
    // The problem is ill-conditioned near grazing: d(chord)/db = -b/chord ~ 1/sqrt(2 eps),
    // so the rounding of b (and of B^2 - A C) moves tau by ~ 1e-16 d / (u sqrt(eps)); the
    // tolerance is 10 times that. What matters, the distance at contact, is checked below.
    REQUIRE(std::abs(tau - exact) < 1e-15 * d / (u * std::sqrt(eps)));
    xi += tau * vi;
    const Vec<D> r = xi - xj;
    REQUIRE(std::abs(r.norm() - sigma) < 1e-14);
    const Vec<D> n = r / r.norm();
    const Vec<D> p0 = vi + vj;
    const double e0 = vi.squaredNorm() + vj.squaredNorm();
    collide(vi, vj, 1.0, 1.0, n);
    REQUIRE(vi.allFinite());
    REQUIRE(vj.allFinite());
    REQUIRE((vi + vj - p0).norm() < 1e-15 * u);
    REQUIRE(std::abs(vi.squaredNorm() + vj.squaredNorm() - e0) < 1e-15 * e0);
    // Momentum given to j: m u |n1| along n, |n1| = half_chord / sigma. The chord comes from
    // B^2 - A C, whose rounding (~1e-16 u^2 d^2) moves it by ~1e-16 d^2 / chord; 10x that.
    REQUIRE(std::abs(vj.norm() - u * half_chord) < 1e-15 * u * d * d / half_chord);
    // After the collision the pair separates: no new contact is ever predicted.
    REQUIRE(predict<D>(xi, vi, xj, vj) == never);
  }
  // Just missing: b = sigma (1 + 1e-12) never touches.
  Vec<D> xi = Vec<D>::Zero(), vi = Vec<D>::Zero(), z = Vec<D>::Zero();
  xi[0] = -d;
  xi[1] = sigma * (1.0 + 1e-12);
  vi[0] = u;
  REQUIRE(predict<D>(xi, vi, z, z) == never);
}

TEMPLATE_TEST_CASE_SIG("pairs starting exactly in contact", "[edmd][extreme]", ((int D), D), 1,
                       2, 3, 6) {
  // |r| = sigma exactly: approaching -> collide now (tau = 0), separating or sliding
  // tangentially (r.v = 0) -> never; after the collision the pair separates.
  Vec<D> xi = Vec<D>::Zero(), xj = Vec<D>::Zero(), vi = Vec<D>::Zero(), vj = Vec<D>::Zero();
  xj[0] = 1.0;
  vi[0] = 0.7;
  REQUIRE(predict<D>(xi, vi, xj, vj) == 0.0);
  const Vec<D> n = (xi - xj).normalized();
  collide(vi, vj, 1.0, 1.0, n);
  REQUIRE(vi[0] == 0.0);
  REQUIRE(vj[0] == 0.7);
  REQUIRE(predict<D>(xi, vi, xj, vj) == never);
  if constexpr (D >= 2) {
    Vec<D> vt = Vec<D>::Zero();
    vt[1] = 1.0;  // tangential: r.v = 0, touching but not approaching
    REQUIRE(predict<D>(xi, vt, xj, Vec<D>::Zero().eval()) == never);
  }
  // Overlap by round-off (|r| = sigma (1 - 1e-15)) while approaching: collide at once.
  xj[0] = 1.0 - 1e-15;
  vi = Vec<D>::Zero();
  vi[0] = 1.0;
  REQUIRE(predict<D>(xi, vi, xj, Vec<D>::Zero().eval()) == 0.0);
}

TEMPLATE_TEST_CASE_SIG("coincident centres or a bad normal are rejected with a clear error",
                       "[edmd][extreme]", ((int D), D), 1, 3, 6) {
  Vec<D> v1 = Vec<D>::Ones(), v2 = -Vec<D>::Ones();
  const Vec<D> zero = Vec<D>::Zero();
  // A coincident pair has r = 0, so the normal r/|r| cannot be formed; the kernel rejects
  // the zero normal, and a 0/0 normal (NaN), instead of producing NaN velocities.
  REQUIRE_THROWS_WITH(collide(v1, v2, 1.0, 1.0, zero), Catch::Contains("coincident"));
  const Vec<D> nan = zero / zero.norm();
  REQUIRE_THROWS_AS(collide(v1, v2, 1.0, 1.0, nan), InvalidInput);
  Vec<D> half = Vec<D>::Zero();
  half[0] = 0.5;
  REQUIRE_THROWS_AS(collide(v1, v2, 1.0, 1.0, half), InvalidInput);
  REQUIRE(v1 == Vec<D>::Ones().eval());  // nothing was modified
  REQUIRE(v2 == (-Vec<D>::Ones()).eval());
  // A coincident pair is never predicted to "collide" by the contact root (r = 0 means
  // C = -sigma^2 < 0 and B = 0: not approaching), so it cannot reach the kernel silently.
  REQUIRE(contact_time(0.0, 2.0, 0.0, 1.0) == never);
}

// Per-particle values and temperatures of a snapshot (analysis/sample.hpp). Deterministic.
#include <catch2/catch.hpp>

#include <cmath>

#include "hypergas/analysis/sample.hpp"
#include "hypergas/error.hpp"
#include "test_analysis_support.hpp"

using namespace hypergas;
using namespace hypergas::analysis;

TEST_CASE("Values, masses and temperatures of a two-species snapshot", "[analysis]") {
  // D = 2: particle 0 (species 0, mass 1) v = (3, 4); particle 1 (species 1, mass 4)
  // v = (1, 0). Mean mass 2.5; kT = (1*25 + 4*1) / (2 * 2) = 7.25.
  test::OwnedState st(2, 2);
  st.velocity(0)[0] = 3;
  st.velocity(0)[1] = 4;
  st.velocity(1)[0] = 1;
  st.velocity(1)[1] = 0;
  st.species = {0, 1};
  st.species_inv_mass = {1.0, 0.25};
  const Snapshot s = st.snapshot();
  CHECK(mean_mass(s) == 2.5);
  CHECK(temperature(s) == 7.25);
  CHECK(temperature(s, 0) == 12.5);
  CHECK(temperature(s, 1) == 2.0);
  // Pooled speeds are mass-weighted, v sqrt(m / m_mean); one species' speeds are raw.
  const auto pooled = values(s, Quantity::speed);
  CHECK(pooled[0] == Approx(5.0 * std::sqrt(1.0 / 2.5)).epsilon(1e-15));
  CHECK(pooled[1] == Approx(1.0 * std::sqrt(4.0 / 2.5)).epsilon(1e-15));
  CHECK(values(s, Quantity::speed, 1) == std::vector<double>{1.0});
  CHECK(values(s, Quantity::component, 0) == std::vector<double>{3.0});
  const auto e = values(s, Quantity::energy);
  CHECK(e == std::vector<double>{12.5, 2.0});
  // The references: common kT, mean mass of the selection.
  const MaxwellReference r = reference(s, Quantity::speed, 1);
  CHECK(r.kT == 7.25);
  CHECK(r.mass == 4.0);
  CHECK(r.dim == 2);
}

TEST_CASE("Unreadable snapshots are refused", "[analysis]") {
  test::OwnedState st(3, 4);
  Snapshot s = st.snapshot();
  s.stride = 2;
  CHECK_THROWS_AS(values(s, Quantity::speed), InvalidInput);
  s = st.snapshot();
  s.velocities = nullptr;
  CHECK_THROWS_AS(values(s, Quantity::speed), InvalidInput);
  st.species = {0, 1, 2, 1};
  st.species_inv_mass = {1.0, 1.0};  // species 2 does not exist
  CHECK_THROWS_AS(values(st.snapshot(), Quantity::speed), InvalidInput);
  st.species_inv_mass = {1.0, 0.0, 1.0};  // an infinite mass has no thermal velocity
  CHECK_THROWS_AS(reference(st.snapshot(), Quantity::speed), InvalidInput);
  CHECK_THROWS_AS(temperature(st.snapshot(), 3), InvalidInput);  // no such particles
}

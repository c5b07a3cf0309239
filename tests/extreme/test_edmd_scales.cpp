// EDMD at velocity scales 1e-150 and 1e150 (kT = s^2): the same dimensionless results as at
// scale 1. Time runs in units of sigma sqrt(m/kT), so the run lengths scale as 1/s; the
// contact quadratic then holds terms near 1e-300 and 1e300 (near-grazing discriminants go
// subnormal at 1e-150). Checked per D and scale: finite velocities, no overlap at the end
// (all-pairs check), energy conserved to 1e-12 relative, and Z from the collision virial
// and the collision rate per sigma sqrt(m/kT) agree with the scale-1 run within a Welch
// test over B = 10 batch means each (false-failure probability 1e-4 per comparison; 12
// comparisons: 1.2e-3).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "extreme/extreme_common.hpp"
#include "hypergas/edmd/engine.hpp"

using namespace hypergas;

namespace {
struct Batches {
  std::vector<double> Z, rate;
  bool ok = true;
};

template <int D>
Batches run_scale(double s, std::size_t n, double eta) {
  edmd::Config cfg;
  cfg.n = n;
  cfg.packing = eta;
  cfg.seed = 21 + D;
  cfg.initial.kT = s * s;
  edmd::Engine<D> e(cfg);
  e.run_until(2.0 / s);  // leave the lattice start
  const double e0 = e.kinetic_energy();
  Batches b;
  for (int k = 0; k < 10; ++k) {
    e.reset_observables();
    e.run_until(e.time() + 0.5 / s);
    b.Z.push_back(e.pressure_Z());
    b.rate.push_back(e.collision_rate() / s);
  }
  b.ok = extreme::all_finite(e.particles()) && std::abs(e.kinetic_energy() - e0) < 1e-12 * e0;
  e.check_overlaps();  // throws std::logic_error naming an overlapping pair
  return b;
}

template <int D>
void check(std::size_t n, double eta) {
  const Batches ref = run_scale<D>(1.0, n, eta);
  REQUIRE(ref.ok);
  for (double s : {1e-150, 1e150}) {
    const Batches x = run_scale<D>(s, n, eta);
    REQUIRE(x.ok);
    for (int k = 0; k < 2; ++k) {
      const auto [ma, sa] = extreme::mean_se(k ? x.rate : x.Z);
      const auto [mb, sb] = extreme::mean_se(k ? ref.rate : ref.Z);
      INFO("D = " << D << ", scale " << s << (k ? ": collision rate " : ": Z ") << ma << " +- "
                  << sa << " vs scale 1: " << mb << " +- " << sb);
      REQUIRE(std::abs(ma - mb) < extreme::t_threshold(1e-4, 19) * std::hypot(sa, sb));
    }
  }
}
}  // namespace

TEST_CASE("EDMD at velocity scales 1e-150 and 1e150", "[edmd][extreme]") {
  check<2>(400, 0.3);
  check<3>(500, 0.25);
}

// The exact Kac process and Bird's NTC scheme agree as the NTC step goes to zero.
// Observable: the fourth moment m4 of 3D hard spheres at t = 1 and t = 3 from the delta
// shell (mid-relaxation, where a step error would show). R replicas per scheme; the
// difference of replica means is tested against its standard error with a Welch t test
// (normal quantile for 2R - 2 dof) at false-failure probability 1e-5 per comparison.
// Larger steps are run and printed (the error-against-run-time report plots them).
#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

#include "hypergas/dsmc/engine.hpp"
#include "physics/test_dsmc_common.hpp"

using namespace hypergas;
using namespace hypergas::dsmc;
using namespace dsmc_test;

namespace {
constexpr int R = 16;
std::vector<std::vector<double>> m4_runs(Scheme s, double dt, std::uint64_t seed0) {
  std::vector<std::vector<double>> out(2, std::vector<double>(R));
  for_replicas(R, [&](int r) {
    Config cfg;
    cfg.n = 20000;
    cfg.init = InitialState::delta;
    cfg.scheme = s;
    cfg.dt = dt;
    cfg.seed = seed0 + r;
    Engine<3, HardSpheres> e(cfg);
    e.run_until(1.0);
    out[0][r] = moment(e.particles(), 2);
    e.run_until(3.0);
    out[1][r] = moment(e.particles(), 2);
  });
  return out;
}
}  // namespace

TEST_CASE("NTC converges to the exact process as dt -> 0", "[dsmc][physics]") {
  const auto exact = m4_runs(Scheme::exact, 0.0 + 1.0, 100);
  for (double dt : {1.0, 0.1, 0.01}) {
    const auto ntc = m4_runs(Scheme::ntc, dt, 200 + static_cast<std::uint64_t>(1000 * dt));
    for (int k = 0; k < 2; ++k) {
      const auto [me, se] = mean_se(exact[k]);
      const auto [mn, sn] = mean_se(ntc[k]);
      const double z = (mn - me) / std::sqrt(se * se + sn * sn);
      INFO("dt = " << dt << ", t = " << (k ? 3 : 1) << ": exact m4 " << me << " +- " << se
                   << ", NTC " << mn << " +- " << sn << ", z = " << z);
      WARN("dt = " << dt << ", t = " << (k ? 3 : 1) << ": NTC - exact = " << mn - me << " +- "
                   << std::sqrt(se * se + sn * sn));
      if (dt <= 0.01) REQUIRE(std::abs(z) < t_threshold(1e-5, 2 * R - 1));
    }
  }
}

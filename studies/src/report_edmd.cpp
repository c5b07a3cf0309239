// The EDMD part of the work-precision study (report.hpp): the pressure Z against its
// reference in D = 1..4; run time grows with the measurement window.
#include <cmath>
#include <cstdint>
#include <numbers>

#include "clock.hpp"
#include "hypergas/analysis/estimates.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/engines.hpp"  // the engines, compiled once (extern)
#include "hypergas/edmd/observables.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/replicas.hpp"
#include "report_parts.hpp"

namespace hypergas::studies::detail {

using analysis::MeanSe;
using analysis::mean_se;

namespace {

/// Packing fraction and reference Z of the EDMD study in dimension D (report.hpp).
std::pair<double, double> eos_reference(int D) {
  switch (D) {
    case 1: return {0.5, 1.0 / (1.0 - 0.5)};         // Tonks: exact
    case 2: return {0.3, edmd::henderson_Z(0.3)};    // Henderson
    case 3: return {0.2618, edmd::carnahan_starling_Z(0.2618)};
    default: {                                       // 4D: virial series to B3
      const double x = 0.2, b3 = 4.0 / 3.0 - 3.0 * std::sqrt(3.0) / (2.0 * std::numbers::pi);
      return {x / 8.0, 1.0 + x + b3 * x * x};
    }
  }
}

}  // namespace

void eos_study(const ReportOptions& o, ReportResult& res) {
  const std::vector<double> Te = o.quick ? std::vector<double>{0.25, 1, 4}
                                         : std::vector<double>{0.25, 1, 4, 16, 64};
  const int Re = 16;
  for (int d = 1; d <= 4; ++d)
    for_dim(d, [&](auto dim) {
          constexpr int D = decltype(dim)::value;
          if constexpr (D <= 4) {
            const auto [eta, zref] = eos_reference(D);
            for (double T : Te) {
              std::vector<double> z(Re), cpu(Re);
              for_each_replica(Re, o.threads, [&](int r) {
                edmd::Config cfg;
                cfg.n = 1000;
                cfg.packing = eta;
                cfg.seed = replica_seed(o.seed + 3000 + 100 * static_cast<std::uint64_t>(D) +
                                            static_cast<std::uint64_t>(T),
                                        r);
                edmd::Engine<D> e(cfg);
                e.run_until(2.0);  // melt the lattice start
                e.reset_observables();
                const double c0 = thread_cpu_seconds();
                e.run_until(2.0 + T);
                cpu[r] = thread_cpu_seconds() - c0;
                z[r] = e.pressure_Z();
              }, {&z, &cpu});
              const auto [err, se] = rel_rms(z, zref);
              res.points.push_back({"eos", "edmd", D, T, mean_se(cpu).mean, err, se, Re});
            }
            add_slope(res, "eos", "edmd", D, 4.0);  // statistical regime (report.hpp)
          }
        });
}

}  // namespace hypergas::studies::detail

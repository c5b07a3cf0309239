// EDMD throughput (throughput.hpp): timed collision events per neighbour-scan policy.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "clock.hpp"
#include "hypergas/edmd/box.hpp"
#include "hypergas/edmd/engine.hpp"
#include "hypergas/edmd/observables.hpp"
#include "hypergas/error.hpp"
#include "hypergas/engines.hpp"
#include "hypergas/studies/statistics.hpp"
#include "hypergas/studies/throughput.hpp"

namespace hypergas::studies {

namespace {

using detail::Stopwatch;

/// The event queue the engine uses, for the JSON field "queue".
constexpr const char* queue_name = "calendar";

template <int D, class Scan>
void edmd_case(const EdmdCase& c, std::ostream& out) {
  std::vector<double> rates;
  for (int r = 0; r < c.repeats; ++r) {
    edmd::Config cfg;
    cfg.n = c.n;
    cfg.packing = c.packing;
    cfg.seed = c.seed + static_cast<std::uint64_t>(r);
    cfg.start_packing = c.start_packing;
    const Stopwatch setup_clock(false);
    edmd::Engine<D, Features{.positions = true}, Scan> e(cfg);
    const double setup_s = setup_clock.seconds();
    const double per_particle = c.warmup >= 0.0 ? c.warmup : edmd_warmup(D, c.packing);
    const auto warm = static_cast<std::uint64_t>(per_particle * static_cast<double>(c.n) / 2.0);
    const Stopwatch warmup_clock(false);
    while (e.collisions() < warm) e.step();
    const double warmup_s = warmup_clock.seconds();
    e.reset_observables();
    const std::uint64_t c0 = e.collisions(), x0 = e.crossings(), s0 = e.stale_events(),
                        p0 = e.pairs_tested(), n0 = e.scans();
    const Stopwatch wall_clock(false), cpu_clock(true);
    while (e.collisions() - c0 < c.collisions) e.step();
    const double wall = wall_clock.seconds();
    const double cpu = cpu_clock.seconds();
    const double rate = static_cast<double>(c.collisions) / cpu;
    rates.push_back(rate);
    const double per = static_cast<double>(c.collisions);
    // Z of the timed window against the equation of state (edmd/observables.hpp): a timing
    // of a state that has not melted shows as Z_dev of several percent.
    const double z = e.pressure_Z(), z_eos = edmd::reference_Z(D, c.packing);
    char eos[96] = "null,\"Z_dev\":null";
    if (std::isfinite(z_eos)) std::snprintf(eos, sizeof eos, "%.5f,\"Z_dev\":%.4f", z_eos, z / z_eos - 1.0);
    char buf[800];
    std::snprintf(buf, sizeof buf,
                  "{\"bench\":\"edmd\",\"queue\":\"%s\",\"scan\":\"%s\",\"dim\":%d,\"n\":%zu,"
                  "\"packing\":%.6g,\"start_packing\":%.6g,\"setup_s\":%.3f,\"warmup_s\":%.3f,"
                  "\"repeat\":%d,"
                  "\"collisions\":%llu,\"wall_s\":%.4f,\"cpu_s\":%.4f,\"collisions_per_s\":%.1f,"
                  "\"bytes_per_particle\":%.1f,\"cells_per_side\":%d,\"warmup_per_particle\":%g,"
                  "\"Z\":%.5f,\"Z_eos\":%s,"
                  "\"crossings_per_collision\":%.3f,\"stale_per_collision\":%.3f,"
                  "\"pairs_per_collision\":%.1f,\"scans_per_collision\":%.3f}",
                  queue_name, std::string(Scan::name).c_str(), D, c.n, c.packing,
                  c.start_packing > 0.0 ? c.start_packing : c.packing, setup_s, warmup_s, r,
                  static_cast<unsigned long long>(c.collisions), wall, cpu, rate,
                  e.bytes_per_particle(), e.cells_per_side(), per_particle, z, eos,
                  static_cast<double>(e.crossings() - x0) / per,
                  static_cast<double>(e.stale_events() - s0) / per,
                  static_cast<double>(e.pairs_tested() - p0) / per,
                  static_cast<double>(e.scans() - n0) / per);
    out << buf << std::endl;
  }
  char buf[256];
  std::snprintf(buf, sizeof buf,
                "{\"bench\":\"edmd\",\"stat\":\"median\",\"queue\":\"%s\",\"dim\":%d,"
                "\"n\":%zu,\"packing\":%.6g,\"repeats\":%d,\"collisions_per_s\":%.1f}",
                queue_name, D, c.n, c.packing, c.repeats, median(rates));
  out << buf << std::endl;
}

}  // namespace

std::vector<std::string_view> edmd_scan_names() { return registry::scan_names(); }

double edmd_warmup(int dim, double packing) {
  return packing < 0.5 * edmd::jamming_packing(dim) ? 2.0 : 100.0;
}

void run_edmd_bench(const EdmdCase& c, std::ostream& out) {
  registry::EngineChoice choice;
  choice.engine = registry::EngineKind::edmd;
  choice.dim = c.dim;
  choice.scan = c.scan;
  choice.packing = c.packing;
  registry::with_engine<registry::Scans>(choice, [&](auto engine) {
    using Engine = typename decltype(engine)::type;
    if constexpr (!registry::is_dsmc<Engine> && !registry::EngineTraits<Engine>::features.species)
      edmd_case<Engine::dim, typename registry::EngineTraits<Engine>::Scan>(c, out);
  });
}

std::vector<EdmdCase> default_edmd_cases() {
  return {{3, 4000, 0.26}, {3, 32000, 0.26}, {3, 256000, 0.26}, {6, 32000, 0.05, 200000}};
}

}  // namespace hypergas::studies

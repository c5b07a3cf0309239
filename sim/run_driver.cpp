// sim/run_driver.cpp -- the stops of a run, the checkpoint rule, the stored arguments.
#include "run_driver.hpp"

#include <sys/resource.h>

#include <fmt/core.h>

#include "hypergas/registry.hpp"
#include "version.hpp"

namespace hypergas::cli {

std::optional<Stop> RunPlan::stop(std::uint64_t k) const {
  const auto w = static_cast<std::uint64_t>(warmup_stops);
  const double t0 = sampling.t0();
  if (k + 1 < w) return Stop{t0 * static_cast<double>(k + 1) / warmup_stops, false, false};
  // f: the stop's place on the fine grid from t0 (the last equilibration stop is its first)
  const std::uint64_t f = w > 0 ? k + 1 - w : k;
  const std::uint64_t m = f / substeps, j = f % substeps;
  if (m > sampling.intervals() || (m == sampling.intervals() && j > 0)) return std::nullopt;
  const bool start = w > 0 && f == 0;
  if (j == 0) return Stop{sampling.time(m), start, true, true};
  const double a = sampling.time(m), b = sampling.time(m + 1);
  return Stop{a + (b - a) * static_cast<double>(j) / static_cast<double>(substeps), false, false,
              true};
}

Checkpointer::Checkpointer(std::filesystem::path dir, double every, double wall_s)
    : dir_(std::move(dir)), every_(every), wall_s_(wall_s) {}

bool Checkpointer::due(double t, const DriverState& st) const {
  if (every_ > 0.0 && t >= st.last_checkpoint + every_) return true;
  if (wall_s_ > 0.0) {
    const double since =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_wall_).count();
    if (since >= wall_s_) return true;
  }
  return false;
}

std::string build_identity() {
  return fmt::format("hypergas {} ({} {}, {}-bit)", version(),
#if defined(__clang__)
                     "clang",
#else
                     "gcc",
#endif
                     __VERSION__, sizeof(void*) * 8);
}

void save_header(checkpoint::Writer& w, const RunOptions& o) {
  w.tag("hypergas-run");
  w(build_identity(), options::replay_arguments(o));
  w(o.init_frame_read, o.init_checksum);  // the frame of --init-file the run started from
}

double peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0.0;
  return static_cast<double>(u.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

}  // namespace hypergas::cli

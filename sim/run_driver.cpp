// sim/run_driver.cpp -- the stops of a run, the checkpoint rule, the stored arguments.
#include "run_driver.hpp"

#include <sys/resource.h>

#include <fmt/core.h>

#include "hypergas/registry.hpp"

namespace hypergas::cli {

std::optional<Stop> RunPlan::stop(std::uint64_t k) const {
  const auto w = static_cast<std::uint64_t>(warmup_stops);
  if (k + 1 < w) return Stop{t0 * static_cast<double>(k + 1) / warmup_stops, false, false};
  if (k + 1 == w) return Stop{t0, true, true};
  const std::uint64_t m = w > 0 ? k - w + 1 : k;
  double t = t0 + static_cast<double>(m) * every;
  if (t > until) {
    if (!clamp_last || t - until > 1e-9 * every) return std::nullopt;
    t = until;
  }
  // A clamped stop at `until` is the last: the next grid point is beyond the tolerance.
  return Stop{t, false, true};
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

namespace {
std::string num(double x) { return fmt::format("{:.17g}", x); }
}  // namespace

std::vector<std::string> run_arguments(const RunOptions& o) {
  const bool edmd = o.engine_kind() == registry::EngineKind::edmd;
  std::vector<std::string> a = {"--engine", o.engine, "--dim", std::to_string(o.dim),
                                "--n", std::to_string(o.n), "--seed", std::to_string(o.seed)};
  const auto add = [&](const char* name, std::string value) {
    a.emplace_back(name);
    a.push_back(std::move(value));
  };
  if (!o.init.empty()) add("--init", o.init);
  if (o.until > 0.0) add("--until", num(o.until));
  if (o.every > 0.0) add("--every", num(o.every));
  add("--mass-ratio", num(o.mass_ratio));
  add("--fraction", num(o.fraction));
  if (edmd) {
    add("--packing", num(o.packing));
    if (o.start_packing > 0.0) add("--start-packing", num(o.start_packing));
  } else {
    add("--model", o.model);
    if (o.model == dsmc::VariableHardSpheres::name) add("--vhs-exponent", num(o.vhs_exponent));
    add("--temperature", num(o.temperature));
    add("--threads", std::to_string(o.threads));
  }
  if (o.checkpoint_every > 0.0) add("--checkpoint-every", num(o.checkpoint_every));
  if (!o.checkpoint_wall.empty()) add("--checkpoint-wall", o.checkpoint_wall);
  return a;
}

std::string build_identity() {
#ifndef HYPERGAS_VERSION
#define HYPERGAS_VERSION "unknown"
#endif
  return fmt::format("hypergas {} ({} {}, {}-bit)", HYPERGAS_VERSION,
#if defined(__clang__)
                     "clang",
#else
                     "gcc",
#endif
                     __VERSION__, sizeof(void*) * 8);
}

void save_header(checkpoint::Writer& w, const RunOptions& o) {
  w.tag("hypergas-run");
  w(build_identity(), run_arguments(o));
}

double peak_rss_bytes() {
  rusage u{};
  if (getrusage(RUSAGE_SELF, &u) != 0) return 0.0;
  return static_cast<double>(u.ru_maxrss) * 1024.0;  // Linux: kilobytes
}

}  // namespace hypergas::cli

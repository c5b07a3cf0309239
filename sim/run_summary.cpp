// sim/run_summary.cpp -- the keys every run's summary has (run_summary.hpp).
#include "run_summary.hpp"

#include <cmath>
#include <limits>
#include <variant>

#include <fmt/core.h>

#include "hypergas/registry.hpp"
#include "version.hpp"

namespace hypergas::cli {

analysis::JsonObject run_summary(const RunOptions& o, const RunFacts& f,
                                 const analysis::JsonObject& engine_keys, const DriverState& st) {
  analysis::JsonObject s{
      {"dim", std::int64_t{f.dim}},
      {"engine", std::string(registry::name(o.engine_kind()))},
      {"model", f.model},
      {"n", static_cast<std::int64_t>(o.n)},
      {"seed", o.seed},  // unsigned 64-bit: seeds of replicas are often above 2^63
      {"collisions", f.collisions},
      {"wall_s", f.wall_s},
      {"collisions_per_s", f.collisions_per_s},
      {"energy_rel_drift", f.energy_rel_drift},
      {"momentum_drift", f.momentum_drift},
      {"init", o.init_file.empty() ? std::string(registry::name(o.initial_state()))
                                   : std::string("file")},
  };
  if (!o.init_file.empty()) {  // the start: which frame of which file (init_file.hpp)
    s.emplace_back("init_file", o.init_file);
    s.emplace_back("init_frame", static_cast<std::int64_t>(o.init_frame_read));
    s.emplace_back("init_checksum", o.init_checksum);
  }
  const analysis::JsonObject run{
      {"time", f.time},
      {"every", f.every},
      {"mass_ratio", o.mass_ratio},
      {"fraction", f.fraction},
  };
  s.insert(s.end(), run.begin(), run.end());
  s.insert(s.end(), engine_keys.begin(), engine_keys.end());
  const analysis::JsonObject process{
      {"setup_s", f.setup_s},
      {"engine_s", st.engine_s},
      {"analysis_s", st.analysis_s},
      {"engine_bytes_per_particle", f.engine_bytes_per_particle},
      {"peak_rss_bytes_per_particle", peak_rss_bytes() / static_cast<double>(o.n)},
      {"checkpoints", static_cast<std::int64_t>(st.checkpoints)},
      {"resumes", static_cast<std::int64_t>(st.resumes)},
      {"version", std::string(version())},
      {"git", std::string(git_describe())},
  };
  s.insert(s.end(), process.begin(), process.end());
  return s;
}

std::string summary_field(const analysis::JsonObject& o, const std::string& key) {
  for (const auto& [k, v] : o)
    if (k == key)
      return std::visit(
          [](const auto& x) -> std::string {
            using T = std::decay_t<decltype(x)>;
            if constexpr (std::is_same_v<T, std::string>) return x;
            else if constexpr (std::is_same_v<T, double>)
              return std::isfinite(x) ? fmt::format("{:.4g}", x) : std::string("-");
            else return fmt::format("{}", x);
          },
          v);
  return "-";
}

double summary_number(const analysis::JsonObject& o, const std::string& key) {
  for (const auto& [k, v] : o)
    if (k == key) {
      if (const auto* d = std::get_if<double>(&v)) return *d;
      if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
      if (const auto* u = std::get_if<std::uint64_t>(&v)) return static_cast<double>(*u);
    }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace hypergas::cli

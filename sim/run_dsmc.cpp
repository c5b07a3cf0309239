// sim/run_dsmc.cpp -- `hypergas run --engine dsmc`: the velocity-space engine with recorders.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>
#include <variant>

#include <fmt/core.h>

#include "engine_runs.hpp"
#include "granular_summary.hpp"
#include "hypergas/analysis/moments_recorder.hpp"
#include "hypergas/conserved.hpp"
#include "hypergas/dsmc/engine.hpp"
#include "hypergas/engine_concept.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/studies/replicas.hpp"
#include "hypergas/studies/statistics.hpp"
#include "run_driver.hpp"
#include "run_observer.hpp"

namespace hypergas::cli {

RunRecord simulate(const RunOptions& o, bool progress, RunContext& ctx) {
  if (o.engine_kind() == registry::EngineKind::edmd) return simulate_edmd(o, progress, ctx);
  return simulate_dsmc(o, progress, ctx);
}

RunRecord simulate(const RunOptions& o, bool progress) {
  RunContext none;
  return simulate(o, progress, none);
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

namespace detail {
/// The DSMC run for one (D, model, species): run_dsmc_impl.hpp, instantiated in
/// run_dsmc_d12.cpp, run_dsmc_d34.cpp and run_dsmc_d56.cpp.
template <int D, class Model, bool Species>
RunRecord run_dsmc(const RunOptions& o, const dsmc::Config& cfg, bool progress,
                   RunContext& ctx);
}  // namespace detail

RunRecord simulate_dsmc(const RunOptions& o, bool progress, RunContext& ctx) {
  const dsmc::Config cfg = dsmc_config(o);
  const bool species = two_species(o);
  if (o.dim == 1 && !species)
    fmt::print(stderr,
               "hypergas: note: in D = 1 equal masses only swap velocities, so the gas never "
               "relaxes; use --mass-ratio R (R != 1) for a two-mass gas\n");
  return registry::dispatch(
      [&](auto dim, auto model, auto sp) {
        return detail::run_dsmc<decltype(dim)::type::value, typename decltype(model)::type,
                                decltype(sp)::type::value>(o, cfg, progress, ctx);
      },
      registry::dimension(o.dim), registry::model(o.model), registry::species(species));
}

}  // namespace hypergas::cli

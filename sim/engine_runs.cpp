// sim/engine_runs.cpp -- the one entry of the command's engine runs (engine_runs.hpp) and
// the loops over a run's outputs.
#include "engine_runs.hpp"

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string_view>

#include <fmt/core.h>

#include "hypergas/vec.hpp"

namespace hypergas::cli {

RunRecord simulate(const RunOptions& o, bool progress, RunContext& ctx) {
  if (o.engine_kind() == registry::EngineKind::dsmc && o.dim == 1 && !two_species(o))
    fmt::print(stderr,
               "hypergas: note: in D = 1 equal masses only swap velocities, so the gas never "
               "relaxes; use --mass-ratio R (R != 1) for a two-mass gas\n");
  for (const std::string& note : options::span_notes(o, sampling_start(o)))
    fmt::print(stderr, "hypergas: note: {}\n", note);
  return for_dim(o.dim, [&](auto dim) {
    return detail::run_dim<decltype(dim)::value>(o, progress, ctx);
  });
}

RunRecord simulate(const RunOptions& o, bool progress) {
  RunContext none;
  return simulate(o, progress, none);
}

double sampling_start(const RunOptions& o) {
  // the fraction of [0, until] an EDMD run equilibrates when --equilibration is not given
  constexpr double equilibration_fraction = 0.2;
  if (o.engine_kind() != registry::EngineKind::edmd) return 0.0;
  return o.equilibration > 0.0 ? o.equilibration : equilibration_fraction * o.until;
}

std::vector<Observer*> samplers(const std::vector<std::unique_ptr<Output>>& outputs) {
  std::vector<Observer*> v;
  for (const auto& out : outputs)
    if (Observer* s = out->sampler()) v.push_back(s);
  return v;
}

std::vector<Observer*> fine_observers(const std::vector<std::unique_ptr<Output>>& outputs) {
  std::vector<Observer*> v;
  for (const auto& out : outputs)
    if (Observer* s = out->fine()) v.push_back(s);
  return v;
}

void finish_outputs(const std::vector<std::unique_ptr<Output>>& outputs, DriverState& st) {
  const auto t0 = std::chrono::steady_clock::now();
  for (const auto& out : outputs) out->finish();
  st.analysis_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

void summarize_outputs(const std::vector<std::unique_ptr<Output>>& outputs,
                       analysis::JsonObject& summary) {
  for (const auto& out : outputs) out->summarize(summary);
  // each key has one owner (outputs/output.hpp): a key written twice is a defect
  std::vector<std::string_view> keys;
  for (const auto& [k, v] : summary) keys.push_back(k);
  std::sort(keys.begin(), keys.end());
  if (const auto d = std::adjacent_find(keys.begin(), keys.end()); d != keys.end())
    throw std::logic_error(fmt::format("summary.json: key '{}' written twice", *d));
}

}  // namespace hypergas::cli

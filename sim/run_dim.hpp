// sim/run_dim.hpp -- the runs of one dimension: every engine the registry lists for D,
// reached through registry::with_engine. run_dim.cpp.in instantiates it once per D of the
// instantiation list (cmake/HypergasDims.cmake), so a parallel build spreads the engines
// over the cores.
#pragma once

#include "engine_runs.hpp"
#include "hypergas/engines.hpp"
#include "run_dsmc.hpp"
#include "run_edmd.hpp"

namespace hypergas::cli::detail {

template <int D>
RunRecord run_dim(const RunOptions& o, bool progress, RunContext& ctx) {
  return registry::with_engine<D>(options::engine_choice(o), [&](auto engine) -> RunRecord {
    using Engine = typename decltype(engine)::type;
    if constexpr (registry::is_dsmc<Engine>)
      return run_dsmc<Engine>(o, progress, ctx);
    else
      return run_edmd<Engine>(o, progress, ctx);
  });
}

}  // namespace hypergas::cli::detail

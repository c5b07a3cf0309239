// options/src/from_given.cpp -- validated run options from given text (the command, a sweep's
// cases) or from typed values (the Python keywords): the engine's defaults, the values, then
// validate.
#include "hypergas/options/from_given.hpp"

namespace hypergas::options {

RunOptions make(registry::EngineKind e, const std::function<void(RunOptions&)>& set) {
  RunOptions o = defaults(e);
  set(o);
  validate(o);
  return o;
}

RunOptions from_given(const Given& given, const std::function<void(RunOptions&)>& adjust) {
  registry::EngineKind engine = default_engine;
  for (const auto& [opt, text] : given)
    if (opt->name == "engine") {
      RunOptions probe;
      set_text(probe, *opt, text);  // checks the name
      engine = probe.engine_kind();
    }
  return make(engine, [&](RunOptions& o) {
    for (const auto& [opt, text] : given) set_text(o, *opt, text);
    if (adjust) adjust(o);
  });
}

}  // namespace hypergas::options

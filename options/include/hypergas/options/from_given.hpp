// hypergas/options/from_given.hpp -- validated run options, built in one place: the engine's
// defaults, the values (typed, or as given text), then validate(). `hypergas run` and each
// case of a sweep build theirs from the given (option, text) pairs (from_given); the Python
// keywords and the default scene set typed values (make).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "hypergas/options/table.hpp"

namespace hypergas::options {

/// Options as given on a command line or in a sweep plan: each entry with its text, in order.
using Given = std::vector<std::pair<const Option*, std::string>>;

/// Validated run options of engine `e`: defaults(e), then `set` (the set_* functions of
/// table.hpp, or plain assignments), then validate(). Throws InvalidInput from either (and
/// whatever `set` throws).
RunOptions make(registry::EngineKind e, const std::function<void(RunOptions&)>& set);

/// The validated options that `given` describes, as `hypergas run` builds them: make() for
/// the engine of the last given --engine (default_engine without one; its name checked by
/// set_text), setting each text in order (set_text), then `adjust` (if any) before validate().
RunOptions from_given(const Given& given, const std::function<void(RunOptions&)>& adjust = {});

}  // namespace hypergas::options

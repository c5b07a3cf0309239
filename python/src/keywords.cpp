// python/src/keywords.cpp -- the keyword lists of hypergas.DSMC / hypergas.EDMD and
// run_options: keyword arguments -> cli::RunOptions (keywords.hpp).
#include "keywords.hpp"

#include <algorithm>

#include "convert.hpp"

namespace hypergas::python {

const std::vector<std::string> dsmc_keywords = {"dim",         "n",           "model",
                                                "vhs_exponent", "init",       "mass_ratio",
                                                "fraction",     "temperature", "seed",
                                                "threads"};
const std::vector<std::string> edmd_keywords = {"dim",        "n",        "packing",
                                                "start_packing", "init", "mass_ratio",
                                                "fraction",   "seed"};

cli::RunOptions run_options(registry::EngineKind kind, const py::kwargs& kw,
                            const std::vector<std::string>& allowed) {
  cli::RunOptions o;
  o.engine = std::string(registry::name(kind));
  o.out = "python";  // no output folder: the module writes nothing by itself
  for (const auto& [key, value] : kw) {
    const std::string k = py::str(key);
    if (std::find(allowed.begin(), allowed.end(), k) == allowed.end())
      type_error("unexpected keyword argument '" + k + "'");
    if (value.is_none()) continue;  // not given: the default
    std::string option = "--" + k;
    for (char& c : option)
      if (c == '_') c = '-';
    o.given.push_back(option);
    if (k == "dim") o.dim = static_cast<int>(std::clamp<long long>(as_integer(k, value), -1, 1000));
    else if (k == "n") o.n = as_integer(k, value);
    else if (k == "model") o.model = as_text(k, value);
    else if (k == "init") o.init = as_text(k, value);
    else if (k == "vhs_exponent") o.vhs_exponent = as_real(k, value);
    else if (k == "packing") o.packing = as_real(k, value);
    else if (k == "start_packing") o.start_packing = as_real(k, value);
    else if (k == "mass_ratio") o.mass_ratio = as_real(k, value);
    else if (k == "fraction") o.fraction = as_real(k, value);
    else if (k == "temperature") o.temperature = as_real(k, value);
    else if (k == "seed") o.seed = as_seed(value);
    else if (k == "threads")
      o.threads = static_cast<int>(std::clamp<long long>(as_integer(k, value), -1, 100000));
  }
  cli::validate(o);
  return o;
}

}  // namespace hypergas::python

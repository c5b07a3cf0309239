// python/src/handles.cpp -- the engine factories: the dimension picks the per-dimension
// translation unit (handles_dim.cpp.in), which picks model and features.
#include "engine_handle.hpp"
#include "hypergas/dsmc/config.hpp"
#include "hypergas/registry.hpp"
#include "hypergas/vec.hpp"

namespace hypergas::python {

std::unique_ptr<DsmcHandle> make_dsmc(const options::RunOptions& o,
                                      const GivenVelocities* given) {
  const dsmc::Config cfg = options::dsmc_config(o);
  dsmc::validate(cfg);
  return for_dim(o.dim,
                 [&](auto dim) { return detail::make_dsmc_dim<decltype(dim)::value>(o, cfg, given); });
}

std::unique_ptr<EdmdHandle> make_edmd(const options::RunOptions& o,
                                      const edmd::GivenState* given) {
  const edmd::Config cfg = options::edmd_config(o);
  return for_dim(o.dim, [&](auto dim) {
    return detail::make_edmd_dim<decltype(dim)::value>(o, cfg, given);
  });
}

}  // namespace hypergas::python

// sim/run_dsmc_d12.cpp -- the DSMC runs of D = 1 and 2 (run_dsmc_impl.hpp).
#include "run_dsmc_impl.hpp"

namespace hypergas::cli::detail {
HYPERGAS_RUN_DSMC_INSTANTIATE(1)
HYPERGAS_RUN_DSMC_INSTANTIATE(2)
}  // namespace hypergas::cli::detail

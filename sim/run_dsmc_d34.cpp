// sim/run_dsmc_d34.cpp -- the DSMC runs of D = 3 and 4 (run_dsmc_impl.hpp).
#include "run_dsmc_impl.hpp"

namespace hypergas::cli::detail {
HYPERGAS_RUN_DSMC_INSTANTIATE(3)
HYPERGAS_RUN_DSMC_INSTANTIATE(4)
}  // namespace hypergas::cli::detail

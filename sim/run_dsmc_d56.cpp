// sim/run_dsmc_d56.cpp -- the DSMC runs of D = 5 and 6 (run_dsmc_impl.hpp).
#include "run_dsmc_impl.hpp"

namespace hypergas::cli::detail {
HYPERGAS_RUN_DSMC_INSTANTIATE(5)
HYPERGAS_RUN_DSMC_INSTANTIATE(6)
}  // namespace hypergas::cli::detail

# engine_detail.cmake -- an engine's `detail` namespace is its own: nothing outside the
# engine's folder (include/hypergas/<engine>/) names dsmc::detail or edmd::detail; what
# others need (the lanes' shape, the tick counter, huge pages) is the engine's public API.
# The tests may reach inside (tests/ is not scanned). This script fails on such a name.
# Run by ctest: cmake -DSRC=<source dir> -P engine_detail.cmake
include(${CMAKE_CURRENT_LIST_DIR}/sources.cmake)
set(found "")
hypergas_scan(found "dsmc::detail" "^include/hypergas/dsmc/")
hypergas_scan(found "edmd::detail" "^include/hypergas/edmd/")
if(found)
  message(FATAL_ERROR "an engine's detail named outside its folder:${found}")
endif()
message(STATUS "engine_detail: no engine's detail named outside its folder")

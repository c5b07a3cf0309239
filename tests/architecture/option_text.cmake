# option_text.cmake -- the run options' named choices (engine, scheme, drive, thermostat,
# initial state, model) are parsed once, by the option table (options/src/table.cpp), into
# the enums of RunOptions; code past it reads the enums. This script fails if a source file
# outside the parsers turns option text into a choice or compares a model name.
# Run by ctest: cmake -DSRC=<source dir> -P option_text.cmake
include(${CMAKE_CURRENT_LIST_DIR}/sources.cmake)
# Skipped: the option table and its rules (options/), and the parsers of other inputs: the
# bench command's options (sim/options.cpp, studies/src/throughput_dsmc.cpp) and the engine
# name Python passes (python/src).
set(found "")
hypergas_scan(found
  "(\\.model (==|!=))|drive_kind\\(|thermostat_kind\\(|registry::scheme\\(|registry::initial_state\\(|registry::engine\\("
  "^options/" "^sim/options\\.cpp$" "^studies/src/throughput_dsmc\\.cpp$" "^python/src/keywords\\.cpp$"
  "^python/src/bind_run\\.cpp$" "^include/hypergas/registry\\.hpp$")
if(found)
  message(FATAL_ERROR "option text parsed or compared outside the option table:${found}")
endif()
message(STATUS "option_text: no option text parsed outside the parsers")

# option_text.cmake -- the run options' named choices (engine, scheme, drive, thermostat,
# initial state, model) are parsed once, by the option table (options/src/table.cpp), into
# the enums of RunOptions; code past it reads the enums. This script fails if a source file
# outside the parsers turns option text into a choice or compares a model name.
# Run by ctest: cmake -DSRC=<source dir> -P option_text.cmake
cmake_policy(SET CMP0057 NEW)  # if(IN_LIST)
file(GLOB_RECURSE sources
     ${SRC}/sim/*.cpp ${SRC}/sim/*.hpp ${SRC}/sim/*.in
     ${SRC}/python/src/*.cpp ${SRC}/python/src/*.hpp
     ${SRC}/studies/src/*.cpp ${SRC}/studies/src/*.hpp ${SRC}/studies/include/*.hpp
     ${SRC}/analysis/src/*.cpp ${SRC}/analysis/include/*.hpp
     ${SRC}/h5md/*.cpp ${SRC}/h5md/*.hpp ${SRC}/include/*.hpp)
# The parsers of other inputs: the bench command's options (sim/options.cpp,
# studies/src/throughput_dsmc.cpp) and the engine name Python passes (python/src).
set(parsers sim/options.cpp studies/src/throughput_dsmc.cpp python/src/keywords.cpp
            python/src/bind_run.cpp include/hypergas/registry.hpp)
set(pattern "(\\.model (==|!=))|drive_kind\\(|thermostat_kind\\(|registry::scheme\\(|registry::initial_state\\(|registry::engine\\(")
set(found "")
foreach(f IN LISTS sources)
  file(RELATIVE_PATH rel ${SRC} ${f})
  if(rel IN_LIST parsers)
    continue()
  endif()
  file(STRINGS ${f} lines REGEX "${pattern}")
  foreach(l IN LISTS lines)
    string(APPEND found "\n  ${rel}: ${l}")
  endforeach()
endforeach()
list(LENGTH sources n)
if(n LESS 50)
  message(FATAL_ERROR "option_text: only ${n} sources found under ${SRC}: wrong folder")
endif()
if(found)
  message(FATAL_ERROR "option text parsed or compared outside the option table:${found}")
endif()
message(STATUS "option_text: ${n} sources, no option text parsed outside the parsers")

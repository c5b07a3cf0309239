# HypergasDims.cmake -- the one instantiation list: the dimensions every engine is compiled
# for, read from include/hypergas/vec.hpp (min_dim, max_dim), and the generation of one
# translation unit per dimension from an .inst.in-style template (deal.II's pattern).
#
#   hypergas_per_dim(<out-var> TEMPLATE <file.cpp.in> PREFIX <name>)
#
# configures <file.cpp.in> once per dimension D with @HYPERGAS_DIM@ = D into
# <binary dir>/<name>_<D>d.cpp and appends the generated paths to <out-var>.
# Included by every directory that generates per-dimension files (the variables are set in
# the including directory's scope, so no include guard).

file(STRINGS ${CMAKE_CURRENT_LIST_DIR}/../include/hypergas/vec.hpp _hypergas_dim_lines
     REGEX "inline constexpr int (min|max)_dim = [0-9]+;")
foreach(line ${_hypergas_dim_lines})
  if(line MATCHES "min_dim = ([0-9]+)")
    set(HYPERGAS_MIN_DIM ${CMAKE_MATCH_1})
  elseif(line MATCHES "max_dim = ([0-9]+)")
    set(HYPERGAS_MAX_DIM ${CMAKE_MATCH_1})
  endif()
endforeach()
if(NOT HYPERGAS_MIN_DIM OR NOT HYPERGAS_MAX_DIM)
  message(FATAL_ERROR "HypergasDims.cmake: min_dim/max_dim not found in include/hypergas/vec.hpp")
endif()
set(HYPERGAS_DIMS)
foreach(d RANGE ${HYPERGAS_MIN_DIM} ${HYPERGAS_MAX_DIM})
  list(APPEND HYPERGAS_DIMS ${d})
endforeach()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS
             ${CMAKE_CURRENT_LIST_DIR}/../include/hypergas/vec.hpp)

function(hypergas_per_dim out)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "TEMPLATE;PREFIX" "")
  set(files ${${out}})
  foreach(d ${HYPERGAS_DIMS})
    set(HYPERGAS_DIM ${d})
    set(file ${CMAKE_CURRENT_BINARY_DIR}/${arg_PREFIX}_${d}d.cpp)
    configure_file(${arg_TEMPLATE} ${file} @ONLY)
    list(APPEND files ${file})
  endforeach()
  set(${out} ${files} PARENT_SCOPE)
endfunction()

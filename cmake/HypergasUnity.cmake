# hypergas_unity(<target> [SKIP <file>...]): compiles the target's files in batches of 8 (a
# CMake unity build) when HYPERGAS_UNITY_BUILD is on. Each light file spends most of its
# compile parsing the same headers (the standard library, {fmt}, the analysis and option
# headers); eight of them together compile in about a quarter of their separate times
# (docs/benchmarks.md, build time). The files listed after SKIP, each one instantiating a
# list of engines, stay alone so that the cores share them.
function(hypergas_unity target)
  cmake_parse_arguments(U "" "" "SKIP" ${ARGN})
  if(NOT HYPERGAS_UNITY_BUILD)
    return()
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 8)
  if(U_SKIP)
    set_source_files_properties(${U_SKIP} PROPERTIES SKIP_UNITY_BUILD_INCLUSION ON)
  endif()
endfunction()

# sources.cmake -- the sources the architecture checks scan: every library, command and
# binding file (tests/ excluded), in `var`; fails when fewer than 50 are found (a wrong
# SRC). Included by the checks, which then grep them: hypergas_scan(<var> <regex> <skip>...)
# appends "\n  <file>: <line>" for each line matching <regex> in a file whose path below
# SRC matches none of the <skip> regexes.
function(hypergas_sources var)
  file(GLOB_RECURSE sources
       ${SRC}/sim/*.cpp ${SRC}/sim/*.hpp ${SRC}/sim/*.in
       ${SRC}/python/src/*.cpp ${SRC}/python/src/*.hpp
       ${SRC}/studies/src/*.cpp ${SRC}/studies/src/*.hpp ${SRC}/studies/include/*.hpp
       ${SRC}/analysis/src/*.cpp ${SRC}/analysis/include/*.hpp
       ${SRC}/options/*.cpp ${SRC}/options/*.hpp ${SRC}/engines/*.cpp ${SRC}/engines/*.in
       ${SRC}/h5md/*.cpp ${SRC}/h5md/*.hpp ${SRC}/include/*.hpp)
  list(LENGTH sources n)
  if(n LESS 50)
    message(FATAL_ERROR "only ${n} sources found under ${SRC}: wrong folder")
  endif()
  set(${var} ${sources} PARENT_SCOPE)
endfunction()

function(hypergas_scan var regex)
  hypergas_sources(sources)
  set(found "${${var}}")
  foreach(f IN LISTS sources)
    file(RELATIVE_PATH rel ${SRC} ${f})
    set(skipped FALSE)
    foreach(skip IN LISTS ARGN)
      if(rel MATCHES "${skip}")
        set(skipped TRUE)
      endif()
    endforeach()
    if(skipped)
      continue()
    endif()
    file(STRINGS ${f} lines REGEX "${regex}")
    foreach(l IN LISTS lines)
      string(APPEND found "\n  ${rel}: ${l}")
    endforeach()
  endforeach()
  set(${var} "${found}" PARENT_SCOPE)
endfunction()

# GitDescribe.cmake -- run at build time (cmake -DSOURCE_DIR=... -DOUT=... -P this file):
# writes OUT, a translation unit defining hypergas::cli::git_describe() as
# `git describe --always --dirty --tags` of SOURCE_DIR ("unknown" without git), and rewrites
# it only when the description changed, so an unchanged tree recompiles nothing.
execute_process(COMMAND git -C "${SOURCE_DIR}" describe --always --dirty --tags
                OUTPUT_VARIABLE describe OUTPUT_STRIP_TRAILING_WHITESPACE
                RESULT_VARIABLE status ERROR_QUIET)
if(NOT status EQUAL 0 OR describe STREQUAL "")
  set(describe "unknown")
endif()
set(content "// Generated at build time by cmake/GitDescribe.cmake.\n#include \"version.hpp\"\n\nstd::string_view hypergas::cli::git_describe() { return \"${describe}\"; }\n")
set(old "")
if(EXISTS "${OUT}")
  file(READ "${OUT}" old)
endif()
if(NOT old STREQUAL content)
  file(WRITE "${OUT}" "${content}")
endif()

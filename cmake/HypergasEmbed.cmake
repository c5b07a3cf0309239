# HypergasEmbed.cmake -- text files of the repository (gnuplot scripts) compiled into a
# target as string constants, so that the programs carry the scripts and the repository
# keeps them as files only.
#
#   hypergas_embed_text(<target> NAME <identifier> FILE <path>)
#
# generates, at build time, <binary dir>/embedded/<identifier>.hpp holding
#   namespace hypergas::embedded { inline constexpr std::string_view <identifier> = R"(...)"; }
# with the file's bytes, adds that folder to the target's private include path, and
# regenerates the header whenever the file changes.
include_guard(GLOBAL)

function(hypergas_embed_text target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "NAME;FILE" "")
  if(NOT arg_NAME OR NOT arg_FILE)
    message(FATAL_ERROR "hypergas_embed_text: NAME and FILE are required")
  endif()
  set(script ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/embed_text.cmake)
  set(dir ${CMAKE_CURRENT_BINARY_DIR}/embedded)
  set(header ${dir}/${arg_NAME}.hpp)
  add_custom_command(
    OUTPUT ${header}
    COMMAND ${CMAKE_COMMAND} -DNAME=${arg_NAME} -DINPUT=${arg_FILE} -DOUTPUT=${header}
            -P ${script}
    DEPENDS ${arg_FILE} ${script}
    COMMENT "Embedding ${arg_FILE}"
    VERBATIM)
  target_sources(${target} PRIVATE ${header})
  target_include_directories(${target} PRIVATE ${dir})
endfunction()

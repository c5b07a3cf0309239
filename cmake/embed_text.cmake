# embed_text.cmake -- writes OUTPUT, a C++ header holding the bytes of INPUT as the
# std::string_view hypergas::embedded::NAME (a raw string literal). Run by
# hypergas_embed_text (HypergasEmbed.cmake) as `cmake -DNAME=.. -DINPUT=.. -DOUTPUT=.. -P`.
foreach(var NAME INPUT OUTPUT)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "embed_text.cmake: -D${var}= is required")
  endif()
endforeach()
file(READ ${INPUT} text)
set(delim "HYPERGAS_EMBED")
string(FIND "${text}" ")${delim}\"" clash)
if(NOT clash EQUAL -1)
  message(FATAL_ERROR "embed_text.cmake: ${INPUT} contains the delimiter )${delim}\"")
endif()
get_filename_component(source_name ${INPUT} NAME)
file(WRITE ${OUTPUT}
  "// Generated from ${source_name} by cmake/embed_text.cmake; edit the script, not this file.\n"
  "#pragma once\n\n#include <string_view>\n\nnamespace hypergas::embedded {\n\n"
  "inline constexpr std::string_view ${NAME} = R\"${delim}(${text})${delim}\";\n\n"
  "}  // namespace hypergas::embedded\n")

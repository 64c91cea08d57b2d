# Compiles one public header alone, as C99 or C++11, with pedantic warnings
# as errors, and checks it includes nothing but <stddef.h>, <stdint.h> and
# its sibling headers.  Called by the abi_header_* tests:
#   cmake -DCOMPILER=cc -DLANG=C|CXX -DHEADER=octree.h -DINCLUDE_DIR=...
#         -DWORK_DIR=... -P check_header.cmake
# With -DSOURCE=file.c instead, compiles that source the same way (C++:
# as C++ code), e.g. a file using every OPX_*_INIT macro.
cmake_minimum_required(VERSION 3.16)

if(DEFINED SOURCE)
  get_filename_component(HEADER ${SOURCE} NAME)
endif()
foreach(var COMPILER LANG HEADER INCLUDE_DIR WORK_DIR)
  if(NOT DEFINED ${var})
    message(FATAL_ERROR "check_header.cmake: ${var} is not set")
  endif()
endforeach()

# Only the standard headers the ABI needs, or our own public headers.
if(NOT DEFINED SOURCE)
file(STRINGS ${INCLUDE_DIR}/octoprox/${HEADER} include_lines REGEX "^[ \t]*#[ \t]*include")
file(GLOB public_headers RELATIVE ${INCLUDE_DIR}/octoprox ${INCLUDE_DIR}/octoprox/*.h)
foreach(line IN LISTS include_lines)
  if(line MATCHES "<(stddef|stdint)\\.h>")
    continue()
  endif()
  if(line MATCHES "\"([^\"]+)\"" AND CMAKE_MATCH_1 IN_LIST public_headers)
    continue()
  endif()
  message(FATAL_ERROR "${HEADER}: forbidden include \"${line}\" (public headers include only "
                      "<stddef.h>, <stdint.h> and each other)")
endforeach()
endif()

string(MAKE_C_IDENTIFIER "${HEADER}_${LANG}" stem)
if(LANG STREQUAL "C")
  set(source ${WORK_DIR}/${stem}.c)
  set(flags -std=c99 -pedantic -Werror -Wall -Wextra -Wstrict-prototypes -Wundef
            -Wmissing-prototypes -Wshadow)
elseif(LANG STREQUAL "CXX")
  set(source ${WORK_DIR}/${stem}.cpp)
  set(flags -std=c++11 -pedantic -Werror -Wall -Wextra -Wundef -Wshadow -Wold-style-cast)
else()
  message(FATAL_ERROR "LANG must be C or CXX, not ${LANG}")
endif()

# The header first (nothing before it may hide a missing include), twice
# (the include guard), then a function so the unit is not empty.
file(MAKE_DIRECTORY ${WORK_DIR})
if(DEFINED SOURCE)
  file(READ ${SOURCE} content)
  file(WRITE ${source} "${content}")
else()
  file(WRITE ${source}
    "#include <octoprox/${HEADER}>\n"
    "#include <octoprox/${HEADER}>\n"
    "int opx_header_check_${stem}(void);\n"
    "int opx_header_check_${stem}(void) { return OPX_VERSION_MAJOR >= 0; }\n")
endif()

execute_process(
  COMMAND ${COMPILER} ${flags} -I${INCLUDE_DIR} -c ${source} -o ${source}.o
  RESULT_VARIABLE result
  OUTPUT_VARIABLE output
  ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "${HEADER} does not compile alone as ${LANG} (${flags}):\n${output}")
endif()
message(STATUS "${HEADER} compiles alone as ${LANG}")

# The demo's smoke tests: run `opx-demo --quick` (with -DREAL=ON also
# --real, on the shared data) and check that it exits 0, prints the report
# (both engines agree) and the picture's path, and that the picture is a
# PNG of a plausible size.  --real without the data prints "SKIP:" (the
# test's SKIP_REGULAR_EXPRESSION).
#   cmake -DDEMO=path/to/opx-demo -DOUT=dir [-DREAL=ON -DDATA=dir] -P check_demo.cmake
set(picture opx-demo.png)
set(arguments --quick --out "${OUT}")
if(REAL)
  if(DEFINED ENV{OPX_DATA_DIR} AND NOT "$ENV{OPX_DATA_DIR}" STREQUAL "")
    set(DATA "$ENV{OPX_DATA_DIR}")
  endif()
  if(NOT EXISTS "${DATA}/rgbd" OR NOT EXISTS "${DATA}/robots/pr2_description")
    message("SKIP: ${DATA} holds no rgbd/ and robots/pr2_description/; set OPX_DATA_DIR to the shared data folder")
    return()
  endif()
  set(picture opx-demo-real.png)
  list(APPEND arguments --real --data "${DATA}")
endif()
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${DEMO}" ${arguments}
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
message("${output}${errors}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "opx-demo --quick exited ${result}")
endif()
foreach(expected "engines +agree" "path query +collides" "picture +${OUT}/${picture}" "2\\. ingest")
  if(NOT output MATCHES "${expected}")
    message(FATAL_ERROR "the demo's report lacks '${expected}'")
  endif()
endforeach()
file(READ "${OUT}/${picture}" head LIMIT 24 HEX)
# The PNG signature, then the IHDR chunk (length 13).
if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452")
  message(FATAL_ERROR "${OUT}/${picture} is not a PNG (starts ${head})")
endif()
file(SIZE "${OUT}/${picture}" size)
if(size LESS 5000)
  message(FATAL_ERROR "${OUT}/${picture} is only ${size} bytes")
endif()

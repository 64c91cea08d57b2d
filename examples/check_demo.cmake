# The demo's smoke test: runs `opx-demo --quick` and checks that it exits
# 0, prints the report (both engines agree) and the picture's path, and
# that the picture is a PNG of a plausible size.
#   cmake -DDEMO=path/to/opx-demo -DOUT=dir -P check_demo.cmake
file(REMOVE_RECURSE "${OUT}")
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${DEMO}" --quick --out "${OUT}"
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
message("${output}${errors}")
if(NOT result EQUAL 0)
  message(FATAL_ERROR "opx-demo --quick exited ${result}")
endif()
foreach(expected "engines +agree" "path query +collides" "picture +${OUT}/opx-demo.png" "2\\. ingest")
  if(NOT output MATCHES "${expected}")
    message(FATAL_ERROR "the demo's report lacks '${expected}'")
  endif()
endforeach()
file(READ "${OUT}/opx-demo.png" head LIMIT 24 HEX)
# The PNG signature, then the IHDR chunk (length 13).
if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452")
  message(FATAL_ERROR "${OUT}/opx-demo.png is not a PNG (starts ${head})")
endif()
file(SIZE "${OUT}/opx-demo.png" size)
if(size LESS 5000)
  message(FATAL_ERROR "${OUT}/opx-demo.png is only ${size} bytes")
endif()

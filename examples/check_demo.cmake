# The demo's smoke tests: run `opx-demo --quick` (with -DREAL=ON also
# --real, on the shared data) and check that it exits 0, prints the report
# (both engines agree) and the picture's path, and that the picture is a
# PNG of a plausible size; --real also its self-filter step (the arm's
# image collides without the filter and not with it) and that picture.
# --real without the data prints "SKIP:" (the test's
# SKIP_REGULAR_EXPRESSION).
#   cmake -DDEMO=path/to/opx-demo -DOUT=dir [-DREAL=ON -DDATA=dir] -P check_demo.cmake
set(pictures opx-demo.png)
set(expectations "engines +agree" "path query +collides" "2\\. ingest")
set(arguments --quick --out "${OUT}")
if(REAL)
  if(DEFINED ENV{OPX_DATA_DIR} AND NOT "$ENV{OPX_DATA_DIR}" STREQUAL "")
    set(DATA "$ENV{OPX_DATA_DIR}")
  endif()
  if(NOT EXISTS "${DATA}/rgbd" OR NOT EXISTS "${DATA}/robots/pr2_description")
    message("SKIP: ${DATA} holds no rgbd/ and robots/pr2_description/; set OPX_DATA_DIR to the shared data folder")
    return()
  endif()
  set(pictures opx-demo-real.png opx-demo-real-self-filter.png)
  list(APPEND expectations "self-filter +the PR2's right arm"
    "without +[0-9.]+ cm map, [0-9]+ occupied leaves \\([0-9]+ ms\\); the arm collides with its own image"
    "with +robot_padding 0.02 m, clear_robot_volume: [1-9][0-9]* points on robot, [0-9]+ shadowed, [1-9][0-9]* cells cleared"
    "occupied leaves \\([0-9]+ ms\\); the arm is collision-free")
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
foreach(picture ${pictures})
  list(APPEND expectations "picture +${OUT}/${picture}")
endforeach()
foreach(expected ${expectations})
  if(NOT output MATCHES "${expected}")
    message(FATAL_ERROR "the demo's report lacks '${expected}'")
  endif()
endforeach()
foreach(picture ${pictures})
  file(READ "${OUT}/${picture}" head LIMIT 24 HEX)
  # The PNG signature, then the IHDR chunk (length 13).
  if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452")
    message(FATAL_ERROR "${OUT}/${picture} is not a PNG (starts ${head})")
  endif()
  file(SIZE "${OUT}/${picture}" size)
  if(size LESS 5000)
    message(FATAL_ERROR "${OUT}/${picture} is only ${size} bytes")
  endif()
endforeach()

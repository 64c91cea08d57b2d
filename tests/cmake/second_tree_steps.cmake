# Shared by the cmake -P scripts that configure, build and run a second
# build tree from a ctest test (asan_c_tests, tsan_threads).

# Stops with a message naming `script` when any of the variables is unset.
function(opx_require_variables script)
  foreach(var IN LISTS ARGN)
    if(NOT DEFINED ${var})
      message(FATAL_ERROR "${script}: ${var} is not set")
    endif()
  endforeach()
endfunction()

# run_step(<test> <description> <command...>): runs the command in
# BINARY_DIR, announced as "<test>: <description>"; stops on failure.
function(run_step test description)
  message(STATUS "${test}: ${description}")
  execute_process(COMMAND ${ARGN} WORKING_DIRECTORY ${BINARY_DIR} RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "${test}: ${description} failed (${result})")
  endif()
endfunction()
